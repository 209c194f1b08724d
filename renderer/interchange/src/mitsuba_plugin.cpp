// Mitsuba parameters -> lamina values (mitsuba_plugin.h). Value syntax follows mitsuba3
// src/core/xml.cpp: lists separated by commas and/or white space, `<rgb value>` one or three
// numbers, `<spectrum value>` one number or "nm:value, ...", or `filename` (nm value per line).
#include "mitsuba_plugin.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "lamina/core/error.h"

namespace lamina::render::mitsuba {

namespace {

constexpr const char* kPropertyTags[] = {"float", "integer",  "boolean", "string", "rgb",
                                         "srgb",  "spectrum", "point",   "vector", "transform"};

bool isPropertyTag(const std::string& tag) {
    for (const char* t : kPropertyTags)
        if (tag == t) return true;
    return false;
}

std::string attributeOr(const Element& e, const std::string& name, const std::string& fallback) {
    const std::string* v = e.attribute(name);
    return v ? *v : fallback;
}

double srgbToLinear(double c) {
    // IEC 61966-2-1 transfer function.
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

Json spectrumList(const std::vector<std::pair<double, double>>& samples, const Element& at) {
    if (samples.size() < 2)
        throw InputError(at.where() + ": a spectrum needs at least two wavelengths");
    Json list = Json::array();
    for (const auto& [nm, value] : samples)
        list.push_back(Json::array({nm, value}));
    return Json{{"spectrum", list}};
}

Json readSpectrumFile(const std::filesystem::path& path, const Element& at, Diagnostics& d) {
    constexpr std::uintmax_t kMaxBytes = 1 << 20;
    std::error_code error;
    const auto size = std::filesystem::file_size(path, error);
    if (error) throw InputError(at.where() + ": cannot open the spectrum file " + path.string());
    if (size > kMaxBytes)
        throw InputError(at.where() + ": the spectrum file " + path.string() +
                         " is larger than 1 MiB");
    std::ifstream in(path);
    if (!in) throw InputError(at.where() + ": cannot open the spectrum file " + path.string());
    d.files.push_back(path);
    std::vector<std::pair<double, double>> samples;
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        const std::string where = path.string() + ":" + std::to_string(number);
        const auto v = parseNumbers(line, at, where);
        if (v.size() != 2)
            throw InputError(where + ": expected a wavelength and a value, got \"" + line + "\"");
        samples.emplace_back(v[0], v[1]);
    }
    return spectrumList(samples, at);
}

}  // namespace

// Refuses an attribute of `e` not in `allowed`: nothing in the file is dropped without a word.
void checkAttributes(const Element& e, std::initializer_list<const char*> allowed) {
    for (const auto& [name, value] : e.attributes) {
        bool known = false;
        for (const char* a : allowed)
            known |= name == a;
        if (!known)
            throw InputError(e.where() + ": <" + e.tag + ">: attribute \"" + name +
                             "\" is not supported");
    }
}

double parseNumber(const std::string& text, const Element& at, const std::string& what) {
    const auto numbers = parseNumbers(text, at, what);
    if (numbers.size() != 1)
        throw InputError(at.where() + ": " + what + ": expected one number, got \"" + text + "\"");
    return numbers[0];
}

// The components x, y, z of <translate>, <point>... : attributes x/y/z (default `fallback`)
// or value="x y z".
glm::dvec3 readTriple(const Element& e, double fallback, const std::string& what) {
    if (const std::string* value = e.attribute("value")) {
        const auto v = parseNumbers(*value, e, what);
        if (v.size() == 1) return glm::dvec3(v[0]);
        if (v.size() != 3)
            throw InputError(e.where() + ": " + what + ": expected 1 or 3 numbers, got \"" +
                             *value + "\"");
        return {v[0], v[1], v[2]};
    }
    glm::dvec3 out(fallback);
    const char* names[] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
        if (const std::string* c = e.attribute(names[i])) out[i] = parseNumber(*c, e, what);
    return out;
}

std::vector<double> parseNumbers(const std::string& text, const Element& at,
                                 const std::string& what) {
    std::vector<double> out;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c == ' ' || c == ',' || c == '\t' || c == '\n' || c == '\r') {
            ++i;
            continue;
        }
        std::size_t end = i;
        while (end < text.size() && text[end] != ' ' && text[end] != ',' && text[end] != '\t' &&
               text[end] != '\n' && text[end] != '\r')
            ++end;
        const std::string token = text.substr(i, end - i);
        char* stop = nullptr;
        errno = 0;
        const double v = std::strtod(token.c_str(), &stop);
        if (stop != token.c_str() + token.size() || !std::isfinite(v) || errno == ERANGE)
            throw InputError(at.where() + ": " + what + ": expected a number, got \"" + token +
                             "\"");
        out.push_back(v);
        if (out.size() > 4096)
            throw InputError(at.where() + ": " + what + ": more than 4096 numbers");
        i = end;
    }
    return out;
}

