#include "lamina/render/realistic_camera.h"

#include <cmath>

namespace lamina::render {

RealisticCamera::RealisticCamera(const CameraDesc& desc, int width, int height)
    : lens_(desc.lensSystem), width_(width), height_(height) {
    const Vec3d forward = glm::normalize(desc.lookAt - desc.position);
    const bool left = desc.handedness == Handedness::Left;
    const Vec3d right =
        glm::normalize(left ? glm::cross(desc.up, forward) : glm::cross(forward, desc.up));
    forward_ = forward;
    right_ = right;
    up_ = left ? glm::cross(forward, right) : glm::cross(right, forward);
    origin_ = desc.position;
    // The film's width and height from its diagonal and the image's aspect.
    const double aspect = double(height) / double(width);
    filmWidth_ = lens_->filmDiagonal() / std::sqrt(1 + aspect * aspect);
    filmHeight_ = aspect * filmWidth_;
}

CameraRay RealisticCamera::generateRay(float x, float y, const Vec2<float>& lens) const {
    // The lens turns the image over: the pixel on the image's right looks through the film
    // point on the left, the top pixel through the bottom one.
    const glm::dvec2 film(-(double(x) / width_ - 0.5) * filmWidth_,
                          (double(y) / height_ - 0.5) * filmHeight_);
    const auto pupil = lens_->sampleExitPupil(film, glm::dvec2(lens));
    const CameraRay blocked{Vec3<float>(origin_), Vec3<float>(forward_), 0.0f};
    if (!pupil) return blocked;
    const glm::dvec3 from(film, 0.0);
    const glm::dvec3 d = glm::normalize(pupil->point - from);
    const auto out = lens_->traceFromFilm({from, d});
    if (!out) return blocked;
    // cos^4(theta) / (pdf z^2): the projected solid angle of the pupil point over its density.
    const double z = lens_->filmDistance();
    const double weight = std::pow(d.z, 4) / (pupil->pdf * z * z);
    const auto toWorld = [&](const glm::dvec3& v) {
        return v.x * right_ + v.y * up_ + v.z * forward_;
    };
    return {Vec3<float>(origin_ + toWorld(out->origin)),
            Vec3<float>(glm::normalize(toWorld(out->direction))), float(weight)};
}

Matrix4 RealisticCamera::cameraToWorld() const {
    const Vec3<float> r(right_), u(up_), f(forward_), o(origin_);
    return {r.x, u.x, f.x, o.x, r.y, u.y, f.y, o.y, r.z, u.z, f.z, o.z, 0.0f, 0.0f, 0.0f, 1.0f};
}

Matrix4 RealisticCamera::worldToNdc() const {
    // As PerspectiveCamera::worldToNdc with tan(half angle) = half the film over the rear
    // vertex's distance, the projection centred there.
    const double z = lens_->filmDistance();
    const double ax = 0.5 / (0.5 * filmWidth_ / z), ay = -0.5 / (0.5 * filmHeight_ / z);
    const glm::dvec3 centre = origin_ + z * forward_;
    const glm::dvec3 rows[3] = {ax * right_ + 0.5 * forward_, ay * up_ + 0.5 * forward_, forward_};
    Matrix4 m{};
    for (int r = 0; r < 3; ++r) {
        const int out = r == 2 ? 3 : r;
        m[std::size_t(4 * out)] = float(rows[r].x);
        m[std::size_t(4 * out + 1)] = float(rows[r].y);
        m[std::size_t(4 * out + 2)] = float(rows[r].z);
        m[std::size_t(4 * out + 3)] = float(-glm::dot(rows[r], centre));
    }
    m[11] = 1.0f;
    return m;
}

}  // namespace lamina::render
