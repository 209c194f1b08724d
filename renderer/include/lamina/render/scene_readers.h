// The parts of a scene file (docs/scene-format.md), each read by its own unit; scene_loader.cpp
// reads a file top down with them:
//   scene_settings_reader.cpp  "camera", "film", "integrator", "sampler"
//   scene_materials.cpp        "materials" and "textures", read when a shape first names one
//   shape_reader.cpp           "shapes": spheres, disks, rectangles, meshes inline or in files
//   light_reader.cpp           "lights", and the emission of shapes
// Every error names the file and the JSON path.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "lamina/render/scene_description.h"

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

// scene_settings_reader.cpp
CameraDesc readCamera(const JsonReader& r);
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
    /// and its textures on first use.
    int materialOf(const JsonReader& shape);
    /// Lists the materials and textures defined but never used in the scene.
    void recordUnused();

  private:
    int textureIndex(const JsonReader& at, const std::string& name);
    int add(const JsonReader& material);

    SceneDesc& scene_;
    std::vector<std::pair<std::string, JsonReader>> materials_, textures_;
};

/// Reads one entry of "shapes" into `scene` (shape_reader.cpp).
void readShape(const JsonReader& r, SceneMaterials& materials, SceneDesc& scene);

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
