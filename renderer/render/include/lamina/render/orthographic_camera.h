// The orthographic camera: rays parallel to the view, leaving the film's screen window, a
// rectangle of A = (x1 - x0)(y1 - y0) square scene units on the plane through the camera's
// position facing the view (pbrt-v4's and Mitsuba 3's orthographic cameras, without a lens).
//
// Importance (light tracing, BDPT). A pixel's value is
//   I_p = integral over the film plane of h_p(raster(x)) K L(x, forward) dA(x),
// h_p the pixel filter normalised to integral 1 in pixel units, K = W H / A the pixels per unit
// area of the film plane. So We(x, omega) = h_p K delta(omega - forward): an area of positions
// and a delta of directions, the camera twin of a directional light. A scene point p connects
// to the one film point it projects to, x = p - depth forward, and the delta cancels against
// the change from film area to solid angle at p (dA(x) = |cos theta_p| dA(p) for parallel rays,
// the cosine being in the BSDF's value): a vertex of throughput beta contributes beta f K, so
// the connection's importance is K and its pdf 1. Generated from a film point uniform over the
// film, a ray reaches a surface point p with the area density |cos theta_p| / A
// (parallelPdf), which BDPT's weights compare with the light subpath's densities there.
#pragma once

#include <cmath>
#include <optional>

#include "lamina/render/camera_types.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

class OrthographicCamera {
  public:
    OrthographicCamera(const CameraDesc& desc, int width, int height)
        : width_(width), height_(height) {
        const Vec3d forward = glm::normalize(desc.lookAt - desc.position);
        const bool left = desc.handedness == Handedness::Left;
        const Vec3d right =
            glm::normalize(left ? glm::cross(desc.up, forward) : glm::cross(forward, desc.up));
        const Vec3d up = left ? glm::cross(forward, right) : glm::cross(right, forward);
        forward_ = Vec3<float>(forward);
        right_ = Vec3<float>(right);
        up_ = Vec3<float>(up);
        origin_ = Vec3<float>(desc.position);
        // pbrt-v4's default: the shorter image axis spans [-1, 1].
        const double aspect = double(width) / double(height);
        const std::array<double, 4> window = desc.screenWindow.value_or(
            aspect >= 1 ? std::array{-aspect, aspect, -1.0, 1.0}
                        : std::array{-1.0, 1.0, -1 / aspect, 1 / aspect});
        x0_ = float(window[0]);
        x1_ = float(window[1]);
        y0_ = float(window[2]);
        y1_ = float(window[3]);
        area_ = (window[1] - window[0]) * (window[3] - window[2]);
    }

    /// The ray through film position (x, y) in pixels (0 at the top-left corner); `lens` is
    /// not used.
    CameraRay generateRay(float x, float y, const Vec2<float>&) const {
        const float sx = x0_ + (x / float(width_)) * (x1_ - x0_);
        const float sy = y1_ - (y / float(height_)) * (y1_ - y0_);
        return {origin_ + sx * right_ + sy * up_, forward_};
    }

    bool isPinhole() const { return true; }  ///< no lens point is drawn

    /// Camera space: x right, y up, z forward, origin at the centre of the film plane's axes.
    Matrix4 cameraToWorld() const {
        return {right_.x, up_.x, forward_.x, origin_.x, right_.y, up_.y, forward_.y, origin_.y,
                right_.z, up_.z, forward_.z, origin_.z, 0.0f,     0.0f,  0.0f,       1.0f};
    }
    /// World -> NDC: x and y in [0, 1] over the film from its top-left corner, z the depth
    /// along the view, w = 1 (an affine projection).
    Matrix4 worldToNdc() const {
        const Vec3<float> rx = right_ / (x1_ - x0_), ry = -up_ / (y1_ - y0_);
        const float ox = -glm::dot(rx, origin_) - x0_ / (x1_ - x0_);
        const float oy = -glm::dot(ry, origin_) + y1_ / (y1_ - y0_);
        return {rx.x, rx.y, rx.z,       ox,         ry.x,       ry.y,
                ry.z, oy,   forward_.x, forward_.y, forward_.z, -glm::dot(forward_, origin_),
                0.0f, 0.0f, 0.0f,       1.0f};
    }

    /// The film position (pixels) of film-plane point `o`, or nullopt if it is off the film.
    std::optional<Vec2<float>> rasterPosition(const Vec3<float>& o) const {
        const Vec3<float> p = o - origin_;
        const float x = (glm::dot(p, right_) - x0_) / (x1_ - x0_) * float(width_);
        const float y = (y1_ - glm::dot(p, up_)) / (y1_ - y0_) * float(height_);
        if (!(x >= 0.0f && x < float(width_) && y >= 0.0f && y < float(height_)))
            return std::nullopt;
        return Vec2<float>(x, y);
    }

    /// The film point `ref` projects to (the connection is deterministic: `uLens` is unused).
    std::optional<CameraConnection> sampleConnection(const Vec3<float>& ref,
                                                     const Vec2<float>&) const {
        const float depth = glm::dot(ref - origin_, forward_);
        if (!(depth > 0.0f) || !std::isfinite(depth)) return std::nullopt;
        const Vec3<float> lens = ref - depth * forward_;
        const auto raster = rasterPosition(lens);
        if (!raster) return std::nullopt;
        return CameraConnection{lens, -forward_, depth, *raster, pixelsPerUnitArea(), 1.0f};
    }

    /// The film point per unit area; the direction is a delta (its coefficient 1).
    CameraRayPdf rayPdf(const Vec3<float>&) const { return {float(1.0 / area_), 1.0f}; }

    /// The area density at a point of normal `n` (`onSurface`; else per unit area across the
    /// ray) with which a ray from a film point uniform over the film reaches it.
    float parallelPdf(const Vec3<float>& n, bool onSurface) const {
        const float a = float(1.0 / area_);
        return onSurface ? a * std::abs(glm::dot(n, forward_)) : a;
    }

  private:
    /// K: film pixels per unit area of the film plane.
    float pixelsPerUnitArea() const { return float(double(width_) * double(height_) / area_); }

    int width_, height_;
    Vec3<float> origin_, forward_, right_, up_;
    float x0_, x1_, y0_, y1_;
    double area_;
};

}  // namespace lamina::render
