// The shapes of a scene (docs/scene-format.md, "shapes"), as the readers leave them: one
// std::variant of kinds, each kind a struct with its own fields on top of what every surface
// has (SurfaceDesc: name, material, emission, alpha). A new kind of shape is a struct here and
// an alternative of ShapeDesc; the compiler then names every place that treats each kind on
// its own (the readers, boundingBox, the geometry, the light set, `lamina info`).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "lamina/core/name_table.h"
#include "lamina/core/vector.h"
#include "lamina/scene/medium_description.h"
#include "lamina/spectral/emission_spectrum.h"

namespace lamina::render {

using Vec3d = Vec3<double>;

/// Emission of an area light: RGB radiance (linear Rec.709) or a spectrum, one- or two-sided.
struct EmissionDesc {
    Rgb<double> radiance{0.0};
    std::shared_ptr<const EmissionSpectrum> spectrum;  ///< set: the radiance is this spectrum
    bool twoSided = false;
};

/// The `type` of a scene file's shape: analytic spheres and disks become SphereDesc and
/// DiskDesc (QuadricDesc when clipped), a cylinder a QuadricDesc, an instance an InstanceDesc,
/// the others triangle meshes but `curves` (CurvesDesc).
enum class ShapeKind {
    Sphere,
    Disk,
    Cylinder,
    Rectangle,
    Mesh,
    Obj,
    Ply,
    Serialized,
    Instance,
    Curves
};
inline constexpr NameTable kShapeKindNames{std::array{
    NameEntry{ShapeKind::Sphere, "sphere"}, NameEntry{ShapeKind::Disk, "disk"},
    NameEntry{ShapeKind::Cylinder, "cylinder"}, NameEntry{ShapeKind::Rectangle, "rectangle"},
    NameEntry{ShapeKind::Mesh, "mesh"}, NameEntry{ShapeKind::Obj, "obj"},
    NameEntry{ShapeKind::Ply, "ply"}, NameEntry{ShapeKind::Serialized, "serialized"},
    NameEntry{ShapeKind::Curves, "curves"}, NameEntry{ShapeKind::Instance, "instance"}}};

/// A shape's `alpha` cut-out: a constant in [0, 1] or a texture's first channel at the hit's
/// uv. A hit where alpha < 1 is kept only when alpha reaches a hash of the ray and the hit
/// (pbrt-v4's stochastic alpha test, GeometricPrimitive::Intersect); alpha 0 is invisible.
struct AlphaDesc {
    float value = 1;
    int texture = -1;  ///< into SceneDesc::textures; -1: `value`
    bool cutsOut() const { return texture >= 0 || value < 1; }
};

/// A shape's "material": "interface" (docs/media.md): an index-matched boundary between two
/// media, which a path crosses without scattering. Its material index is kInterfaceMaterial.
inline constexpr const char* kInterfaceMaterialName = "interface";
inline constexpr int kInterfaceMaterial = -2;

/// What every kind of shape has.
struct SurfaceDesc {
    std::string name;   ///< for messages and `lamina info`
    int material = -1;  ///< into SceneDesc::materials, or kInterfaceMaterial
    /// Set when the shape names an "interior" or "exterior" medium: a path that crosses the
    /// surface enters the medium of the side it goes to. Unset: crossing keeps the medium.
    std::optional<MediumInterfaceDesc> media;
    std::optional<EmissionDesc> emission;
    AlphaDesc alpha;
    bool isInterface() const { return material == kInterfaceMaterial; }
};

/// A triangle mesh in world space (or in its object's space, ObjectDesc). Quads and polygons
/// from files are already split.
struct MeshDesc : SurfaceDesc {
    std::vector<Vec3<float>> positions;
    std::vector<Vec3<float>> normals;  ///< per vertex, optional (shading normals)
    std::vector<Vec2<float>> uvs;      ///< per vertex, optional
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

struct SphereDesc : SurfaceDesc {
    Vec3d center{0.0};
    double radius = 1;
    bool flipNormals = false;  ///< emits / faces inwards (a closed emitting room)
};

/// An analytic disk: centre, unit normal (its front side), radius.
struct DiskDesc : SurfaceDesc {
    Vec3d center{0.0};
    Vec3d normal{0, 0, 1};
    double radius = 1;
};

/// Which of pbrt-v4's quadrics a QuadricDesc is.
enum class Quadric { Sphere, Cylinder, Disk };

/// A partial sphere, a cylinder or a partial disk: pbrt-v4's quadrics (Pharr, Jakob and
/// Humphreys, "Physically Based Rendering", 4th edition, sections 6.2-6.4) in a frame of their
/// own, z the axis and phi = atan2(y, x) in [0, 2 pi) turning from +x towards +y. The sphere
/// (centred at the origin) is clipped to z_min <= z <= z_max and phi <= phi_max; the cylinder
/// (about the z axis, open: no caps) likewise; the disk (in the plane z = 0) to
/// inner_radius <= rho <= radius and phi <= phi_max. The frame is a similarity's: `axes` is
/// orthonormal (a rotation, or a rotation and a mirroring) and lengths are in the shape's
/// space. A sphere or disk that is not clipped is a SphereDesc or DiskDesc (Embree's own
/// primitives); these are Embree user geometry with an exact intersection (quadric.h).
struct QuadricDesc : SurfaceDesc {
    Quadric kind = Quadric::Cylinder;
    Vec3d origin{0.0};     ///< the frame's origin
    glm::dmat3 axes{1.0};  ///< the frame's x, y and z axes (columns), orthonormal
    double radius = 1;
    double zMin = -1, zMax = 1;       ///< the sphere's and the cylinder's clipping along z
    double innerRadius = 0;           ///< the disk's
    double phiMax = 2 * kPi<double>;  ///< radians, in (0, 2 pi]
    /// The normal faces the axis (sphere, cylinder) or the frame's -z (disk) instead of away
    /// from it or +z.
    bool flipNormals = false;

