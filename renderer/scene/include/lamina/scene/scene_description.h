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
#include "lamina/image/pixel_bounds.h"
#include "lamina/interchange/scene_format.h"
#include "lamina/scene/light_description.h"
#include "lamina/scene/material_textures.h"
#include "lamina/scene/shape_description.h"

namespace lamina {
struct JsonSource;  // core/json_reader.h
}

namespace lamina::render {

/// The `type` of a scene file's camera: a pinhole, a thin lens (a pinhole with an aperture),
/// an orthographic projection (parallel rays along the view from a screen window), or a
/// realistic one (rays traced through a system of spherical lens elements, lens_file.h).
enum class CameraKind { Perspective, ThinLens, Orthographic, Realistic };
inline constexpr NameTable kCameraKindNames{std::array{
    NameEntry{CameraKind::Perspective, "perspective"}, NameEntry{CameraKind::ThinLens, "thin_lens"},
    NameEntry{CameraKind::Orthographic, "orthographic"},
    NameEntry{CameraKind::Realistic, "realistic"}}};

class LensSystem;  // lens_system.h

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
    bool orthographic = false;
    /// orthographic: the film's extent in scene units on the plane through `position` facing
    /// the view, [x0, x1, y0, y1] with x to the image's right and y up; unset: the shorter
    /// image axis spans [-1, 1] (pbrt-v4's default)
    std::optional<std::array<double, 4>> screenWindow;
    /// An ideal linear polariser in front of the lens (the polarised mode only): the angle of
    /// its transmission axis in degrees from the image's right towards its up
    /// (docs/polarisation.md, "Stokes images"); unset: none.
    std::optional<double> analyserDegrees;
    /// The medium the camera sits in (into SceneDesc::media); -1: vacuum.
    int medium = -1;
    /// The shutter's open and close times (open <= close): each pixel sample is taken at one
    /// time uniform between them, where moving instances stand (InstanceDesc::toWorldEnd).
    std::array<double, 2> shutter{0.0, 1.0};
    /// Set: a realistic camera, its lens system (the film sits at `position`, the lens in
    /// front of it along the view); null: a perspective or orthographic one.
    std::shared_ptr<const LensSystem> lensSystem;
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
    /// The sensor (film_response.h): every sample times the imaging ratio exposure_time x iso /
    /// 100 (pbrt-v4's PixelSensor) times `scale`, its CIE XYZ scaled down to at most
    /// `maxComponentValue` in its largest component (a clamp: biased), then adapted from the
    /// white of daylight at `whiteBalance` kelvin (0: none) to the image's white (Bradford).
    double iso = 100, exposureTime = 1, scale = 1;
    std::optional<double> maxComponentValue;
    double whiteBalance = 0;
    /// Only these pixels of the image are rendered and written (the EXR's data window).
    std::optional<PixelBounds> crop;
    double imagingRatio() const { return exposureTime * iso / 100 * scale; }
};

/// sobol-global: every number of a sample a coordinate of one point of a global Sobol sequence
/// over the image (as pbrt-v4's SobolSampler): film positions unscrambled (the same for every
/// seed), the other dimensions Owen-scrambled per pixel (render/sampler.h).
enum class SamplerKind { Sobol, Independent, SobolGlobal };
inline constexpr NameTable kSamplerNames{std::array{
    NameEntry{SamplerKind::Sobol, "sobol"}, NameEntry{SamplerKind::Independent, "independent"},
    NameEntry{SamplerKind::SobolGlobal, "sobol-global"}}};

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

/// An entry of "objects": shapes in the object's own space, stored once however many
/// instances place them (none emits: the reader refuses emission in an object).
struct ObjectDesc {
    std::string name;
    std::vector<ShapeDesc> shapes;  ///< ordered by kind (orderShapesByKind)
};

/// An `instance` shape: an object placed by a transform (object to world).
struct InstanceDesc {
    std::string name;
    int object = -1;          ///< into SceneDesc::objects
    glm::dmat4 toWorld{1.0};  ///< at time 0 (and before)
    /// Set: the instance moves, from toWorld at time 0 to this at time 1 (and after), the
    /// matrices interpolated linearly, element by element (motion blur, ray_time.h).
    std::optional<glm::dmat4> toWorldEnd;
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
    /// Ordered by kind, in the order of ShapeDesc's alternatives (every mesh, then every
    /// sphere, then every disk), each kind in the order of the file (orderShapesByKind): a
    /// shape's index is its Embree geometry id.
    std::vector<ShapeDesc> shapes;
    /// The objects some instance uses (read on first use, like materials), and the instances.
    std::vector<ObjectDesc> objects;
    std::vector<InstanceDesc> instances;
    /// Objects defined in the file but placed by no instance: never read.
    std::vector<std::string> unusedObjectNames;
    std::vector<LightDesc> lights;
    /// The "media" the file names (docs/media.md), in the file's order.
    std::vector<MediumDesc> media;
    /// True when any path can meet a medium or an interface: media are defined, the camera
    /// sits in one, or a shape is an interface. Only the path integrator renders such scenes.
    bool hasMedia() const;
    /// True when an instance moves: each pixel sample then draws a time in the shutter.
    bool hasMotion() const;
};

/// Reads and validates a scene file (scene_loader.cpp, with the readers of scene_readers.h).
/// Errors name the file and the JSON path. A pbrt-v4 or Mitsuba file is translated first
/// (scene_import.h). Its warnings, and the loader's own, are kept in `importWarnings` and
/// printed to stderr, one "lamina: warning: ..." line each.
/// `printWarnings` false keeps them in `importWarnings` only (`lamina convert --check`).
SceneDesc loadScene(const std::filesystem::path& file, bool printWarnings = true);
/// The same from text already in memory (tests); relative paths resolve against `directory`.
SceneDesc parseScene(const std::string& text, const JsonSource& source);

}  // namespace lamina::render