Plugin::Plugin(const Element& element, const MitsubaDocument& document, Diagnostics& diagnostics)
    : element_(element),
      document_(document),
      diagnostics_(diagnostics),
      type_(attributeOr(element, "type", "")) {
    checkAttributes(element, {"type", "id", "name"});
}

std::string Plugin::prefix() const {
    return element_.where() + ": " + element_.describe();
}

void Plugin::fail(const std::string& what) const {
    throw InputError(prefix() + ": " + what);
}

bool Plugin::has(const std::string& name) const {
    for (const Element& c : element_.children)
        if (const std::string* n = c.attribute("name"); n && *n == name) return true;
    return false;
}

std::string Plugin::tagOf(const std::string& name) const {
    for (const Element& c : element_.children)
        if (const std::string* n = c.attribute("name"); n && *n == name) return c.tag;
    return "";
}

const Element* Plugin::property(const std::string& name, std::initializer_list<const char*> tags) {
    for (const Element& c : element_.children) {
        const std::string* n = c.attribute("name");
        if (!n || *n != name || c.tag == "ref") continue;
        used_.insert(&c);
        for (const char* tag : tags)
            if (c.tag == tag) {
                if (c.tag == "spectrum")
                    checkAttributes(c, {"name", "value", "filename", "type"});
                else if (c.tag == "point" || c.tag == "vector")
                    checkAttributes(c, {"name", "value", "x", "y", "z"});
                else if (c.tag == "transform" || c.tag == "texture")
                    checkAttributes(c, {"name", "type", "id"});
                else
                    checkAttributes(c, {"name", "value"});
                return &c;
            }
        std::string expected;
        for (const char* tag : tags)
            expected += (expected.empty() ? "<" : " or <") + std::string(tag) + ">";
        throw InputError(c.where() + ": " + element_.describe() + ": parameter \"" + name +
                         "\" must be " + expected + ", got <" + c.tag + ">");
    }
    return nullptr;
}

std::optional<double> Plugin::optionalNumber(const std::string& name) {
    const Element* e = property(name, {"float", "integer"});
    if (!e) return std::nullopt;
    const std::string* value = e->attribute("value");
    if (!value) throw InputError(e->where() + ": parameter \"" + name + "\" needs a value");
    return parseNumber(*value, *e, "parameter \"" + name + "\"");
}

double Plugin::number(const std::string& name, double fallback) {
    return optionalNumber(name).value_or(fallback);
}

long Plugin::integer(const std::string& name, long fallback) {
    const Element* e = property(name, {"integer"});
    if (!e) return fallback;
    const std::string* value = e->attribute("value");
    const std::string text = value ? *value : "";
    char* stop = nullptr;
    errno = 0;
    const long v = std::strtol(text.c_str(), &stop, 10);
    if (text.empty() || stop != text.c_str() + text.size() || errno == ERANGE)
        throw InputError(e->where() + ": parameter \"" + name + "\": expected an integer, got \"" +
                         text + "\"");
    return v;
}

bool Plugin::boolean(const std::string& name, bool fallback) {
    const Element* e = property(name, {"boolean"});
    if (!e) return fallback;
    const std::string value = attributeOr(*e, "value", "");
    if (value == "true") return true;
    if (value == "false") return false;
    throw InputError(e->where() + ": parameter \"" + name + "\": expected true or false, got \"" +
                     value + "\"");
}

std::optional<std::string> Plugin::string(const std::string& name) {
    const Element* e = property(name, {"string"});
    if (!e) return std::nullopt;
    const std::string* value = e->attribute("value");
    if (!value) throw InputError(e->where() + ": parameter \"" + name + "\" needs a value");
    return *value;
}

std::optional<glm::dvec3> Plugin::point(const std::string& name) {
    const Element* e = property(name, {"point", "vector"});
    if (!e) return std::nullopt;
    return readTriple(*e, 0.0, "parameter \"" + name + "\"");
}

std::optional<Transform> Plugin::transform(const std::string& name) {
    const Element* e = property(name, {"transform"});
    if (!e) return std::nullopt;
    return readTransform(*e);
}

std::optional<Plugin::TextureParameter> Plugin::texture(const std::string& name) {
    for (const Element& c : element_.children) {
        const std::string* n = c.attribute("name");
        if (!n || *n != name || (c.tag != "texture" && c.tag != "ref")) continue;
        const Element* target = &c;
        if (c.tag == "ref") {
            checkAttributes(c, {"name", "id"});
            const std::string* id = c.attribute("id");
            if (!id) throw InputError(c.where() + ": <ref> needs an id");
            target = &document_.find(*id, c);
            if (target->tag != "texture")
                throw InputError(c.where() + ": " + element_.describe() + ": parameter \"" + name +
                                 "\" refers to " + target->describe() + " at " + target->where() +
                                 ", which is not a texture");
        }
        used_.insert(&c);
        return TextureParameter{&c, target};
    }
    return std::nullopt;
}

