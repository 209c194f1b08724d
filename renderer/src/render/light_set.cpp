#include "lamina/render/lights.h"

#include <algorithm>

#include "lamina/render/area_lights.h"
#include "lamina/render/infinite_lights.h"
#include "lamina/render/point_lights.h"

namespace lamina::render {

namespace {

bool emits(const std::optional<EmissionDesc>& e) {
    return e && !(e->radiance.maxValue() <= 0.0 && !e->spectrum);
}

}  // namespace

LightSet::LightSet(const SceneDesc& scene, const Geometry& geometry, bool uniformSelection) {
    // The area lights, shape by shape: one per triangle of a mesh, one for a whole rectangle,
    // disk or sphere.
    const auto& shapes = geometry.shapes();
    shapeLights_.resize(shapes.size());
    for (std::size_t s = 0; s < shapes.size(); ++s) {
        const ShapeInfo& info = shapes[s];
        const int first = int(lights_.size());
        if (info.kind == ShapeInfo::Kind::Mesh) {
            const MeshDesc& m = scene.meshes[std::size_t(info.index)];
            if (!emits(m.emission)) continue;
            if (RectangleLight::isRectangle(m)) {
                shapeLights_[s] = {first, false};
                lights_.push_back(std::make_unique<RectangleLight>(m));
                continue;
            }
            shapeLights_[s] = {first, true};
            for (std::size_t t = 0; t < m.triangles.size(); ++t)
                lights_.push_back(std::make_unique<TriangleLight>(m, t));
        } else if (info.kind == ShapeInfo::Kind::Disk) {
            const DiskDesc& dk = scene.disks[std::size_t(info.index)];
            if (!emits(dk.emission)) continue;
            shapeLights_[s] = {first, false};
            lights_.push_back(std::make_unique<DiskLight>(dk));
        } else {
            const SphereDesc& sp = scene.spheres[std::size_t(info.index)];
            if (!emits(sp.emission)) continue;
            shapeLights_[s] = {first, false};
            lights_.push_back(std::make_unique<SphereLight>(sp));
        }
    }
    for (const LightDesc& d : scene.lights) {
        if (d.intensity.maxValue() <= 0.0 && !d.spectrum) continue;
        switch (d.kind) {
            case LightKind::Point:
                lights_.push_back(std::make_unique<PointLight>(d));
                break;
            case LightKind::Spot:
                lights_.push_back(std::make_unique<SpotLight>(d));
                break;
            case LightKind::Directional:
                infinite_.push_back(lights_.size());
                lights_.push_back(std::make_unique<DirectionalLight>(d, geometry));
                break;
            case LightKind::Environment:
                infinite_.push_back(lights_.size());
                if (d.file.empty())
                    lights_.push_back(std::make_unique<ConstantEnvironment>(d, geometry));
                else
                    lights_.push_back(std::make_unique<ImageEnvironment>(d, geometry));
                break;
        }
    }
    // Selection proportional to power (or uniform); a light of zero luminance but non-zero
    // colour (pure blue, say) still gets a share so it is never starved.
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
}

std::pair<std::size_t, float> LightSet::choose(float u) const {
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u);
    const std::size_t i = std::min(std::size_t(it - cdf_.begin()), cdf_.size() - 1);
    return {i, pmf_[i]};
}

int LightSet::lightAt(const SurfaceHit& hit) const {
    const ShapeLights& s = shapeLights_[std::size_t(hit.shape)];
    if (s.first < 0) return -1;
    return s.first + (s.perPrimitive ? int(hit.primitive) : 0);
}

}  // namespace lamina::render