    Vec3d toShapeSpace(const Vec3d& local) const { return origin + axes * local; }
    Vec3d toLocal(const Vec3d& p) const { return glm::transpose(axes) * (p - origin); }
    /// The area: phi_max r (z_max - z_min) for the sphere (Archimedes) and the cylinder,
    /// phi_max (r^2 - r_inner^2) / 2 for the disk.
    double area() const;
    /// The axis-aligned box [lo, hi] in the shape's space (the frame's box, transformed).
    void bounds(Vec3d& lo, Vec3d& hi) const;
};

/// How a curve's cross-section is drawn (pbrt-v4's curve types): a round tube (Embree's round
/// curves, a real surface), or a flat ribbon turned to face each ray (Embree's flat curves, for
/// distant hair: each ray sees its own ribbon), shaded with a tube's normal.
enum class CurveShape { Cylinder, Flat };
inline constexpr NameTable kCurveShapeNames{
    std::array{NameEntry{CurveShape::Cylinder, "cylinder"}, NameEntry{CurveShape::Flat, "flat"}}};

/// Curves (hair, fur): strands of cubic Bezier segments, each segment four control points
/// of which the last is the next segment's first, with a radius per control point. `segments`
/// holds each segment's first control point.
struct CurvesDesc : SurfaceDesc {
    std::vector<Vec3<float>> points;
    std::vector<float> radii;
    std::vector<std::uint32_t> segments;
    CurveShape shape = CurveShape::Cylinder;
    /// The most control points one shape holds (fuzzing: 16 bytes each in Embree, 64 MiB).
    static constexpr std::size_t kMaxPoints = std::size_t(1) << 22;
};

/// One shape. The order of the alternatives is the order of the kinds in a list of shapes
/// (orderShapesByKind), and so of their Embree geometry ids and of the emitters' lights.
using ShapeDesc = std::variant<MeshDesc, SphereDesc, DiskDesc, QuadricDesc, CurvesDesc>;

/// The fields every kind has.
inline const SurfaceDesc& surface(const ShapeDesc& shape) {
    return std::visit([](const SurfaceDesc& s) -> const SurfaceDesc& { return s; }, shape);
}
inline SurfaceDesc& surface(ShapeDesc& shape) {
    return std::visit([](SurfaceDesc& s) -> SurfaceDesc& { return s; }, shape);
}

/// How many of `shapes` are of the kind `Kind` (MeshDesc, SphereDesc, DiskDesc, QuadricDesc).
template <class Kind>
std::size_t countShapes(const std::vector<ShapeDesc>& shapes) {
    return std::size_t(std::count_if(shapes.begin(), shapes.end(), [](const ShapeDesc& s) {
        return std::holds_alternative<Kind>(s);
    }));
}

/// Orders a list of shapes by kind, in the order of ShapeDesc's alternatives (every mesh,
/// then every sphere, then every disk, then every quadric), keeping the order of each kind's
/// shapes. The scene loader leaves SceneDesc::shapes and every ObjectDesc::shapes so: a shape's
/// index is then its Embree geometry id (geometry.h), and the light set makes the emitters' lights
/// in this order, as they were made when each kind had a list of its own.
inline void orderShapesByKind(std::vector<ShapeDesc>& shapes) {
    std::stable_sort(shapes.begin(), shapes.end(),
                     [](const ShapeDesc& a, const ShapeDesc& b) { return a.index() < b.index(); });
}

/// The axis-aligned box [lo, hi] of one shape, in its own space (empty, lo > hi, for a mesh
/// without vertices).
void shapeBounds(const ShapeDesc& shape, Vec3d& lo, Vec3d& hi);

/// The axis-aligned box [lo, hi] of a list of shapes, in their own space.
void boundingBox(const std::vector<ShapeDesc>& shapes, Vec3d& lo, Vec3d& hi);

}  // namespace lamina::render