std::optional<Json> Plugin::color(const std::string& name, bool emitted) {
    const std::string what = "parameter \"" + name + "\"";
    if (const auto t = texture(name))
        throw InputError(t->at->where() + ": " + element_.describe() + ": " + what +
                         ": a texture is not supported here (give a colour)");
    const Element* e = property(name, {"rgb", "srgb", "float", "spectrum"});
    if (!e) return std::nullopt;
    if (e->tag == "spectrum" && e->attribute("type"))
        throw InputError(e->where() + ": " + what + ": the spectrum plugin \"" +
                         *e->attribute("type") +
                         "\" is not supported (give value=\"nm:value, ...\" or a filename)");
    if (e->tag == "spectrum" && e->attribute("filename")) {
        return readSpectrumFile(document_.resolve(*e->attribute("filename"), *e), *e, diagnostics_);
    }
    const std::string* value = e->attribute("value");
    if (!value) throw InputError(e->where() + ": " + what + " needs a value");
    if (e->tag == "spectrum" && value->find(':') != std::string::npos) {
        std::vector<std::pair<double, double>> samples;
        std::stringstream list(*value);
        std::string entry;
        while (std::getline(list, entry, ',')) {
            const auto colon = entry.find(':');
            if (colon == std::string::npos)
                throw InputError(e->where() + ": " + what +
                                 ": expected \"wavelength:value\" entries, got \"" + entry + "\"");
            samples.emplace_back(parseNumber(entry.substr(0, colon), *e, what),
                                 parseNumber(entry.substr(colon + 1), *e, what));
            if (samples.size() > 4096) throw InputError(e->where() + ": " + what + ": too long");
        }
        return spectrumList(samples, *e);
    }
    const auto v = parseNumbers(*value, *e, what);
    if (e->tag == "float" || e->tag == "spectrum") {
        if (v.size() != 1)
            throw InputError(e->where() + ": " + what + ": expected one number, got \"" + *value +
                             "\"");
        // An emitter's constant <spectrum> is equal energy per nm (mitsuba3 xml.cpp: its RGB is
        // value x xyz_to_srgb(1, 1, 1)): CIE illuminant E of luminance `value`.
        if (emitted && e->tag == "spectrum") return Json{{"illuminant", "E"}, {"scale", v[0]}};
        return Json(v[0]);
    }
    if (v.size() != 1 && v.size() != 3)
        throw InputError(e->where() + ": " + what + ": expected 1 or 3 numbers, got \"" + *value +
                         "\"");
    std::vector<double> rgb = v.size() == 1 ? std::vector<double>(3, v[0]) : v;
    if (e->tag == "srgb")
        for (double& c : rgb)
            c = srgbToLinear(c);
    if (rgb[0] == rgb[1] && rgb[1] == rgb[2]) return Json(rgb[0]);
    return Json::array({rgb[0], rgb[1], rgb[2]});
}

std::optional<std::filesystem::path> Plugin::file(const std::string& name) {
    const std::optional<std::string> value = string(name);
    if (!value) return std::nullopt;
    const std::filesystem::path path = document_.resolve(*value, element_);
    if (!std::filesystem::is_regular_file(path))
        fail("parameter \"" + name + "\": cannot open " + path.string());
    return std::filesystem::absolute(path);
}

std::vector<const Element*> Plugin::objects(const std::string& tag) {
    std::vector<const Element*> out;
    for (const Element& c : element_.children) {
        const Element* target = &c;
        if (c.tag == "ref") {
            const std::string* id = c.attribute("id");
            if (!id) throw InputError(c.where() + ": <ref> needs an id");
            target = &document_.find(*id, c);
        }
        if (target->tag != tag) continue;
        used_.insert(&c);
        out.push_back(target);
    }
    return out;
}

void Plugin::ignore(const std::string& name, const std::string& why) {
    for (const Element& c : element_.children)
        if (const std::string* n = c.attribute("name"); n && *n == name) {
            used_.insert(&c);
            diagnostics_.warn(c,
                              element_.describe() + ": parameter \"" + name + "\" ignored: " + why);
        }
}

void Plugin::finish() const {
    for (const Element& c : element_.children) {
        if (used_.count(&c)) continue;
        const std::string* n = c.attribute("name");
        if (isPropertyTag(c.tag) && n)
            throw InputError(c.where() + ": " + element_.describe() + ": parameter \"" + *n +
                             "\" is not supported");
        throw InputError(c.where() + ": " + element_.describe() + ": <" + c.tag +
                         (c.attribute("type") ? " type=\"" + *c.attribute("type") + "\"" : "") +
                         "> is not supported here");
    }
}

}  // namespace lamina::render::mitsuba
