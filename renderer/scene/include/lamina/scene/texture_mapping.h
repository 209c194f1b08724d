// Where a texture is looked up: the surface point a lookup is made at (its uv and its position in
// the world, `TexturePoint`) and the mappings that turn it into texture coordinates, as pbrt-v4
// defines them (Pharr, Jakob and Humphreys, "Physically Based Rendering", 4th ed., section
// 10.2): the 2D mappings uv (a scale and an offset of the surface's uv), planar (two vectors and
// offsets), spherical and cylindrical (about the origin of the texture's space), and the 3D
// point mapping of the solid textures (the point in the texture's space). The texture's space is
// placed in the world by its `transform`, as pbrt-v4 places it by the transform in effect where
// the texture is defined; the world point is what pbrt-v4's render-space point is, whatever
// shape or instance was hit.
#pragma once

#include "lamina/core/name_table.h"
#include "lamina/core/vector.h"

namespace lamina::render {

/// A surface point a texture is looked up at. A lookup that knows only uv (p at the origin)
/// is what every uv-mapped texture needs.
struct TexturePoint {
    TexturePoint(const Vec2<float>& uv_, const Vec3<float>& p_ = Vec3<float>(0.0f),
                 const Vec3<float>& n_ = Vec3<float>(0.0f))
        : uv(uv_), p(p_), n(n_) {}
    Vec2<float> uv;
    Vec3<float> p;  ///< in the world
    /// The geometric normal, unit, in the world (pbrt-v4's TextureEvalContext::n); the zero
    /// vector where none is known (an alpha test)
    Vec3<float> n;
};

/// The `type` of a texture's `mapping`.
enum class TextureMappingKind { Uv, Planar, Spherical, Cylindrical, Point };
inline constexpr NameTable kTextureMappingKindNames{std::array{
    NameEntry{TextureMappingKind::Uv, "uv"}, NameEntry{TextureMappingKind::Planar, "planar"},
    NameEntry{TextureMappingKind::Spherical, "spherical"},
    NameEntry{TextureMappingKind::Cylindrical, "cylindrical"},
    NameEntry{TextureMappingKind::Point, "point"}}};

/// An affine map of the world into a texture's space (the inverse of the texture's transform),
/// kept as its 3 x 3 part and translation in float: a lookup is a handful of multiplies.
struct TextureSpace {
    glm::mat3 linear{1.0f};
    Vec3<float> translation{0.0f};
    /// The world -> texture map of a texture placed by `worldFromTexture`.
    static TextureSpace fromTransform(const glm::dmat4& worldFromTexture);
    Vec3<float> operator()(const Vec3<float>& world) const { return linear * world + translation; }
};

/// A 2D mapping: (s, t) from a surface point (pbrt-v4's TextureMapping2D).
struct TextureMapping2D {
    TextureMappingKind kind = TextureMappingKind::Uv;
    Vec2<float> scale{1.0f};                                 ///< uv: (s, t) = scale uv + offset
    Vec2<float> offset{0.0f};                                ///< uv and planar: added to (s, t)
    Vec3<float> v1{1.0f, 0.0f, 0.0f}, v2{0.0f, 1.0f, 0.0f};  ///< planar
    TextureSpace space;                                      ///< planar, spherical, cylindrical

    Vec2<float> map(const TexturePoint& at) const {
        if (kind == TextureMappingKind::Uv)
            return Vec2<float>(at.uv.x * scale.x + offset.x, at.uv.y * scale.y + offset.y);
        return mapProjected(at.p);
    }

  private:
    /// The mappings that read the point's position (texture_mapping.cpp).
    Vec2<float> mapProjected(const Vec3<float>& world) const;
};

}  // namespace lamina::render
