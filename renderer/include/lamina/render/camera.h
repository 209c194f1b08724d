// Perspective camera: a pinhole, or a thin lens (aperture radius, focus distance). The image
// plane maps film x to the right and film y downwards; right = forward x up (right-handed).
#pragma once

#include "lamina/core/warp.h"
#include "lamina/render/scene_description.h"

namespace lamina::render {

class Camera {
  public:
    Camera(const CameraDesc& desc, int width, int height)
        : desc_(desc), width_(width), height_(height) {
        const Vec3d forward = glm::normalize(desc.lookAt - desc.position);
        const Vec3d right = glm::normalize(glm::cross(forward, desc.up));
        const Vec3d up = glm::cross(right, forward);
        forward_ = Vec3<float>(forward);
        right_ = Vec3<float>(right);
        up_ = Vec3<float>(up);
        origin_ = Vec3<float>(desc.position);
        tanHalfHeight_ = float(std::tan(0.5 * lamina::radians(desc.verticalFovDegrees)));
        tanHalfWidth_ = tanHalfHeight_ * float(width) / float(height);
    }

    struct CameraRay {
        Vec3<float> origin, direction;
    };

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

  private:
    CameraDesc desc_;
    int width_, height_;
    Vec3<float> origin_, forward_, right_, up_;
    float tanHalfHeight_, tanHalfWidth_;
};

}  // namespace lamina::render
