// The scene as described by a scene file (docs/scene-format.md), after validation and before
// any acceleration structure is built: plain data, in world space, millimetres or whatever
// unit the file uses (lamina is scale-independent apart from ray offsets, which are relative).
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lamina/bsdf/material.h"
#include "lamina/core/name_table.h"
#include "lamina/core/vector.h"
#include "lamina/scene/material_textures.h"
#include "lamina/interchange/scene_format.h"
#include "lamina/spectral/emission_spectrum.h"

namespace lamina {
struct JsonSource;  // core/json_reader.h
}

namespace lamina::render {

using Vec3d = Vec3<double>;

/// The `type` of a scene file's camera: a pinhole or a thin lens (a pinhole with an aperture).
enum class CameraKind { Perspective, ThinLens };
inline constexpr NameTable kCameraKindNames{
    std::array{NameEntry{CameraKind::Perspective, "perspective"},
               NameEntry{CameraKind::ThinLens, "thin_lens"}}};

/// Which way the image's right points: `Right`: forward x up (lamina's default); `Left`:
/// up x forward (pbrt's left-handed camera space, whose +x is the image's right).
enum class Handedness { Right, Left };
inline constexpr NameTable kHandednessNames{
    std::array{NameEntry{Handedness::Right, "right"}, NameEntry{Handedness::Left, "left"}}};

struct CameraDesc {
    Vec3d position{0, 0, 0};
    Vec3d lookAt{0, 0, 1};
    Vec3d up{0, 1, 0};
    double verticalFovDegrees = 40;
    double apertureRadius = 0;  ///< 0: pinhole
    double focusDistance = 1;
    Handedness handedness = Handedness::Right;
};

enum class FilterKind { Box, Gaussian, BlackmanHarris, Triangle };
inline constexpr NameTable kFilterNames{
    std::array{NameEntry{FilterKind::Box, "box"}, NameEntry{FilterKind::Gaussian, "gaussian"},
               NameEntry{FilterKind::BlackmanHarris, "blackman_harris"},
               NameEntry{FilterKind::Triangle, "triangle"}}};

struct FilmDesc {
    int width = 256, height = 256;
    FilterKind filter = FilterKind::Box;
    double filterRadius = 0.5;  ///< pixels; box radius 0.5 is a one-pixel box
    /// gaussian: the standard deviation in pixels; unset: radius / 3 (computed in float, as
    /// before the key existed, so that such images keep their bits)
    std::optional<double> filterSigma;
};

enum class SamplerKind { Sobol, Independent };
inline constexpr NameTable kSamplerNames{std::array{
    NameEntry{SamplerKind::Sobol, "sobol"}, NameEntry{SamplerKind::Independent, "independent"}}};

/// The light transport algorithm: camera path tracing, light tracing, bidirectional.
enum class IntegratorKind { Path, Light, Bdpt };
inline constexpr NameTable kIntegratorNames{std::array{NameEntry{IntegratorKind::Path, "path"},
                                                       NameEntry{IntegratorKind::Light, "light"},
                                                       NameEntry{IntegratorKind::Bdpt, "bdpt"}}};

/// How BDPT weights its strategies (Veach 1997, section 9.2).
enum class MisHeuristic { Power, Balance };
inline constexpr NameTable kMisHeuristicNames{std::array{
    NameEntry{MisHeuristic::Power, "power"}, NameEntry{MisHeuristic::Balance, "balance"}}};

/// How next-event estimation picks a light: by the light BVH from the shading point (light_bvh.h),
/// proportional to its power, or uniformly.
enum class LightSelection { Bvh, Power, Uniform };
inline constexpr NameTable kLightSelectionNames{
    std::array{NameEntry{LightSelection::Bvh, "bvh"}, NameEntry{LightSelection::Power, "power"},
               NameEntry{LightSelection::Uniform, "uniform"}}};

struct RenderSettings {
    IntegratorKind integrator = IntegratorKind::Path;
    MisHeuristic mis = MisHeuristic::Power;  ///< bdpt only
    int maxDepth = 16;                       ///< scattering events along a path
    int russianRouletteDepth = 5;
    /// path only: false turns next-event estimation off (a BSDF-sampling-only reference)
    bool nextEvent = true;
    int spp = 16;
    std::uint64_t seed = 0;
    SamplerKind sampler = SamplerKind::Sobol;
    LightSelection lightSelection = LightSelection::Bvh;
};

/// Emission of an area light: RGB radiance (linear Rec.709) or a spectrum, one- or two-sided.
struct EmissionDesc {
    Rgb<double> radiance{0.0};
    std::shared_ptr<const EmissionSpectrum> spectrum;  ///< set: the radiance is this spectrum
    bool twoSided = false;
};

/// The `type` of a scene file's shape: analytic spheres and disks become SphereDesc and
/// DiskDesc, an instance an InstanceDesc, the others triangle meshes.
enum class ShapeKind { Sphere, Disk, Rectangle, Mesh, Obj, Ply, Instance };
inline constexpr NameTable kShapeKindNames{
    std::array{NameEntry{ShapeKind::Sphere, "sphere"}, NameEntry{ShapeKind::Disk, "disk"},
               NameEntry{ShapeKind::Rectangle, "rectangle"}, NameEntry{ShapeKind::Mesh, "mesh"},
               NameEntry{ShapeKind::Obj, "obj"}, NameEntry{ShapeKind::Ply, "ply"},
               NameEntry{ShapeKind::Instance, "instance"}}};

/// A shape's `alpha` cut-out: a constant in [0, 1] or a texture's first channel at the hit's
/// uv. A hit where alpha < 1 is kept only when alpha reaches a hash of the ray and the hit
/// (pbrt-v4's stochastic alpha test, GeometricPrimitive::Intersect); alpha 0 is invisible.
struct AlphaDesc {
    float value = 1;
    int texture = -1;  ///< into SceneDesc::textures; -1: `value`
    bool cutsOut() const { return texture >= 0 || value < 1; }
};

/// A triangle mesh in world space (or in its object's space, ObjectDesc). Quads and polygons
/// from files are already split.
struct MeshDesc {
    std::string name;  ///< for messages and `lamina info`
    std::vector<Vec3<float>> positions;
    std::vector<Vec3<float>> normals;  ///< per vertex, optional (shading normals)
    std::vector<Vec2<float>> uvs;      ///< per vertex, optional
    std::vector<std::array<std::uint32_t, 3>> triangles;
    int material = -1;
    std::optional<EmissionDesc> emission;
    AlphaDesc alpha;
};

struct SphereDesc {
    std::string name;
    Vec3d center{0.0};
    double radius = 1;
    bool flipNormals = false;  ///< emits / faces inwards (a closed emitting room)
    int material = -1;
    std::optional<EmissionDesc> emission;
    AlphaDesc alpha;
};

/// An analytic disk: centre, unit normal (its front side), radius.
struct DiskDesc {
    std::string name;
    Vec3d center{0.0};
    Vec3d normal{0, 0, 1};
    double radius = 1;
    int material = -1;
    std::optional<EmissionDesc> emission;
    AlphaDesc alpha;
};

/// An entry of "objects": shapes in the object's own space, stored once however many
/// instances place them (none emits: the reader refuses emission in an object).
struct ObjectDesc {
    std::string name;
    std::vector<MeshDesc> meshes;
    std::vector<SphereDesc> spheres;
    std::vector<DiskDesc> disks;
};

/// The axis-aligned box [lo, hi] of a list of shapes, in their own space.
template <class Shapes>
void boundingBox(const Shapes& shapes, Vec3d& lo, Vec3d& hi) {
    lo = Vec3d(std::numeric_limits<double>::infinity());
    hi = -lo;
    for (const MeshDesc& m : shapes.meshes)
        for (const Vec3<float>& p : m.positions) {
            lo = glm::min(lo, Vec3d(p));
            hi = glm::max(hi, Vec3d(p));
        }
    for (const SphereDesc& s : shapes.spheres) {
        lo = glm::min(lo, s.center - s.radius);
        hi = glm::max(hi, s.center + s.radius);
    }
    for (const DiskDesc& d : shapes.disks) {
        lo = glm::min(lo, d.center - d.radius);
        hi = glm::max(hi, d.center + d.radius);
    }
}

/// An `instance` shape: an object placed by a transform (object to world).
struct InstanceDesc {
    std::string name;
    int object = -1;  ///< into SceneDesc::objects
    glm::dmat4 toWorld{1.0};
};

enum class LightKind { Point, Spot, Directional, Environment };
inline constexpr NameTable kLightKindNames{
    std::array{NameEntry{LightKind::Point, "point"}, NameEntry{LightKind::Spot, "spot"},
               NameEntry{LightKind::Directional, "directional"},
               NameEntry{LightKind::Environment, "environment"}}};

/// How an environment image covers the sphere (environment_map.h).
enum class EnvironmentMapping { Equirectangular, EqualAreaOctahedral };
inline constexpr NameTable kEnvironmentMappingNames{
    std::array{NameEntry{EnvironmentMapping::Equirectangular, "equirectangular"},
               NameEntry{EnvironmentMapping::EqualAreaOctahedral, "equal_area_octahedral"}}};

/// Lights that are not shapes.
struct LightDesc {
    LightKind kind = LightKind::Point;
    Vec3d position{0.0};         ///< point
    Vec3d direction{0, -1, 0};   ///< directional: the direction light travels; spot: its axis
    double coneAngle = 30;       ///< spot: half-angle of the cone, degrees
    double falloffStart = 25;    ///< spot: half-angle where the smooth falloff begins, degrees
    Rgb<double> intensity{1.0};  ///< point: W/sr; directional: irradiance; environment: radiance
    std::shared_ptr<const EmissionSpectrum> spectrum;  ///< set: the intensity is this spectrum
    std::filesystem::path file;  ///< environment: an image (intensity scales it)
    EnvironmentMapping mapping = EnvironmentMapping::Equirectangular;  ///< environment image
    double rotation = 0;  ///< environment: rotation of the image about +y, degrees
    /// environment: the `transform` (an orthogonal matrix), applied after `rotation`
    Mat3<double> orientation{1.0};
};

struct SceneDesc {
    std::filesystem::path file;
    /// The format of `file`; a pbrt-v4 or Mitsuba file was translated (scene_import.h).
    SceneFormat format = SceneFormat::Lamina;
    /// What the translation, or the loader itself (an OBJ's MTL library: obj_materials.h),
    /// mapped to something else or ignored, one line each ("FILE:LINE: ...").
    std::vector<std::string> importWarnings;
    /// The scene file itself, then every file its readers opened (meshes, textures, n/k
    /// tables, environment maps), in reading order: what the provenance hash covers.
    std::vector<std::filesystem::path> inputFiles;
    CameraDesc camera;
    FilmDesc film;
    RenderSettings settings;
    std::vector<MaterialDesc> materials;
    std::vector<std::string> materialNames;
    std::vector<MaterialTextures> materialTextures;  ///< parallel to materials
    std::vector<std::shared_ptr<const Texture>> textures;
    std::vector<std::string> textureNames;
    /// Defined in the file but used by no shape: never loaded.
    std::vector<std::string> unusedMaterialNames, unusedTextureNames;
    std::vector<MeshDesc> meshes;
    std::vector<SphereDesc> spheres;
    std::vector<DiskDesc> disks;
    /// The objects some instance uses (read on first use, like materials), and the instances.
    std::vector<ObjectDesc> objects;
    std::vector<InstanceDesc> instances;
    /// Objects defined in the file but placed by no instance: never read.
    std::vector<std::string> unusedObjectNames;
    std::vector<LightDesc> lights;
};

/// Reads and validates a scene file (scene_loader.cpp, with the readers of scene_readers.h).
/// Errors name the file and the JSON path. A pbrt-v4 or Mitsuba file is translated first
/// (scene_import.h). Its warnings, and the loader's own, are kept in `importWarnings` and
/// printed to stderr, one "lamina: warning: ..." line each.
SceneDesc loadScene(const std::filesystem::path& file);
/// The same from text already in memory (tests); relative paths resolve against `directory`.
SceneDesc parseScene(const std::string& text, const JsonSource& source);

}  // namespace lamina::render
