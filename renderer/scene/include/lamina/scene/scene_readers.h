// The parts of a scene file (docs/scene-format.md), each read by its own unit; scene_loader.cpp
// reads a file top down with them:
//   scene_settings_reader.cpp  "camera", "film", "integrator", "sampler"
//   scene_materials.cpp        "materials" and "textures", read when a shape first names one
//   shape_reader.cpp           "shapes" and "objects": spheres, disks, instances, and through
//   mesh_shape_reader.cpp      rectangles and meshes inline or in files
//   light_reader.cpp           "lights", and the emission of shapes
// Every error names the file and the JSON path.
#pragma once

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "lamina/core/json_reader.h"
#include "lamina/scene/scene_description.h"

namespace lamina::render {

using Mat4 = glm::dmat4;

/// [x, y, z] at `key`.
inline Vec3d requiredVec3(const JsonReader& r, const std::string& key) {
    const auto a = r.requiredArray<3>(key);
    return {a[0], a[1], a[2]};
}
/// [x, y, z] at `key`, or `defaultValue` when the key is absent.
inline Vec3d readVec3(const JsonReader& r, const std::string& key, Vec3d defaultValue) {
    if (!r.has(key)) return defaultValue;
    return requiredVec3(r, key);
}
/// Sixteen numbers at `key`, a 4 x 4 matrix row by row.
inline Mat4 requiredMatrix(const JsonReader& r, const std::string& key) {
    const auto a = r.requiredArray<16>(key);
    Mat4 m(1.0);
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            m[col][row] = a[std::size_t(row * 4 + col)];  // glm is column-major
    return m;
}

/// A shape's or light's "transform" (a list of operations, the first applied first); the
/// identity when the key is absent (shape_reader.cpp).
Mat4 readTransform(const JsonReader& parent, const char* key = "transform");

/// The largest coordinate magnitude of anything a ray can start from or reach (camera, lens,
/// lights, shapes). Rays and hit points are float: Embree refuses a ray whose origin exceeds
/// 1.8e19 (its ray.valid() assertion), and squared distances overflow float at the same size.
/// 1e15 keeps the farthest distance in a scene (3.5e15) squared at 1e31, seven orders of
/// magnitude below float's limit for the densities and cosines it is multiplied with, and the
/// scene disk of infinite lights (twice the bounding radius) inside Embree's range.
inline constexpr double kMaxSceneCoordinate = 1e15;

/// Fails at `key` unless every coordinate of `p` lies within kMaxSceneCoordinate; `what` says
/// which point it is (empty when the key's value is the point itself).
inline void checkCoordinates(const JsonReader& r, const std::string& key, const Vec3d& p,
                             const std::string& what = "") {
    for (int c = 0; c < 3; ++c)
        if (!(std::abs(p[c]) <= kMaxSceneCoordinate))
            r.failAt(key, (what.empty() ? "" : what + " ") + "(" + formatNumber(p.x) + ", " +
                              formatNumber(p.y) + ", " + formatNumber(p.z) +
                              ") is too far out for float rays: expected coordinates within +-" +
                              formatNumber(kMaxSceneCoordinate));
}

/// An emitter's area, in double from its float geometry, must survive float: the density of a
/// point sampled on it is float(1 / area), infinite for an area below about 3e-39 (a triangle
/// or radius so small that float rounds its area away). Fails at the shape's "emission".
inline void checkEmitterArea(const JsonReader& shape, double area) {
    if (!(area > 0) || !std::isfinite(float(area)) || !std::isfinite(float(1.0 / area)))
        shape.failAt("emission",
                     "the emitting shape has zero area in float (area " + formatNumber(area) + ")");
}

// scene_settings_reader.cpp
/// The camera; its "medium" names one of `media` (read before it).
/// `warnings` gets what a realistic camera's lens file changed ("FILE: PATH: ...").
CameraDesc readCamera(const JsonReader& r, const std::vector<MediumDesc>& media,
                      std::vector<std::string>& warnings);
FilmDesc readFilm(const JsonReader& r);
void readIntegrator(const JsonReader& r, RenderSettings& settings);
void readSampler(const JsonReader& r, RenderSettings& settings);

/// The scene's named materials and textures (scene_materials.cpp). They are read when a
/// shape first refers to them, so a scene never loads what it does not use (images, n/k
/// files, albedo tables).
class SceneMaterials {
  public:
    explicit SceneMaterials(SceneDesc& scene) : scene_(scene) {}

