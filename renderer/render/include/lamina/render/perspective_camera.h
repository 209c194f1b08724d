// The perspective camera: a pinhole, or a thin lens (aperture radius, focus distance). The image
// plane maps film x to the right and film y downwards; right = forward x up (right-handed), or
// up x forward for a left-handed camera (CameraDesc::handedness: pbrt's camera space).
//
// Importance (for light tracing and BDPT). A pixel's value is the measurement
//   I_p = integral over the lens (1/A_lens) integral over directions of
//         h_p(x(omega)) J(omega) L(omega) d omega,
// with h_p the pixel filter normalised to integral 1 over the film (in pixel units) and
// J = K / cos^3(theta) the film area (in pixels) per solid angle, K = (W / 2 tan(fov_x / 2)) *
// (H / 2 tan(fov_y / 2)) the pixels per unit area of the image plane at distance 1, theta the
// angle to the viewing axis (for a thin lens, of the ray through the lens point). So the
// emitted importance is We = K / (A_lens cos^4(theta)) (A_lens = 1 for a pinhole; Veach 1997,
// section 10.8, and pbrt-v4 section 5.2.4 use the same form with the film area instead of K).
#pragma once

#include <array>
#include <optional>

#include "lamina/core/warp.h"
#include "lamina/render/camera_types.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

class PerspectiveCamera {
  public:
    PerspectiveCamera(const CameraDesc& desc, int width, int height)
        : desc_(desc), width_(width), height_(height) {
        const Vec3d forward = glm::normalize(desc.lookAt - desc.position);
        const bool left = desc.handedness == Handedness::Left;
        const Vec3d right =
            glm::normalize(left ? glm::cross(desc.up, forward) : glm::cross(forward, desc.up));
        const Vec3d up = left ? glm::cross(forward, right) : glm::cross(right, forward);
        forward_ = Vec3<float>(forward);
        right_ = Vec3<float>(right);
        up_ = Vec3<float>(up);
        origin_ = Vec3<float>(desc.position);
        tanHalfHeight_ = float(std::tan(0.5 * lamina::radians(desc.verticalFovDegrees)));
        tanHalfWidth_ = tanHalfHeight_ * float(width) / float(height);
    }

    /// The ray through film position (x, y) in pixels (0 at the top-left corner), with `lens`
    /// in [0, 1)^2 choosing the point on the aperture.
    CameraRay generateRay(float x, float y, const Vec2<float>& lens) const {
        const float sx = (2.0f * x / float(width_) - 1.0f) * tanHalfWidth_;
        const float sy = (1.0f - 2.0f * y / float(height_)) * tanHalfHeight_;
        Vec3<float> dir = glm::normalize(forward_ + sx * right_ + sy * up_);
        if (desc_.apertureRadius <= 0) return {origin_, dir};
        // Thin lens: every ray through the pixel's pinhole direction meets at the focus plane.
        const float ft = float(desc_.focusDistance) / glm::dot(dir, forward_);
        const Vec3<float> focus = origin_ + ft * dir;
        const Vec2<float> d = float(desc_.apertureRadius) * squareToUniformDiskConcentric(lens);
        const Vec3<float> o = origin_ + d.x * right_ + d.y * up_;
        return {o, glm::normalize(focus - o)};
    }

    bool isPinhole() const { return !(desc_.apertureRadius > 0); }
    Vec3<float> forward() const { return forward_; }

    /// Camera space: x right, y up, z forward (the viewing axis), origin at the pinhole.
    Matrix4 cameraToWorld() const {
        return {right_.x, up_.x, forward_.x, origin_.x, right_.y, up_.y, forward_.y, origin_.y,
                right_.z, up_.z, forward_.z, origin_.z, 0.0f,     0.0f,  0.0f,       1.0f};
    }
    /// World -> NDC of the pinhole projection, the same as rasterPosition: after the division
    /// by w (the depth along the viewing axis), x in [0, 1] runs left to right and y in [0, 1]
    /// top to bottom over the film (times width and height: pixels), and z = 1 / depth.
    Matrix4 worldToNdc() const {
        const float ax = 0.5f / tanHalfWidth_, ay = -0.5f / tanHalfHeight_;
        const Vec3<float> rows[3] = {ax * right_ + 0.5f * forward_, ay * up_ + 0.5f * forward_,
                                     forward_};
        Matrix4 m{};
        for (int r = 0; r < 3; ++r) {
            const int out = r == 2 ? 3 : r;  // depth goes to w; z is the constant 1
            m[std::size_t(4 * out)] = rows[r].x;
            m[std::size_t(4 * out + 1)] = rows[r].y;
            m[std::size_t(4 * out + 2)] = rows[r].z;
            m[std::size_t(4 * out + 3)] = -glm::dot(rows[r], origin_);
        }
        m[11] = 1.0f;
        return m;
    }

