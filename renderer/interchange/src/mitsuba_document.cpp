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

namespace {

// Mitsuba's FileResolver (mitsuba3 src/core/fresolver.cpp): the first directory that has the
// file; `searchPaths` are looked in before `local` and `top`.
std::filesystem::path resolveIn(const std::string& name,
                                const std::vector<std::filesystem::path>& searchPaths,
                                const std::filesystem::path& local,
                                const std::filesystem::path& top) {
    const std::filesystem::path path = name;
    if (path.is_absolute()) return path;
    std::error_code error;
    for (const std::filesystem::path& directory : searchPaths)
        if (std::filesystem::exists(directory / path, error)) return directory / path;
    if (std::filesystem::exists(local / path, error)) return local / path;
    if (std::filesystem::exists(top / path, error)) return top / path;
    return local / path;
}

}  // namespace

std::filesystem::path MitsubaDocument::resolve(const std::string& name, const Element& at) const {
    return resolveIn(name, searchPaths, at.file.parent_path(), top);
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
        document_.top = file.parent_path();
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

    // mitsuba3 parser.cpp substitute_parameters: every "$name" of a parameter defined so far
    // is replaced, the longest names first (so $resx is not $res then "x"); a "$" left over
    // that "\" does not escape is an undefined parameter; "\$" becomes "$".
    std::string substitute(const std::string& value, const std::string& where) const {
        if (value.find('$') == std::string::npos) return value;
        std::vector<std::pair<std::string, std::string>> byLength(parameters_.begin(),
                                                                  parameters_.end());
        std::stable_sort(byLength.begin(), byLength.end(), [](const auto& a, const auto& b) {
            return a.first.size() > b.first.size();
        });
        std::string out = value;
        for (const auto& [name, replacement] : byLength) {
            const std::string key = "$" + name;
            std::size_t pos = 0;
            while ((pos = out.find(key, pos)) != std::string::npos) {
                if (pos > 0 && out[pos - 1] == '\\') {
                    pos += key.size();
                    continue;
                }
                out.replace(pos, key.size(), replacement);
                pos += replacement.size();
                if (out.size() > kMaxMitsubaFileBytes)
                    throw InputError(where + ": substitutions grow an attribute beyond " +
                                     std::to_string(kMaxMitsubaFileBytes >> 20) + " MiB");
            }
        }
        for (std::size_t pos = 0; (pos = out.find('$', pos)) != std::string::npos; ++pos) {
            if (pos > 0 && out[pos - 1] == '\\') continue;
            std::size_t end = pos + 1;
            while (end < out.size() && isNameCharacter(out[end]))
                ++end;
            const std::string name = out.substr(pos + 1, end - pos - 1);
            throw InputError(where + ": $" + name +
                             " is not defined (declare it with <default name=\"" + name +
                             "\" value=\"...\"/> before it is used)");
        }
        for (std::size_t pos = 0; (pos = out.find("\\$", pos)) != std::string::npos; ++pos)
            out.erase(pos, 1);
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
                // Mitsuba looks in the including file's directory first, then its resolver's.
                const std::filesystem::path local = source.file.parent_path();
                std::error_code error;
                const std::filesystem::path path =
                    std::filesystem::exists(local / *name, error)
                        ? local / *name
                        : resolveIn(*name, document_.searchPaths, local, document_.top);
                Element included = readFile(path, inc.where(), includeDepth + 1);
                for (Element& c : included.children)
                    e.children.push_back(std::move(c));
                continue;
            }
            if (tag == "path") {
                Element p = convert(child, source, major, includeDepth, depth + 1);
                addSearchPath(p, depth == 0);
                continue;
            }
            e.children.push_back(convert(child, source, major, includeDepth, depth + 1));
        }
        return e;
    }

    // `<path value>`: a directory that file names are looked up in (mitsuba3 parser.cpp: only
    // in the root; a relative one is taken from the file's directory, else from the resolver).
    void addSearchPath(const Element& p, bool inRoot) {
        checkPathAttributes(p);
        if (!inRoot) throw InputError(p.where() + ": <path> must be a child of <scene>");
        const std::string& value = *p.attribute("value");
        const std::filesystem::path local = p.file.parent_path();
        std::error_code error;
        std::filesystem::path directory = value;
        if (directory.is_relative())
            directory = std::filesystem::exists(local / value, error)
                            ? local / value
                            : resolveIn(value, document_.searchPaths, local, document_.top);
        if (!std::filesystem::is_directory(directory, error))
            throw InputError(p.where() + ": <path>: the directory \"" + value + "\" is not there");
        document_.searchPaths.insert(document_.searchPaths.begin(), directory);
    }

    static void checkPathAttributes(const Element& p) {
        for (const auto& [name, value] : p.attributes)
            if (name != "value")
                throw InputError(p.where() + ": <path>: attribute \"" + name +
                                 "\" is not supported");
        if (!p.attribute("value") || p.attribute("value")->empty())
            throw InputError(p.where() + ": <path> needs a value (a directory)");
    }

    MitsubaDocument& document_;
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
