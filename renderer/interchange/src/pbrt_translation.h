// What each pbrt-v4 construct becomes in a lamina scene document (docs/interchange.md,
// "pbrt-v4"). The parser's entities go in; the lamina JSON and one warning per construct that
// was mapped to something else come out. A construct without a faithful lamina equivalent is
// refused with an InputError "FILE:LINE: ...".
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "lamina/core/json_reader.h"
#include "pbrt_parser.h"

namespace lamina::render::pbrt {

/// What the translation units share: the scene, the document being written, the warnings.
struct TranslationContext {
    const ParsedScene& scene;
    std::filesystem::path pathsRelativeTo;
    Json document = Json::object();
    std::vector<std::string> warnings;
    /// The lamina names of the materials and textures written so far (translated on first use).
    std::set<std::string> writtenMaterials, writtenTextures, writtenMedia;
    /// Each pbrt material translated once (a mix refers to others by name), null for
    /// "interface".
    std::map<std::string, Json> translatedMaterials;
    /// The medium inside the shapes of each subsurface material (pbrt name -> lamina medium).
    std::map<std::string, std::string> subsurfaceInteriors;
    /// Textures being translated (a texture made of itself is refused).
    std::set<std::string> texturesInProgress;
    /// The film's diagonal in mm (pbrt-v4's Film "diagonal", 35), for a realistic camera.
    double filmDiagonal = 35;

    void warn(const Location& at, const std::string& message) {
        warnings.push_back(at.str() + ": " + message);
    }
    /// A warning said at its first occurrence only: for constructs a file repeats thousands of
    /// times (a hair file's curves), where one line says what all of them became.
    void warnOnce(const Location& at, const std::string& message) {
        if (warnedOnce.insert(message).second) warn(at, message + " (said once for the file)");
    }
    std::set<std::string> warnedOnce;
    [[noreturn]] void fail(const Location& at, const std::string& message) const;
    /// A file name of a parameter, resolved as pbrt-v4 does (against the scene file's
    /// directory) and written relative to `pathsRelativeTo`; a missing file is refused here.
    std::string filePath(const ParamList& params, const Param& p) const;
};

/// The whole translation (pbrt_translation.cpp).
Json translate(TranslationContext& context);

// The camera and its film (pbrt_camera.cpp).

/// The film, with the sensor's settings (the exposure time is `camera`'s shutter interval);
/// sets the image's `width` and `height`.
Json translateFilm(TranslationContext& context, const Entity& film, const Entity& camera,
                   int& width, int& height);
/// The camera for an image of `width` x `height`.
Json translateCamera(TranslationContext& context, const Entity& camera, int width, int height);

// Materials (pbrt_materials.cpp).

/// The lamina material name for a shape's material (`name` empty: pbrt's default diffuse),
/// writing it (and the textures it uses) into the document on first use. Returns an empty
/// string for pbrt's "interface" material: the shape is to be omitted. A subsurface material
/// also names the medium its shapes hold (subsurfaceInteriors).
std::string useMaterial(TranslationContext& context, const std::string& name,
                        const Location& usedAt);
/// A reflectance-like spectrum parameter `name` of `e`: a number, [r, g, b], {"spectrum": pairs}
/// or, with `textureAllowed`, {"texture": name}; `fallback` when absent (pbrt_materials.cpp).
Json colour(TranslationContext& context, const Entity& e, const std::string& name,
            const Json& fallback, bool textureAllowed);
/// A number parameter that may not be a texture; `fallback` when absent.
double constantNumber(const ParamList& params, const std::string& name, double fallback);

// Textures (pbrt_textures.cpp).

/// The lamina texture name for a pbrt float or spectrum texture, written on first use.
std::string useTexture(TranslationContext& context, const std::string& name,
                       const std::string& valueType, const Location& usedAt);
/// pbrt-v4's 2D texture mapping of `e` ("mapping", "uscale", "vscale", "udelta", "vdelta",
/// "v1", "v2") written into the lamina texture `t`: the uv mapping's "scale" and "offset", or a
/// projecting "mapping" (pbrt_texture_mappings.cpp).
void translateMapping2D(TranslationContext& context, const Entity& e, Json& t);
/// pbrt-v4's 3D mapping of `e` (PointTransformMapping) as the lamina texture's "point" mapping,
/// left out for the identity (pbrt_texture_mappings.cpp).
void translateMapping3D(TranslationContext& context, const Entity& e, Json& t);
/// pbrt-v4's solid textures fbm, wrinkled, windy and marble as lamina's, placed by the point
/// mapping; nullopt for any other type (pbrt_texture_mappings.cpp).
std::optional<Json> translateSolidTexture(TranslationContext& context, const Entity& e);

// Media (pbrt_media.cpp).

/// The lamina name of the medium a MediumInterface (at `usedAt`) names, written into the
/// document's `media` on first use; "" (pbrt's vacuum) is "vacuum".
std::string useMedium(TranslationContext& context, const std::string& name, const Location& usedAt);
/// Warns of each MakeNamedMedium no shape or camera used (it is not translated).
void warnUnusedMedia(TranslationContext& context);
/// pbrt-v4's measured media by name (a medium's "preset", a subsurface material's "name"):
/// sigma_a and the reduced sigma'_s as rgb triples in mm^-1; nullopt for an unknown name
/// (pbrt_media.cpp).
std::optional<std::pair<Json, Json>> measuredMediumCoefficients(const std::string& name);
/// A medium's sigma_a or sigma_s (default 1, pbrt-v4's): a number or rgb (pbrt_media.cpp).
Json mediumCoefficient(TranslationContext& context, const ParamList& params,
                       const std::string& name);
/// A medium's `scale` and Henyey-Greenstein `g` into `medium` (pbrt_media.cpp).
void mediumScaleAndPhase(const ParamList& params, Json& medium);
/// A medium's Henyey-Greenstein `g` alone (pbrt-v4's cloud reads no `scale`; pbrt_media.cpp).
void mediumPhase(const ParamList& params, Json& medium);
/// MakeNamedMedium "uniformgrid", "rgbgrid" or "nanovdb" -> a lamina grid medium, "cloud" -> a
/// lamina cloud medium, placed by the transform in effect at MakeNamedMedium
/// (pbrt_grid_media.cpp).
Json translateGridMedium(TranslationContext& context, const MediumDef& medium);

// Spectra (pbrt_spectra.cpp).

/// An emission value for an illuminant parameter (`L` or `I`): rgb, blackbody, spectrum
/// (pairs or a named spectrum) or absent (pbrt's colour-space illuminant, D65), normalised as
/// pbrt-v4 normalises lights (`scale /= SpectrumToPhotometric(spectrum)`, lights.cpp) and
/// multiplied by `scale`.
Json emissionValue(TranslationContext& context, const ParamList& params, const std::string& name,
                   double scale);
/// A parameter given as a float, an rgb triple or spectrum (nm, value) pairs, each value
/// divided by `divisor`: a number, [r, g, b] or [[nm, value], ...].
Json numericSpectrum(TranslationContext& context, const ParamList& params, const Param& p,
                     double divisor);
/// The conductor optics for pbrt's eta and k parameters (`prefix` "" or "conductor."),
/// divided by `outsideIor` (a coat's index; 1 in air).
void conductorOptics(TranslationContext& context, const Entity& e, const std::string& prefix,
                     double outsideIor, Json& material);
/// A dielectric's index: a number, a named glass or Sellmeier coefficients.
Json dielectricIor(TranslationContext& context, const ParamList& params, const std::string& name,
                   const Location& at);

}  // namespace lamina::render::pbrt
