#include "lamina/lights/lights.h"

#include <algorithm>

#include "lamina/lights/area_lights.h"
#include "lamina/lights/infinite_lights.h"
#include "lamina/lights/point_lights.h"
#include "lamina/lights/portal_environment.h"

namespace lamina::render {

namespace {

bool emits(const std::optional<EmissionDesc>& e) {
    return e && !(e->radiance.maxValue() <= 0.0 && !e->spectrum);
}

// The area lights of an emitting shape, one function per kind of ShapeDesc: one light per
// triangle of a mesh (perPrimitive), one for a whole rectangle, sphere, disk or quadric.
struct AreaLights {
    std::vector<std::unique_ptr<Light>> lights;
    bool perPrimitive = false;
};

AreaLights makeAreaLights(const MeshDesc& m) {
    AreaLights a;
    if (RectangleLight::isRectangle(m)) {
        a.lights.push_back(std::make_unique<RectangleLight>(m));
        return a;
    }
    a.perPrimitive = true;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
        a.lights.push_back(std::make_unique<TriangleLight>(m, t));
    return a;
}

AreaLights makeAreaLights(const SphereDesc& s) {
    AreaLights a;
    a.lights.push_back(std::make_unique<SphereLight>(s));
    return a;
}

AreaLights makeAreaLights(const DiskDesc& d) {
    AreaLights a;
    a.lights.push_back(std::make_unique<DiskLight>(d));
    return a;
}

AreaLights makeAreaLights(const QuadricDesc& q) {
    AreaLights a;
    a.lights.push_back(std::make_unique<QuadricLight>(q));
    return a;
}

// Curves never emit (their reader refuses emission).
AreaLights makeAreaLights(const CurvesDesc&) {
    return {};
}

// The light of an entry of "lights", one function per kind of LightDesc.
std::unique_ptr<Light> makeLight(const PointLightDesc& d, const Geometry&) {
    return std::make_unique<PointLight>(d);
}

std::unique_ptr<Light> makeLight(const SpotLightDesc& d, const Geometry&) {
    return std::make_unique<SpotLight>(d);
}

std::unique_ptr<Light> makeLight(const DirectionalLightDesc& d, const Geometry& g) {
    return std::make_unique<DirectionalLight>(d, g);
}

std::unique_ptr<Light> makeLight(const EnvironmentLightDesc& d, const Geometry& g) {
    std::unique_ptr<EnvironmentLight> environment;
    if (d.file.empty())
        environment = std::make_unique<ConstantEnvironment>(d, g);
    else
        environment = std::make_unique<ImageEnvironment>(d, g);
    if (d.portal) return std::make_unique<PortalEnvironment>(std::move(environment), *d.portal, g);
    return environment;
}

}  // namespace

LightSet::LightSet(const SceneDesc& scene, const Geometry& geometry, LightSelection selection) {
    // The area lights, shape by shape, in the order of the geometry's shapes.
    const auto& shapes = geometry.shapes();
    shapeLights_.resize(shapes.size());
    for (std::size_t s = 0; s < shapes.size(); ++s) {
        const ShapeInfo& info = shapes[s];
        if (info.object >= 0) continue;  // objects hold no emitters (shape_reader.cpp)
        if (!emits(surface(*info.desc).emission)) continue;
        AreaLights area =
            std::visit([](const auto& shape) { return makeAreaLights(shape); }, *info.desc);
        shapeLights_[s] = {int(lights_.size()), area.perPrimitive};
        for (auto& light : area.lights)
            lights_.push_back(std::move(light));
    }
    // The lights that are not shapes; a light at infinity is also listed in infinite_.
    for (const LightDesc& d : scene.lights) {
        const LightIntensityDesc& strength = lightIntensity(d);
        if (strength.intensity.maxValue() <= 0.0 && !strength.spectrum) continue;
        std::unique_ptr<Light> light =
            std::visit([&](const auto& desc) { return makeLight(desc, geometry); }, d);
        if (light->isInfinite()) infinite_.push_back(lights_.size());
        lights_.push_back(std::move(light));
    }
    // The point-independent distribution: proportional to power (or uniform); a light of
    // zero luminance but non-zero colour (pure blue, say) still gets a share so it is never
    // starved.
    const bool uniformSelection = selection == LightSelection::Uniform;
    double total = 0;
    std::vector<double> w(lights_.size());
    for (std::size_t i = 0; i < lights_.size(); ++i) {
        w[i] = uniformSelection ? 1.0 : std::max(lights_[i]->power(), 0.0);
        total += w[i];
    }
    pmf_.resize(lights_.size());
    cdf_.resize(lights_.size());
    double running = 0;
    for (std::size_t i = 0; i < lights_.size(); ++i) {
        const double p = total > 0 ? 0.99 * w[i] / total + 0.01 / double(lights_.size())
                                   : 1.0 / double(lights_.size());
        pmf_[i] = float(p);
        running += p;
        cdf_[i] = float(running);
    }
    if (!cdf_.empty()) cdf_.back() = 1.0f;
    chooseNextEventLights();
    buildNextEventDistribution(w);
    if (selection == LightSelection::Bvh) buildBvh();
    // The lights choose() can return: with the tree, its leaves (the lights with bounds) and
    // the lights at infinity next-event estimation samples; else every light it samples.
    for (std::size_t i = 0; i < lights_.size(); ++i)
        if (nextEvent_[i] && (!useBvh_ || infiniteSlot_[i] >= 0 || bvh_.contains(i)))
            ++nextEventChoices_;
}

void LightSet::chooseNextEventLights() {
    // A constant environment is found by BSDF sampling at least as well as by next-event
    // estimation's direction uniform on the sphere (half of which points into the surface),
    // for every BSDF whose sampling follows its lobe, and a next-event sample spent on it is
    // one the other lights lose. So next-event estimation leaves it to BSDF sampling, as
    // Cycles 3.4 does (it disables the background light when the world shader does not vary
    // over directions, scene/light.cpp) and pbrt-v4 (UniformInfiniteLight::SampleLi returns
    // nothing when an incomplete pdf is allowed). Only when every environment is constant:
    // BDPT's MIS needs the same probability ratio for all environments (environment vertices
    // of camera paths do not say which one they hit).
    nextEvent_.assign(lights_.size(), 1);
    bool allConstant = true;
    for (const auto& l : lights_)
        if (l->isInfinite() && !l->isDelta() && !dynamic_cast<const ConstantEnvironment*>(l.get()))
            allConstant = false;
    if (!allConstant) return;
    for (std::size_t i = 0; i < lights_.size(); ++i)
        if (lights_[i]->isInfinite() && !lights_[i]->isDelta()) nextEvent_[i] = 0;
}

void LightSet::buildNextEventDistribution(const std::vector<double>& weights) {
    // pmf_'s formula over the lights next-event estimation samples: pmf_ itself, bit for bit,
    // when it samples them all.
    double total = 0;
    std::size_t count = 0, last = 0;
    for (std::size_t i = 0; i < lights_.size(); ++i)
        if (nextEvent_[i]) {
            total += weights[i];
            ++count;
            last = i;
        }
    nextEventPmf_.assign(lights_.size(), 0.0f);
    nextEventCdf_.assign(lights_.size(), 0.0f);
    if (count == 0) return;
    double running = 0;
    for (std::size_t i = 0; i < lights_.size(); ++i) {
        if (nextEvent_[i]) {
            const double p =
                total > 0 ? 0.99 * weights[i] / total + 0.01 / double(count) : 1.0 / double(count);
            nextEventPmf_[i] = float(p);
            running += p;
        }
        // From the last sampled light on the cdf is 1, so that no light after it (which it
        // never samples) takes up the rounding.
        nextEventCdf_[i] = i >= last ? 1.0f : float(running);
    }
}

void LightSet::buildBvh() {
    useBvh_ = true;
    std::vector<LightBvh::Entry> bounded;
    float strongest = 0.0f;
    for (std::size_t i = 0; i < lights_.size(); ++i) {
        if (lights_[i]->isInfinite()) continue;
        const auto b = lights_[i]->bounds();
        if (!b) continue;
        bounded.push_back({i, *b});
        if (std::isfinite(b->intensity)) strongest = std::max(strongest, b->intensity);
    }
    // As for the power distribution: a light whose luminance is zero keeps a small weight.
    const float floor = strongest > 0.0f ? 1e-6f * strongest : 1.0f;
    for (LightBvh::Entry& e : bounded)
        if (!(e.bounds.intensity >= floor) || !std::isfinite(e.bounds.intensity))
            e.bounds.intensity = floor;
    bvh_ = LightBvh(std::move(bounded));

    // The lights at infinity that next-event estimation samples take a fixed share, as much
    // as one light of the tree (pbrt-v4's BVHLightSampler), and among themselves follow their
    // power distribution, so that probability / emitterProbability is the same for all of
    // them.
    for (std::size_t i : infinite_)
        if (nextEvent_[i]) nextEventInfinite_.push_back(i);
    const std::size_t n = nextEventInfinite_.size();
    infiniteShare_ = n == 0 ? 0.0f : bvh_.empty() ? 1.0f : float(n) / float(n + 1);
    infiniteSlot_.assign(lights_.size(), -1);
    double sum = 0;
    for (std::size_t i : nextEventInfinite_)
        sum += pmf_[i];
    double running = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = nextEventInfinite_[k];
        infiniteSlot_[i] = int(k);
        infinitePmf_.push_back(float(pmf_[i] / sum));
        running += pmf_[i] / sum;
        infiniteCdf_.push_back(float(running));
    }
    if (!infiniteCdf_.empty()) infiniteCdf_.back() = 1.0f;
}

