// A Mitsuba 3 XML scene file as a tree of elements, each with the file and line it came from
// (docs/interchange.md, "Mitsuba 3"). Reading does what Mitsuba's own parser does before any
// plugin sees the scene (mitsuba3 src/core/xml.cpp): `<default name value>` and `$name`
// substitution in attribute values, `<include filename>` spliced in place, `<path value>`
// added to the directories files are looked up in (mitsuba3 src/core/parser.cpp, its
// FileResolver), and the names of scene version 0.x files (camelCase) turned into Mitsuba 3's
// (snake_case). `<ref id>` is kept as an element; `MitsubaDocument::find` resolves it.
//
// Bounded: a file larger than kMaxMitsubaFileBytes, more than kMaxMitsubaTotalBytes in all,
// more than kMaxMitsubaIncludes includes,
// include nesting deeper than kMaxMitsubaIncludeDepth or element nesting deeper than
// kMaxMitsubaElementDepth is refused with an InputError naming the file and line.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace lamina::render::mitsuba {

inline constexpr std::size_t kMaxMitsubaFileBytes = std::size_t(64) << 20;
inline constexpr std::size_t kMaxMitsubaTotalBytes = std::size_t(256) << 20;  ///< with includes
inline constexpr int kMaxMitsubaIncludes = 256;
inline constexpr int kMaxMitsubaIncludeDepth = 16;
inline constexpr int kMaxMitsubaElementDepth = 64;

/// One XML element after substitution.
struct Element {
    std::string tag;
    /// Attributes in file order, values substituted.
    std::vector<std::pair<std::string, std::string>> attributes;
    std::vector<Element> children;
    /// The file (as given or resolved) and 1-based line of the element's start tag.
    std::filesystem::path file;
    int line = 0;

    /// The attribute's value, or nullptr.
    const std::string* attribute(const std::string& name) const;
    /// "FILE:LINE" for messages.
    std::string where() const;
    /// `<TAG type="T">` or `<TAG name="N">`, the shortest phrase that names the element.
    std::string describe() const;
};

/// A read scene. Not copyable: `ids` points into `scene`.
struct MitsubaDocument {
    MitsubaDocument() = default;
    MitsubaDocument(const MitsubaDocument&) = delete;
    MitsubaDocument& operator=(const MitsubaDocument&) = delete;

    Element scene;  ///< the root `<scene>`, includes spliced in
    int majorVersion = 3;
    /// The scene file and every included file, in reading order.
    std::vector<std::filesystem::path> files;
    /// Elements with an `id` attribute, anywhere in the tree.
    std::map<std::string, const Element*> ids;
    /// The directories of the `<path>` elements, the last one read first (Mitsuba prepends each
    /// to its FileResolver).
    std::vector<std::filesystem::path> searchPaths;

    /// The element with `id`; an InputError naming `from` when there is none.
    const Element& find(const std::string& id, const Element& from) const;
    /// A file named in `at` (a parameter or an `<include>`), as Mitsuba's FileResolver finds
    /// it: an absolute name as it is; a relative one in the first `<path>` directory that has
    /// it, else beside the file `at` is in, else beside the scene file. When none has it, the
    /// name beside `at`'s file (so that the caller's "cannot open" names that place).
    std::filesystem::path resolve(const std::string& name, const Element& at) const;
    /// The scene file's directory.
    std::filesystem::path top;
};

/// Reads `file` (a `<scene version="...">`) and everything it includes into `document`.
/// A duplicate `id` is an error naming both places.
void readMitsubaDocument(const std::filesystem::path& file, MitsubaDocument& document);

/// "thisName" -> "this_name", "intIOR" -> "int_ior": Mitsuba 0.x parameter names as Mitsuba 3
/// spells them (mitsuba3 src/core/xml.cpp upgrades version < 2 files the same way).
std::string snakeCase(const std::string& camelCase);

}  // namespace lamina::render::mitsuba
