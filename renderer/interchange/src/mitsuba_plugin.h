// One Mitsuba object (a `<bsdf>`, `<shape>`, `<emitter>`...) and its parameters, read the way
// Mitsuba's plugins read their Properties: by name, with a type, and every parameter the file
// gives must be read (mitsuba3 refuses unreferenced properties; so does lamina, naming the
// file and line). Values come out as lamina scene JSON (numbers, colours, spectra, transforms).
#pragma once

#include <algorithm>
#include <filesystem>
#include <glm/mat4x4.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "lamina/core/json_reader.h"
#include "mitsuba_document.h"

namespace lamina::render::mitsuba {

/// Where the translation's warnings go ("FILE:LINE: what it became"), and the files it read.
struct Diagnostics {
    std::vector<std::string> warnings;
    std::vector<std::filesystem::path> files;
    /// Once per place and text: an object referred to twice is translated twice.
    void warn(const Element& at, const std::string& what) {
        std::string warning = at.where() + ": " + what;
        if (std::find(warnings.begin(), warnings.end(), warning) == warnings.end())
            warnings.push_back(std::move(warning));
    }
};

/// Splits "1, 2 3" into numbers; an InputError naming `at` when a token is not a finite number.
std::vector<double> parseNumbers(const std::string& text, const Element& at,
                                 const std::string& what);

/// Refuses an attribute of `e` not in `allowed`: nothing in the file is dropped without a word.
void checkAttributes(const Element& e, std::initializer_list<const char*> allowed);
/// One finite number; an InputError naming `at` otherwise.
double parseNumber(const std::string& text, const Element& at, const std::string& what);
/// The components x, y, z of <translate>, <point>... : attributes x/y/z (default `fallback`)
/// or value="x y z".
glm::dvec3 readTriple(const Element& e, double fallback, const std::string& what);

/// A transform: the lamina operations (shape `transform` list) and their product.
struct Transform {
    Json operations = Json::array();
    glm::dmat4 matrix{1.0};
};

/// Reads a `<transform>` element's operations in order (each one applied after the previous).
Transform readTransform(const Element& transform);

class Plugin {
  public:
    Plugin(const Element& element, const MitsubaDocument& document, Diagnostics& diagnostics);

    const Element& element() const { return element_; }
    const std::string& type() const { return type_; }
    /// `FILE:LINE: <bsdf type="diffuse">` for messages.
    std::string prefix() const;
    [[noreturn]] void fail(const std::string& what) const;
    void warn(const std::string& what) const { diagnostics_.warn(element_, what); }
    Diagnostics& diagnostics() const { return diagnostics_; }
    const MitsubaDocument& document() const { return document_; }

    bool has(const std::string& name) const;
    /// The tag of parameter `name` ("float", "string"...), or "" when absent.
    std::string tagOf(const std::string& name) const;
    double number(const std::string& name, double fallback);
    std::optional<double> optionalNumber(const std::string& name);
    long integer(const std::string& name, long fallback);
    bool boolean(const std::string& name, bool fallback);
    std::optional<std::string> string(const std::string& name);
    std::optional<glm::dvec3> point(const std::string& name);
    std::optional<Transform> transform(const std::string& name);
    /// A colour or spectrum parameter (`<rgb>`, `<srgb>`, `<float>`, `<spectrum>`) as a lamina
    /// colour: a number, [r, g, b] or {"spectrum": [[nm, value], ...]}. A texture is refused
    /// (colorOrTexture, mitsuba_textures.h, takes one where lamina can).
    /// `emitted`: an emitter's, where a constant `<spectrum>` is illuminant E.
    std::optional<Json> color(const std::string& name, bool emitted = false);
    /// A parameter given as a texture: the element that gives it (a `<texture name>` or a
    /// `<ref name id>`) and the `<texture>` it is.
    struct TextureParameter {
        const Element* at;
        const Element* texture;
    };
    /// Parameter `name` when it is a texture (nested, or a `<ref>` to a `<texture>`), read;
    /// nullopt otherwise.
    std::optional<TextureParameter> texture(const std::string& name);
    /// A file parameter, as the absolute path it names (MitsubaDocument::resolve: the `<path>`
    /// directories, the file's, the scene's); a missing file is an error naming the line.
    std::optional<std::filesystem::path> file(const std::string& name);

    /// Nested objects (children with tag `tag`, `<ref>`s resolved), in file order; each is
    /// consumed. Named ones are consumed under their name as well.
    std::vector<const Element*> objects(const std::string& tag);
    /// Marks a parameter as known and ignored, with a warning saying so.
    void ignore(const std::string& name, const std::string& why);
    /// Refuses every parameter and nested object not read.
    void finish() const;

  private:
    const Element* property(const std::string& name, std::initializer_list<const char*> tags);

    const Element& element_;
    const MitsubaDocument& document_;
    Diagnostics& diagnostics_;
    std::string type_;
    std::set<const Element*> used_;
};

}  // namespace lamina::render::mitsuba
