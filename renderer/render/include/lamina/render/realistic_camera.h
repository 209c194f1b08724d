// The realistic camera: rays traced from the film through a system of lens elements
// (lens_system.h; Kolb, Mitchell and Hanrahan 1995). The film, its size the film diagonal with
// the image's aspect, sits at the camera's position facing the view; the lens stands in front
// of it and turns the image over, so the film point of a pixel is mirrored through the axis.
//
// A pixel measures the irradiance on its film point (Kolb et al.'s measurement, as pbrt-v4's
// RealisticCamera): E = integral over the exit pupil of L cos^4(theta) / z^2 dA, theta the
// angle of the ray from the film point to the pupil point and z the film's distance to the
// plane of the rear vertex, where the pupil is sampled. A ray's weight is its integrand over
// its density (0 where the lens blocks it): its expectation is E, so an emitter of radiance L
// filling the view gives L times the pupil's projected solid angle, falling off towards the
// film's edge (cos^4 and the vignetting of the lens's apertures).
//
// Path tracing only: light tracing and BDPT connect scene points to the lens by the camera's
// importance, which a lens system has in no closed form; sampleConnection has none and the
// integrators other than path refuse the camera (makeIntegrator).
#pragma once

#include <memory>
#include <optional>

#include "lamina/render/camera_types.h"
#include "lamina/scene/lens_system.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

class RealisticCamera {
  public:
    RealisticCamera(const CameraDesc& desc, int width, int height);

    /// The ray through film position (x, y) in pixels (0 at the top-left corner) and the exit
    /// pupil's point `lens` in [0, 1)^2, with its weight (0: blocked).
    CameraRay generateRay(float x, float y, const Vec2<float>& lens) const;

    bool isPinhole() const { return false; }
    /// Camera space: x right, y up, z forward, origin at the film's centre.
    Matrix4 cameraToWorld() const;
    /// The pinhole projection through the rear vertex with the film's extent (metadata: a
    /// lens system has no exact projection).
    Matrix4 worldToNdc() const;
    std::optional<CameraConnection> sampleConnection(const Vec3<float>&, const Vec2<float>&) const {
        return std::nullopt;
    }
    CameraRayPdf rayPdf(const Vec3<float>&) const { return {0.0f, 0.0f}; }

  private:
    std::shared_ptr<const LensSystem> lens_;
    int width_, height_;
    double filmWidth_, filmHeight_;
    glm::dvec3 origin_, forward_, right_, up_;
};

}  // namespace lamina::render
