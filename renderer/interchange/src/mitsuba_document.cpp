// Reading Mitsuba XML (mitsuba_document.h) with pugixml.
#include "mitsuba_document.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <pugixml.hpp>

#include "lamina/core/error.h"

namespace lamina::render::mitsuba {

const std::string* Element::attribute(const std::string& name) const {
    for (const auto& [key, value] : attributes)
        if (key == name) return &value;
    return nullptr;
}

std::string Element::where() const {
    return file.string() + ":" + std::to_string(line);
}

std::string Element::describe() const {
    if (const std::string* type = attribute("type")) return "<" + tag + " type=\"" + *type + "\">";
    if (const std::string* name = attribute("name")) return "<" + tag + " name=\"" + *name + "\">";
    return "<" + tag + ">";
}

const Element& MitsubaDocument::find(const std::string& id, const Element& from) const {
    const auto it = ids.find(id);
    if (it == ids.end())
        throw InputError(from.where() + ": no object has id \"" + id + "\" (" + from.describe() +
                         " refers to it)");
    return *it->second;
}

std::string snakeCase(const std::string& camelCase) {
    std::string out;
    for (std::size_t i = 0; i < camelCase.size(); ++i) {
        const char c = camelCase[i];
        if (std::isupper(static_cast<unsigned char>(c)) && i > 0 &&
            (std::islower(static_cast<unsigned char>(camelCase[i - 1])) ||
             std::isdigit(static_cast<unsigned char>(camelCase[i - 1]))))
            out += '_';
        out += char(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
}

namespace {

/// One file's text and where its lines start, for offsets -> line numbers.
struct SourceText {
    std::filesystem::path file;
    std::string text;
    std::vector<std::size_t> lineStarts;

    int lineOf(std::ptrdiff_t offset) const {
        if (offset < 0) return 0;
        const auto it = std::upper_bound(lineStarts.begin(), lineStarts.end(), std::size_t(offset));
        return int(it - lineStarts.begin());
    }
};

SourceText readSource(const std::filesystem::path& file, const std::string& where) {
    std::error_code error;
    const auto size = std::filesystem::file_size(file, error);
    const std::string prefix = where.empty() ? file.string() : where;
    if (error || !std::filesystem::is_regular_file(file))
        throw InputError(prefix + ": cannot open " + file.string());
    if (size > kMaxMitsubaFileBytes)
        throw InputError(prefix + ": " + file.string() + " is larger than " +
                         std::to_string(kMaxMitsubaFileBytes >> 20) + " MiB");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(prefix + ": cannot open " + file.string());
    SourceText source{file, std::string(std::size_t(size), '\0'), {0}};
    in.read(source.text.data(), std::streamsize(size));
    source.text.resize(std::size_t(in.gcount()));
    for (std::size_t i = 0; i < source.text.size(); ++i)
        if (source.text[i] == '\n') source.lineStarts.push_back(i + 1);
    return source;
}

bool isNameCharacter(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

class Reader {
  public:
    explicit Reader(MitsubaDocument& document) : document_(document) {}

    void readScene(const std::filesystem::path& file) {
        top_ = file.parent_path();
        document_.scene = readFile(file, "", 0);
    }

  private:
    // Reads one file whose root must be <scene>; returns the root with its children.
    Element readFile(const std::filesystem::path& file, const std::string& where, int depth) {
        document_.files.push_back(file);
        SourceText source = readSource(file, where);
        bytes_ += source.text.size();
        if (bytes_ > kMaxMitsubaTotalBytes)
            throw InputError((where.empty() ? file.string() : where) +
                             ": the scene and its includes exceed " +
                             std::to_string(kMaxMitsubaTotalBytes >> 20) + " MiB");
        pugi::xml_document xml;
        const pugi::xml_parse_result result = xml.load_buffer(
            source.text.data(), source.text.size(), pugi::parse_default, pugi::encoding_utf8);
        if (!result)
            throw InputError(file.string() + ":" + std::to_string(source.lineOf(result.offset)) +
                             ": malformed XML: " + result.description());
        const pugi::xml_node root = xml.document_element();
        const std::string here =
            file.string() + ":" + std::to_string(source.lineOf(root.offset_debug()));
        if (std::string(root.name()) != "scene")
            throw InputError(here + ": expected a <scene> element, got <" +
                             std::string(root.name()) + ">");
        const pugi::xml_attribute version = root.attribute("version");
        if (!version)
            throw InputError(here + ": <scene> needs a version attribute (e.g. version=\"3.0.0\")");
        const std::string v = version.value();
        if (v.empty() || !std::isdigit(static_cast<unsigned char>(v[0])))
            throw InputError(here + ": version \"" + v + "\" is not a version number");
        const long major = std::strtol(v.c_str(), nullptr, 10);
        if (major > 3 || v.size() > 32)
            throw InputError(here + ": scene version " + v + " is newer than Mitsuba 3");
        Element scene = convert(root, source, int(major), depth, 0);
        return scene;
    }

    std::string substitute(const std::string& value, const std::string& where) const {
        std::string out;
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (value[i] != '$') {
                out += value[i];
                continue;
            }
            std::size_t end = i + 1;
            while (end < value.size() && isNameCharacter(value[end]))
                ++end;
            const std::string name = value.substr(i + 1, end - i - 1);
            if (name.empty()) {
                out += '$';
                continue;
            }
            const auto it = parameters_.find(name);
            if (it == parameters_.end())
                throw InputError(where + ": $" + name +
                                 " is not defined (declare it with <default name=\"" + name +
                                 "\" value=\"...\"/>)");
            out += it->second;
            i = end - 1;
        }
        return out;
    }

    Element convert(const pugi::xml_node& node, const SourceText& source, int major,
                    int includeDepth, int depth) {
        Element e;
        e.tag = node.name();
        e.file = source.file;
        e.line = source.lineOf(node.offset_debug());
        if (depth > kMaxMitsubaElementDepth)
            throw InputError(e.where() + ": elements nested deeper than " +
                             std::to_string(kMaxMitsubaElementDepth));
        for (const pugi::xml_attribute& a : node.attributes()) {
            std::string value = substitute(a.value(), e.where());
            // Scene version 0.x names parameters in camelCase (mitsuba3 xml.cpp upgrades them).
            if (major < 2 && std::string(a.name()) == "name") value = snakeCase(value);
            e.attributes.emplace_back(a.name(), std::move(value));
        }
        for (const pugi::xml_node& child : node.children()) {
            if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) {
                const std::string text = child.value();
                if (text.find_first_not_of(" \t\r\n") != std::string::npos)
                    throw InputError(source.file.string() + ":" +
                                     std::to_string(source.lineOf(child.offset_debug())) +
                                     ": unexpected text inside " + e.describe());
                continue;
            }
            if (child.type() != pugi::node_element) continue;
            const std::string tag = child.name();
            if (tag == "default") {
                Element d = convert(child, source, major, includeDepth, depth + 1);
                const std::string* name = d.attribute("name");
                const std::string* value = d.attribute("value");
                if (!name || !value || name->empty())
                    throw InputError(d.where() + ": <default> needs name and value");
                parameters_.emplace(*name, *value);  // the first definition wins
                continue;
            }
            if (tag == "include") {
                Element inc = convert(child, source, major, includeDepth, depth + 1);
                const std::string* name = inc.attribute("filename");
                if (!name) throw InputError(inc.where() + ": <include> needs a filename");
                if (includeDepth + 1 > kMaxMitsubaIncludeDepth)
                    throw InputError(inc.where() + ": includes nested deeper than " +
                                     std::to_string(kMaxMitsubaIncludeDepth) +
                                     " (does a file include itself?)");
                if (++includes_ > kMaxMitsubaIncludes)
                    throw InputError(inc.where() + ": more than " +
                                     std::to_string(kMaxMitsubaIncludes) + " includes");
                std::filesystem::path path = *name;
                if (path.is_relative()) {
                    const std::filesystem::path local = source.file.parent_path() / path;
                    path = std::filesystem::exists(local) ? local : top_ / path;
                }
                Element included = readFile(path, inc.where(), includeDepth + 1);
                for (Element& c : included.children)
                    e.children.push_back(std::move(c));
                continue;
            }
            e.children.push_back(convert(child, source, major, includeDepth, depth + 1));
        }
        return e;
    }

    MitsubaDocument& document_;
    std::filesystem::path top_;
    std::map<std::string, std::string> parameters_;
    int includes_ = 0;
    std::size_t bytes_ = 0;
};

void index(const Element& e, std::map<std::string, const Element*>& ids) {
    for (const Element& child : e.children) {
        if (const std::string* id = child.attribute("id"); id && child.tag != "ref") {
            const auto [it, inserted] = ids.emplace(*id, &child);
            if (!inserted)
                throw InputError(child.where() + ": id \"" + *id + "\" is used already at " +
                                 it->second->where());
        }
        index(child, ids);
    }
}

}  // namespace

void readMitsubaDocument(const std::filesystem::path& file, MitsubaDocument& document) {
    Reader reader(document);
    reader.readScene(file);
    if (const std::string* v = document.scene.attribute("version"))
        document.majorVersion = int(std::strtol(v->c_str(), nullptr, 10));
    document.ids.clear();
    index(document.scene, document.ids);
}

}  // namespace lamina::render::mitsuba
