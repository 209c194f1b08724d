// pbrt-v4 directives -> the scene's entities with their transforms (pbrt-v4's file-format
// documentation; the semantics of its BasicSceneBuilder, src/pbrt/scene.cpp). The parser keeps
// the graphics state (the current transform, reverse orientation, material, area light) and
// its stack, the named coordinate systems, materials, textures and objects; it knows nothing
// of lamina, which is pbrt_translation's job.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "pbrt_params.h"
#include "pbrt_transform_directives.h"

namespace lamina::render::pbrt {

/// One directive with a type and parameters (Shape "sphere" ..., Camera "perspective" ...).
struct Entity {
    std::string type;
    ParamList params;
    Location location;
    /// The current transform when the directive was read: pbrt's renderFromObject (for the
    /// camera, cameraFromWorld), at TransformTimes' start.
    glm::dmat4 transform{1.0};
    /// Set when the transform at TransformTimes' end differs (ActiveTransform): it moves.
    std::optional<glm::dmat4> transformEnd;
};

struct TextureDef {
    std::string name;
    std::string valueType;  ///< "float" or "spectrum"
    Entity entity;
};

struct MaterialDef {
    std::string name;  ///< the pbrt name, or a generated one for an anonymous Material
    Entity entity;     ///< its type is the material type
};

/// The media on the two sides of a surface (pbrt-v4's MediumInterface: `inside` is the side
/// the surface normal points away from); empty names are vacuum.
struct MediumSides {
    std::string inside, outside;
    Location location;  ///< where MediumInterface set them
    bool isTransition() const { return inside != outside; }
};

struct ShapeDef {
    Entity entity;
    /// The name of the material in effect: a MaterialDef's, or empty for pbrt's default
    /// (diffuse, reflectance 0.5).
    std::string material;
    Location materialLocation;  ///< where NamedMaterial named it (for an unknown name)
    std::optional<Entity> areaLight;
    bool reverseOrientation = false;
    MediumSides media;
};

/// MakeNamedMedium: its name and parameters (the entity's type is the medium's "string type").
struct MediumDef {
    std::string name;
    Entity entity;
};

struct ObjectDef {
    std::string name;
    Location location;
    std::vector<ShapeDef> shapes;
};

struct InstanceDef {
    std::string object;
    Location location;
    glm::dmat4 transform{1.0};               ///< renderFromInstance
    std::optional<glm::dmat4> transformEnd;  ///< at TransformTimes' end, when it differs
};

/// Everything a pbrt-v4 file (with its includes) describes.
struct ParsedScene {
    std::filesystem::path directory;  ///< relative file names resolve against it
    std::optional<Entity> camera, film, sampler, integrator, filter;
    std::vector<TextureDef> textures;
    std::vector<MaterialDef> materials;
    std::vector<MediumDef> media;
    /// The medium the camera sits in: pbrt-v4's outside medium when Camera was read.
    MediumSides cameraMedia;
    std::vector<ShapeDef> shapes;
    std::vector<Entity> lights;
    std::vector<ObjectDef> objects;
    std::vector<InstanceDef> instances;
    std::vector<std::string> warnings;
    std::vector<std::filesystem::path> files;  ///< the scene file and its includes
    TransformTimes transformTimes;             ///< the times of the start and end transforms
};

/// Parses `file` and the files it includes. Errors are InputErrors "FILE:LINE: ...".
ParsedScene parseFile(const std::filesystem::path& file);
/// The same from text (tests and the fuzz target); includes resolve against `directory`.
ParsedScene parseText(const std::string& text, const std::string& fileName,
                      const std::filesystem::path& directory);

}  // namespace lamina::render::pbrt
