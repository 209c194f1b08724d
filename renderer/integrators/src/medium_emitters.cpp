#include "lamina/integrators/medium_emitters.h"

#include <algorithm>
#include <cmath>

#include "lamina/core/error.h"
#include "lamina/core/math.h"
#include "lamina/integrators/medium_transport.h"
#include "lamina/lights/emitter_color.h"

namespace lamina::render {

namespace {

/// Whether shape `s` bounds medium `medium` on either side.
bool bounds(const ShapeDesc& s, int medium) {
    const auto& media = surface(s).media;
    return media && (media->interior == medium || media->exterior == medium);
}

/// The index whose cdf interval holds u.
std::size_t pick(const std::vector<float>& cdf, float u) {
    const auto it = std::upper_bound(cdf.begin(), cdf.end(), u);
    return std::min(std::size_t(it - cdf.begin()), cdf.size() - 1);
}

/// A distribution over weights w (> 0 in sum): pmf and cdf, the last cdf entry exactly 1.
void tabulate(const std::vector<double>& w, std::vector<float>& pmf, std::vector<float>& cdf) {
    double total = 0;
    for (double x : w)
        total += x;
    pmf.resize(w.size());
    cdf.resize(w.size());
    double running = 0;
    for (std::size_t i = 0; i < w.size(); ++i) {
        pmf[i] = float(w[i] / total);
        running += w[i] / total;
        cdf[i] = float(running);
    }
    if (!cdf.empty()) cdf.back() = 1.0f;
}

/// The luminance of the medium's Le (an emission spectrum reduced to RGB as the RGB mode
/// reduces it), the selection's measure of power as Light::power's.
double emissionLuminance(const MediumDesc& m) {
    return luminance(EmitterColor(m.emission, m.emissionSpectrum).rgbDouble());
}

}  // namespace

bool emissionFillsSpace(const SceneDesc& scene, int medium) {
    const MediumDesc& m = scene.media[std::size_t(medium)];
    if (!m.emits() || m.kind != MediumKind::Homogeneous || scene.camera.medium != medium)
        return false;
    for (const ShapeDesc& s : scene.shapes)
        if (bounds(s, medium)) return false;
    for (const ObjectDesc& o : scene.objects)
        for (const ShapeDesc& s : o.shapes)
            if (bounds(s, medium)) return false;
    return true;
}

void refuseUnboundedEmission(const SceneDesc& scene, int medium) {
    throw InputError(scene.file.string() + ": media." + scene.media[std::size_t(medium)].name +
                     ".Le: the light and bdpt integrators start particles in an emitting "
                     "medium's volume, and this one reaches infinity (no shapes enclose it); "
                     "enclose it with shapes or use --integrator path");
}

MediumEmitters::MediumEmitters(const SceneContext& context, bool media) : lights_(&context.lights) {
    if (!media) return;
    const SceneDesc& scene = context.scene;
    sourceOf_.assign(scene.media.size(), -1);
    std::vector<double> power;
    for (int i = 0; i < int(scene.media.size()); ++i) {
        const MediumDesc& m = scene.media[std::size_t(i)];
        if (!m.emits()) continue;
        double p = 0;
        const bool added = m.grid ? addGrid(context, i, p) : addHomogeneous(context, i, p);
        if (!added) continue;
        sourceOf_[std::size_t(i)] = int(sources_.size()) - 1;
        power.push_back(p);
    }
    if (sources_.empty()) return;
    std::vector<float> pmf;
    tabulate(power, pmf, cdf_);
    double mediaPower = 0, lightPower = 0;
    for (double p : power)
        mediaPower += p;
    for (std::size_t i = 0; i < context.lights.size(); ++i)
        lightPower += std::max(context.lights.light(i).power(), 0.0);
    // The lights keep at least 1% of the particles, as the light set gives each light a floor.
    mediaShare_ = context.lights.empty()
                      ? 1.0f
                      : float(std::clamp(mediaPower / (mediaPower + lightPower), 0.01, 0.99));
    for (std::size_t k = 0; k < sources_.size(); ++k)
        sources_[k].probability = mediaShare_ * pmf[k];
}

bool MediumEmitters::addHomogeneous(const SceneContext& context, int index, double& power) {
    const SceneDesc& scene = context.scene;
    const Geometry& geometry = context.geometry;
    if (emissionFillsSpace(scene, index)) refuseUnboundedEmission(scene, index);
    // The box of the shapes that bound it (the scene's, for shapes of instanced objects).
    Vec3d lo(std::numeric_limits<double>::infinity()), hi = -lo;
    bool named = false;
    for (const ShapeDesc& s : scene.shapes)
        if (bounds(s, index)) {
            Vec3d slo, shi;
            shapeBounds(s, slo, shi);
            lo = glm::min(lo, slo);
            hi = glm::max(hi, shi);
            named = true;
        }
    for (const ObjectDesc& o : scene.objects)
        for (const ShapeDesc& s : o.shapes)
            if (bounds(s, index)) {
                lo = glm::min(lo, Vec3d(geometry.boundsLo()));
                hi = glm::max(hi, Vec3d(geometry.boundsHi()));
                named = true;
            }
    // Reaching infinity: the medium at a point far outside the scene, found from the camera.
    PathStatistics stats;
    const Vec3f away = glm::normalize(Vec3f(0.5377f, 0.6229f, 0.5684f));
    const Vec3f far = geometry.boundsCenter() + away * (4.0f * geometry.boundsRadius() + 1.0f);
    if (mediumAt(geometry, scene.camera.medium, Vec3f(scene.camera.position), far, stats) == index)
        refuseUnboundedEmission(scene, index);
    if (!named) return false;  // bounded by nothing, not around the camera: it is nowhere
    // A margin against the rounding of points on the bounding shapes.
    const Vec3d margin = 1e-4 * (hi - lo) + 1e-6;
    lo -= margin;
    hi += margin;
    const MediumDesc& m = scene.media[std::size_t(index)];
    const double volume = (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z);
    power = 4 * kPi<double> * luminance(m.sigmaA) * emissionLuminance(m) * volume;
    if (!(power > 0) || !(volume > 0) || !std::isfinite(volume)) return false;
    Source s;
    s.medium = index;
    s.lo = Vec3f(lo);
    s.hi = Vec3f(hi);
    s.boxDensity = float(1.0 / volume);
    sources_.push_back(std::move(s));
    return true;
}

bool MediumEmitters::addGrid(const SceneContext& context, int index, double& power) {
    const MediumDesc& m = context.scene.media[std::size_t(index)];
    const GridDensity& grid = *m.grid;
    const MajorantGrid& maj = grid.majorants;
    Source s;
    s.medium = index;
    s.grid = &grid;
    s.lo = grid.boxMin;
    s.hi = grid.boxMax;
    s.nx = maj.nx;
    s.ny = maj.ny;
    s.nz = maj.nz;
    std::vector<double> w(maj.maxima.size());
    double total = 0;
    for (std::size_t c = 0; c < w.size(); ++c)
        total += w[c] = std::max(double(maj.maxima[c]), 0.0);
    if (!(total > 0)) return false;
    tabulate(w, s.cellPmf, s.cellCdf);
    // Medium -> scene: the inverse of the rows of GridDensity::worldToMedium (glm is column
    // major: column j of `linear` holds entry j of every row).
    glm::mat3 linear(1.0f);
    Vec3f offset(0.0f);
    if (grid.transformed)
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c)
                linear[c][r] = grid.worldToMedium[r][c];
            offset[r] = grid.worldToMedium[r][3];
        }
    s.toWorld = glm::inverse(linear);
    s.toWorldOffset = -(s.toWorld * offset);
    const Vec3f extent = grid.boxMax - grid.boxMin;
    const double cellVolume = double(extent.x) * extent.y * extent.z / (double(s.nx) * s.ny * s.nz);
    const double det = std::abs(double(glm::determinant(linear)));
    s.cellDensity = float(det / cellVolume);
    // The density's integral is at most the maxima's over the cells (of the scene's volume
    // cellVolume / det each); colour grids' maxima bound sigma_t itself.
    const double sigmaA = grid.colours ? 1.0 : luminance(m.sigmaA);
    power = 4 * kPi<double> * sigmaA * emissionLuminance(m) * total * cellVolume / det;
    if (!(power > 0) || !std::isfinite(power) || !(s.cellDensity > 0)) return false;
    sources_.push_back(std::move(s));
    return true;
}

