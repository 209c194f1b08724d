// A Mitsuba 3 scene (mitsuba_document.h) -> a lamina scene document: what each plugin
// becomes (docs/interchange.md, "Mitsuba 3"). The scene-level part (sensor, film, sampler,
// integrator, the walk over the scene) is mitsuba_translation.cpp; shapes and emitters are
// mitsuba_shapes.cpp, BSDFs mitsuba_bsdfs.cpp.
#pragma once

#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "lamina/interchange/scene_import.h"
#include "mitsuba_bsdfs.h"
#include "mitsuba_plugin.h"

namespace lamina::render::mitsuba {

/// What translating one scene shares.
struct Translation {
    const MitsubaDocument& document;
    Diagnostics& diagnostics;
    std::filesystem::path pathsRelativeTo;
    Json scene = Json::object();
    /// Top-level BSDFs with an id, translated once: the lamina material name (the id) and
    /// the alpha a `mask` gives the shapes that use it.
    std::map<const Element*, std::optional<Json>> namedBsdfs;
    /// Media translated so far (each once, wherever it is referred to): their lamina names.
    std::map<const Element*, std::string> media;
    /// Area emitters that shapes took (a top-level one with an id is used by reference).
    std::set<const Element*> areaEmitters;
};

/// Writes the textures a translated BSDF names into the document's `textures` (their files
/// relative to the document).
void addTextures(Translation& t, const std::vector<TranslatedTexture>& textures);
/// `<shape>` (also inside a shapegroup: `inGroup`) -> the lamina shape, appended to `out`.
void translateShape(Translation& t, const Element& shape, Json& out, bool inGroup);
/// `bsplinecurve` or `linearcurve` -> a lamina `curves` shape (mitsuba_curves.cpp): the
/// curve file read, the control points placed by to_world, without material or name.
Json curveShape(Translation& t, Plugin& p);
/// Warns when the curves' `material` (a material or a name in the document) is textured:
/// Mitsuba's curves are parameterised otherwise.
void warnCurveTextures(Translation& t, Plugin& p, const Json& material);
/// `<shape type="shapegroup" id>` -> lamina `objects[id]`.
void translateShapeGroup(Translation& t, const Element& group);
/// A top-level `<emitter>` -> a lamina light.
void translateEmitter(Translation& t, const Element& emitter);

// Media (mitsuba_media.cpp).

/// The lamina name of a `<medium>`, written into the document's `media` on first use.
std::string useMedium(Translation& t, const Element& medium);
/// A shape's `interior` and `exterior` media (nested or `<ref>`s) as the lamina shape's keys.
void shapeMedia(Translation& t, Plugin& p, Json& shape);
/// The medium nested in a sensor or an emitter (Mitsuba's Endpoint takes one), if any.
std::optional<std::string> endpointMedium(Translation& t, Plugin& p);

/// The importer's entry in scene_import.cpp's table.
ImportedScene importMitsubaScene(const std::filesystem::path& file,
                                 const std::filesystem::path& pathsRelativeTo);

}  // namespace lamina::render::mitsuba