    /// "materials": {"name": material, ...}
    void define(const JsonReader& materials);
    /// "textures": {"name": texture, ...}
    void defineTextures(const JsonReader& textures);
    /// The index of a shape's "material" (a name, or a material written in place), loading it
    /// and its textures on first use; kInterfaceMaterial for "interface".
    int materialOf(const JsonReader& shape);
    /// The index of the texture `name` (a shape's alpha, a material's parameter, a texture
    /// operation's operand), loading it on first use; fails at `at`'s `key` when it is not
    /// defined or when textures refer to each other in a cycle.
    int textureIndex(const JsonReader& at, const std::string& key, const std::string& name);
    /// The index of a material the loader makes itself (from an OBJ's MTL library), named
    /// `name`: read from `material` on first use (with the image textures `textures`, name
    /// and JSON, that it names: names derived from `name`, so new with it), the same index
    /// after. Relative files are taken against
    /// `source`'s directory, and messages name it.
    int generated(const std::string& name, const Json& material, const JsonSource& source,
                  const std::vector<std::pair<std::string, Json>>& textures = {});
    /// Lists the materials and textures defined but never used in the scene.
    void recordUnused();
    /// The scene being read (the shape readers look up its media).
    const SceneDesc& scene() const { return scene_; }

  private:
    int add(const JsonReader& material);

    SceneDesc& scene_;
    std::vector<std::pair<std::string, JsonReader>> materials_, textures_;
    std::map<std::string, int> generated_;  ///< the materials of generated(), by name
    std::vector<std::string> reading_;      ///< the textures being read, outermost first
};

/// The scene's named objects, "objects": {"name": [shape, ...], ...} (shape_reader.cpp). An
/// object is read when an instance first places it, so an unused one is never read or built.
class SceneObjects {
  public:
    SceneObjects(SceneDesc& scene, SceneMaterials& materials)
        : scene_(scene), materials_(materials) {}

    void define(const JsonReader& objects);
    /// The index of an instance's "object", reading it on first use.
    int objectOf(const JsonReader& instance);
    /// Lists the objects defined but placed by no instance.
    void recordUnused();

  private:
    SceneDesc& scene_;
    SceneMaterials& materials_;
    std::vector<std::pair<std::string, JsonReader>> objects_;
};

/// Reads one entry of "shapes" into `scene` (shape_reader.cpp).
void readShape(const JsonReader& r, SceneMaterials& materials, SceneObjects& objects,
               SceneDesc& scene);

// medium_reader.cpp
/// The name that means "no medium" wherever a medium is named.
inline constexpr const char* kVacuumMediumName = "vacuum";
/// "media": {"name": medium, ...} into scene.media.
void readMedia(const JsonReader& media, SceneDesc& scene);
/// The index of the medium named at `at`'s `key` (-1 for "vacuum"); fails on an unknown name.
int mediumIndex(const JsonReader& at, const std::string& key, const std::vector<MediumDesc>& media);
/// A shape's "interior" and "exterior" (an absent one is vacuum), or nothing when it has
/// neither.
std::optional<MediumInterfaceDesc> readMediumInterface(const JsonReader& shape,
                                                       const std::vector<MediumDesc>& media);

// light_reader.cpp
/// A radiance or intensity at `key`: a number or [r, g, b] (linear Rec.709), or a spectrum:
/// {"illuminant": "D65", "scale": Y}, {"blackbody": kelvin, "scale": Y} (both normalised to
/// luminance 1 before scaling), or {"spectrum": [[nm, value], ...], "scale": s}.
std::pair<Rgb<double>, std::shared_ptr<const EmissionSpectrum>> readEmissionValue(
    const JsonReader& parent, const std::string& key);
/// A shape's "emission", if any.
std::optional<EmissionDesc> readEmission(const JsonReader& shape);
/// One entry of "lights".
LightDesc readLight(const JsonReader& r);

}  // namespace lamina::render