MediumEmitters::Choice MediumEmitters::choose(float u) const {
    if (u < mediaShare_) {
        const float v = std::min(u / mediaShare_, 1.0f - 0x1p-24f);
        const Source& s = sources_[pick(cdf_, v)];
        return {-1, s.medium, s.probability};
    }
    const float v = std::min((u - mediaShare_) / (1.0f - mediaShare_), 1.0f - 0x1p-24f);
    const LightChoice c = lights_->chooseEmitter(v);
    return {int(c.index), -1, c.probability * (1.0f - mediaShare_)};
}

float MediumEmitters::lightProbability(std::size_t i) const {
    if (sources_.empty()) return lights_->emitterProbability(i);
    return lights_->emitterProbability(i) * (1.0f - mediaShare_);
}

float MediumEmitters::mediumProbability(int medium) const {
    if (medium < 0 || std::size_t(medium) >= sourceOf_.size() || sourceOf_[std::size_t(medium)] < 0)
        return 0.0f;
    return sources_[std::size_t(sourceOf_[std::size_t(medium)])].probability;
}

std::optional<MediumEmitters::VolumePoint> MediumEmitters::samplePoint(int medium,
                                                                       const Vec3f& u) const {
    if (mediumProbability(medium) <= 0.0f) return std::nullopt;
    const Source& s = sources_[std::size_t(sourceOf_[std::size_t(medium)])];
    if (!s.grid) return VolumePoint{s.lo + (s.hi - s.lo) * u, s.boxDensity};
    // The cell by u.z, reused within the cell (pbrt-v4's SampleDiscrete remaps the same way).
    const std::size_t c = pick(s.cellCdf, u.z);
    const float before = c > 0 ? s.cellCdf[c - 1] : 0.0f;
    const float z = std::clamp((u.z - before) / s.cellPmf[c], 0.0f, 1.0f - 0x1p-24f);
    const int ix = int(c % std::size_t(s.nx)), iy = int(c / std::size_t(s.nx) % std::size_t(s.ny)),
              iz = int(c / (std::size_t(s.nx) * std::size_t(s.ny)));
    const Vec3f cell = (s.hi - s.lo) / Vec3f(float(s.nx), float(s.ny), float(s.nz));
    const Vec3f local = s.lo + cell * (Vec3f(float(ix), float(iy), float(iz)) + Vec3f(u.x, u.y, z));
    return VolumePoint{s.toWorld * local + s.toWorldOffset, s.cellPmf[c] * s.cellDensity};
}

float MediumEmitters::pointDensity(int medium, const Vec3f& p) const {
    if (mediumProbability(medium) <= 0.0f) return 0.0f;
    const Source& s = sources_[std::size_t(sourceOf_[std::size_t(medium)])];
    const Vec3f local = s.grid ? s.grid->pointToMedium(p) : p;
    const Vec3f f = (local - s.lo) / (s.hi - s.lo);
    for (int i = 0; i < 3; ++i)
        if (!(f[i] >= 0.0f && f[i] <= 1.0f)) return 0.0f;
    if (!s.grid) return s.boxDensity;
    const int ix = std::min(int(f.x * float(s.nx)), s.nx - 1),
              iy = std::min(int(f.y * float(s.ny)), s.ny - 1),
              iz = std::min(int(f.z * float(s.nz)), s.nz - 1);
    const std::size_t c =
        (std::size_t(iz) * std::size_t(s.ny) + std::size_t(iy)) * std::size_t(s.nx) +
        std::size_t(ix);
    return s.cellPmf[c] * s.cellDensity;
}

}  // namespace lamina::render