namespace {

/// The index whose cdf interval holds u.
std::size_t pick(const std::vector<float>& cdf, float u) {
    const auto it = std::upper_bound(cdf.begin(), cdf.end(), u);
    return std::min(std::size_t(it - cdf.begin()), cdf.size() - 1);
}

}  // namespace

LightChoice LightSet::chooseEmitter(float u) const {
    const std::size_t i = pick(cdf_, u);
    return {i, pmf_[i]};
}

std::optional<LightChoice> LightSet::choose(const Vec3f& p, const Vec3f& n, float u) const {
    if (lights_.empty()) return std::nullopt;
    if (!useBvh_) {
        if (nextEventCdf_.empty() || !(nextEventCdf_.back() > 0.0f)) return std::nullopt;
        const std::size_t i = pick(nextEventCdf_, u);
        return LightChoice{i, nextEventPmf_[i]};
    }
    if (u < infiniteShare_) {
        const std::size_t k =
            pick(infiniteCdf_, std::min(u / infiniteShare_, kOneMinusEpsilon<float>));
        return LightChoice{nextEventInfinite_[k], infiniteShare_ * infinitePmf_[k]};
    }
    if (bvh_.empty()) return std::nullopt;
    // Without lights at infinity u goes to the tree as it is: (u - 0) / 1 is u, and the
    // probability times 1 the same float, so this skips a division and nothing else.
    if (infiniteShare_ == 0.0f) return bvh_.choose(p, n, u);
    const float uTree =
        std::min((u - infiniteShare_) / (1.0f - infiniteShare_), kOneMinusEpsilon<float>);
    LightChoice c = bvh_.choose(p, n, uTree);
    c.probability *= 1.0f - infiniteShare_;
    return c;
}

float LightSet::probability(std::size_t i, const Vec3f& p, const Vec3f& n) const {
    if (!useBvh_) return nextEventPmf_[i];
    if (!nextEvent_[i]) return 0.0f;
    if (const int k = infiniteSlot_[i]; k >= 0)
        return infiniteShare_ * infinitePmf_[std::size_t(k)];
    return bvh_.probability(i, p, n) * (1.0f - infiniteShare_);
}

int LightSet::lightAt(const SurfaceHit& hit) const {
    const ShapeLights& s = shapeLights_[std::size_t(hit.shape)];
    if (s.first < 0) return -1;
    return s.first + (s.perPrimitive ? int(hit.primitive) : 0);
}

}  // namespace lamina::render