    /// The film position (pixels) of the ray leaving lens point `o` along `d` (unit, towards
    /// the scene), or nullopt if it misses the film.
    std::optional<Vec2<float>> rasterPosition(const Vec3<float>& o, const Vec3<float>& d) const {
        const float cosTheta = glm::dot(d, forward_);
        if (!(cosTheta > 0.0f)) return std::nullopt;
        Vec3<float> p = d;  // the pinhole direction of the film point
        if (!isPinhole()) p = o + (float(desc_.focusDistance) / cosTheta) * d - origin_;
        const float z = glm::dot(p, forward_);
        if (!(z > 0.0f)) return std::nullopt;
        const float sx = glm::dot(p, right_) / z, sy = glm::dot(p, up_) / z;
        const float x = (sx / tanHalfWidth_ + 1.0f) * 0.5f * float(width_);
        const float y = (1.0f - sy / tanHalfHeight_) * 0.5f * float(height_);
        if (!(x >= 0.0f && x < float(width_) && y >= 0.0f && y < float(height_)))
            return std::nullopt;
        return Vec2<float>(x, y);
    }

    /// We(lens point, d) for a ray leaving the lens along `d` (without the pixel filter).
    float importance(const Vec3<float>& d) const {
        const float c = glm::dot(d, forward_);
        if (!(c > 0.0f)) return 0.0f;
        return pixelsPerUnitArea() / (lensArea() * sqr(sqr(c)));
    }

    /// Chooses a lens point (uniform on the aperture, `uLens`) seen from `ref`. A light
    /// subpath vertex with throughput beta contributes beta f importance / pdf at `raster`.
    std::optional<CameraConnection> sampleConnection(const Vec3<float>& ref,
                                               const Vec2<float>& uLens) const {
        Vec3<float> lens = origin_;
        if (!isPinhole()) {
            const Vec2<float> d =
                float(desc_.apertureRadius) * squareToUniformDiskConcentric(uLens);
            lens = origin_ + d.x * right_ + d.y * up_;
        }
        const Vec3<float> toLens = lens - ref;
        const float dist = glm::length(toLens);
        if (!(dist > 0.0f)) return std::nullopt;
        const Vec3<float> wi = toLens / dist;
        const auto raster = rasterPosition(lens, -wi);
        if (!raster) return std::nullopt;
        const float cosTheta = glm::dot(-wi, forward_);
        const float pdf = dist * dist / (cosTheta * lensArea());
        if (!(pdf > 0.0f) || !std::isfinite(pdf)) return std::nullopt;
        return CameraConnection{lens, wi, dist, *raster, importance(-wi), pdf};
    }

    /// Densities with which generateRay, with the film position uniform over the whole film,
    /// produces a ray from `lensPoint` along `d`: the lens point per unit area (1 for a
    /// pinhole) and the direction per solid angle. BDPT's MIS weights use them.
    CameraRayPdf rayPdf(const Vec3<float>& d) const {
        const float c = glm::dot(d, forward_);
        if (!(c > 0.0f)) return {0.0f, 0.0f};
        return {1.0f / lensArea(),
                pixelsPerUnitArea() / (float(width_) * float(height_) * c * c * c)};
    }

  private:
    float lensArea() const {
        return isPinhole() ? 1.0f : kPi<float> * sqr(float(desc_.apertureRadius));
    }
    /// K: film pixels per unit area of the image plane at distance 1.
    float pixelsPerUnitArea() const {
        return float(width_) * float(height_) / (4.0f * tanHalfWidth_ * tanHalfHeight_);
    }

    CameraDesc desc_;
    int width_, height_;
    Vec3<float> origin_, forward_, right_, up_;
    float tanHalfHeight_, tanHalfWidth_;
};

}  // namespace lamina::render
