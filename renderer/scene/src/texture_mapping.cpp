#include "lamina/scene/texture_mapping.h"

#include <algorithm>
#include <cmath>

#include "lamina/core/math.h"

namespace lamina::render {

TextureSpace TextureSpace::fromTransform(const glm::dmat4& worldFromTexture) {
    const glm::dmat4 inverse = glm::inverse(worldFromTexture);
    TextureSpace s;
    s.linear = glm::mat3(glm::dmat3(inverse));
    s.translation = Vec3<float>(inverse[3]);
    return s;
}

Vec2<float> TextureMapping2D::mapProjected(const Vec3<float>& world) const {
    const Vec3<float> q = space(world);
    switch (kind) {
        case TextureMappingKind::Planar:
            // pbrt-v4's PlanarMapping: (du + q . v1, dv + q . v2), q from the origin.
            return Vec2<float>(offset.x + glm::dot(q, v1), offset.y + glm::dot(q, v2));
        case TextureMappingKind::Spherical: {
            // pbrt-v4's SphericalMapping: the direction to q as (theta / pi, phi / 2 pi), theta
            // from +z, phi in [0, 2 pi) from +x towards +y. The origin itself has no direction:
            // (0, 0) there, where pbrt-v4 would divide by zero.
            const float len = glm::length(q);
            if (!(len > 0.0f)) return Vec2<float>(0.0f);
            const float theta = std::acos(std::clamp(q.z / len, -1.0f, 1.0f));
            float phi = std::atan2(q.y, q.x);
            if (phi < 0.0f) phi += 2.0f * kPi<float>;
            return Vec2<float>(theta * kInvPi<float>, phi * kInv2Pi<float>);
        }
        case TextureMappingKind::Cylindrical:
            // pbrt-v4's CylindricalMapping: ((pi + atan2(y, x)) / 2 pi, z).
            return Vec2<float>((kPi<float> + std::atan2(q.y, q.x)) * kInv2Pi<float>, q.z);
        case TextureMappingKind::Uv:
        case TextureMappingKind::Point:
            break;
    }
    return Vec2<float>(0.0f);
}

}  // namespace lamina::render
