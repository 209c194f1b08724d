// The camera of a render: a perspective one (pinhole or thin lens, perspective_camera.h), an
// orthographic one (orthographic_camera.h) or a realistic one (a lens system,
// realistic_camera.h; path tracing only), chosen by the scene's camera. The integrators ask
// this one class; each kind answers with its own model of rays, importance and densities.
#pragma once

#include <variant>

#include "lamina/render/orthographic_camera.h"
#include "lamina/render/perspective_camera.h"
#include "lamina/render/realistic_camera.h"

namespace lamina::render {

class Camera {
  public:
    Camera(const CameraDesc& desc, int width, int height)
        : kind_(desc.lensSystem ? Kind(std::in_place_type<RealisticCamera>, desc, width, height)
                : desc.orthographic
                    ? Kind(std::in_place_type<OrthographicCamera>, desc, width, height)
                    : Kind(std::in_place_type<PerspectiveCamera>, desc, width, height)) {}

    /// The ray through film position (x, y) in pixels (0 at the top-left corner), with `lens`
    /// in [0, 1)^2 choosing the point on the aperture. Its weight is 1 but for a realistic
    /// camera (0: the lens blocked it).
    CameraRay generateRay(float x, float y, const Vec2<float>& lens) const {
        return std::visit([&](const auto& c) { return c.generateRay(x, y, lens); }, kind_);
    }
    /// True when no lens point is drawn (a pinhole or an orthographic camera).
    bool isPinhole() const {
        return std::visit([](const auto& c) { return c.isPinhole(); }, kind_);
    }
    Matrix4 cameraToWorld() const {
        return std::visit([](const auto& c) { return c.cameraToWorld(); }, kind_);
    }
    /// The image's right in the world: the first column of cameraToWorld (row-major).
    Vec3<float> imageRight() const {
        const Matrix4 m = cameraToWorld();
        return {m[0], m[4], m[8]};
    }
    Matrix4 worldToNdc() const {
        return std::visit([](const auto& c) { return c.worldToNdc(); }, kind_);
    }
    /// Chooses a lens point seen from `ref` (uniform on the aperture, `uLens`).
    std::optional<CameraConnection> sampleConnection(const Vec3<float>& ref,
                                                     const Vec2<float>& uLens) const {
        return std::visit([&](const auto& c) { return c.sampleConnection(ref, uLens); }, kind_);
    }
    /// Densities with which generateRay, with the film position uniform over the whole film,
    /// produces a ray from its lens point along `d`. BDPT's MIS weights use them.
    CameraRayPdf rayPdf(const Vec3<float>& d) const {
        return std::visit([&](const auto& c) { return c.rayPdf(d); }, kind_);
    }
    /// Parallel rays (orthographic): a ray's density at the point it reaches is not its
    /// direction's density over the squared distance but parallelPdf.
    bool parallel() const { return std::holds_alternative<OrthographicCamera>(kind_); }
    float parallelPdf(const Vec3<float>& n, bool onSurface) const {
        return std::get<OrthographicCamera>(kind_).parallelPdf(n, onSurface);
    }

  private:
    using Kind = std::variant<PerspectiveCamera, OrthographicCamera, RealisticCamera>;
    Kind kind_;
};

}  // namespace lamina::render
