// Reading validated values out of JSON objects (materials, scenes). Every error names the
// file, the JSON path of the value and what was expected, e.g.
//   scene.json: materials.gold.roughness: expected a number in [0, 1], got -0.2
// and a reader refuses keys it does not know (a misspelt key is an error, never ignored).
#pragma once

#include <array>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "lamina/core/error.h"
#include "lamina/core/name_table.h"

namespace lamina {

using Json = nlohmann::json;

/// What readers asked of a JSON document: every key, present or not, with the path of the
/// object it was asked of, and for a key read as a name the names it accepts. The test that
/// holds docs/scene.schema.json to the readers (tests/scene/scene_schema_test.cpp) reads it.
struct JsonKeyLog {
    struct Key {
        std::string objectPath;  ///< as JsonReader::path(): "shapes[2].material"
        std::string key;
        std::vector<std::string> names;  ///< empty unless the key is read as a name
    };
    std::vector<Key> keys;
};

/// Where JSON came from: the file name used in messages and the directory relative paths
/// inside it are resolved against.
struct JsonSource {
    std::string name = "<input>";
    std::filesystem::path directory = ".";
    /// When set, every file a reader names (JsonReader::filePath) is appended: the scene's
    /// provenance hash covers what the scene read, not only its JSON text.
    std::vector<std::filesystem::path>* readFiles = nullptr;
    /// When set, every key a reader asks for is appended (JsonKeyLog).
    JsonKeyLog* keyLog = nullptr;
};

/// The deepest nesting of arrays and objects a JSON input may have (scenes need about 6).
inline constexpr int kMaxJsonDepth = 64;

/// Parses JSON text (comments allowed); a syntax error names the line and column, nesting
/// deeper than kMaxJsonDepth is an error.
Json parseJsonText(const std::string& text, const JsonSource& source);
/// Reads and parses a JSON file; a missing file is an InputError naming it.
Json readJsonFile(const std::filesystem::path& path);

/// A value for a message: its JSON text, cut to a short prefix ("...") when long.
std::string shortDump(const Json& v);

/// An interval for numeric validation, closed unless said otherwise. Every number a reader
/// accepts must also survive the conversion to float that rendering makes (checkNumber).
struct Range {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool minOpen = false;  ///< true: min itself is not allowed
    bool maxOpen = false;  ///< true: max itself is not allowed

    static Range any() { return {}; }
    static Range nonNegative() { return {0.0}; }
    static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true}; }
    static Range unit() { return {0.0, 1.0}; }
    bool contains(double v) const {
        return (minOpen ? v > min : v >= min) && (maxOpen ? v < max : v <= max);
    }
    std::string describe() const;
};

class JsonReader {
  public:
    JsonReader(const Json& value, std::string path, const JsonSource& source);

    const Json& value() const { return value_; }
    const std::string& path() const { return path_; }
    const JsonSource& source() const { return source_; }

    /// Throws InputError "<file>: <path>: <message>".
    [[noreturn]] void fail(const std::string& message) const;
    [[noreturn]] void failAt(const std::string& key, const std::string& message) const;
    std::string childPath(const std::string& key) const;
    std::string indexPath(std::size_t index) const;

    /// Requires the value to be an object.
    void expectObject() const;
    bool has(const std::string& key) const;
    /// A reader for a child value (marks the key as known).
    JsonReader child(const std::string& key) const;
    std::optional<JsonReader> optionalChild(const std::string& key) const;

    double number(const std::string& key, double defaultValue, Range range = Range::any()) const;
    double requiredNumber(const std::string& key, Range range = Range::any()) const;
    std::optional<double> optionalNumber(const std::string& key, Range range = Range::any()) const;
    int integer(const std::string& key, int defaultValue, int min, int max) const;
    bool boolean(const std::string& key, bool defaultValue) const;
    std::string string(const std::string& key, const std::string& defaultValue) const;
    std::string requiredString(const std::string& key) const;
    /// The file named by the string at `key`. A relative path is taken beside the JSON file
    /// (JsonSource::directory) when it exists there or nowhere else, otherwise relative to the
    /// working directory; fails with "<path>: no such file" when the file does not exist.
    std::filesystem::path filePath(const std::string& key) const;
    /// A number given alone (grey) or as [r, g, b].
    std::array<double, 3> triple(const std::string& key, std::array<double, 3> defaultValue,
                                 Range range = Range::any()) const;
    std::optional<std::array<double, 3>> optionalTriple(const std::string& key,
                                                        Range range = Range::any()) const;
    /// Exactly N numbers in an array.
    template <std::size_t N>
    std::array<double, N> requiredArray(const std::string& key, Range range = Range::any()) const;

    /// Records in the key log (if any) that `key` is read as one of `names`.
    void noteNames(const std::string& key, std::vector<std::string> names) const;

    /// One of the names of an enumeration's table (name_table.h).
    template <typename E, std::size_t N>
    E choice(const std::string& key, E defaultValue, const NameTable<E, N>& names) const {
        noteNames(key, names.names());
        if (!has(key)) return defaultValue;
        const std::string s = string(key, "");
        if (const auto e = names.find(s)) return *e;
        failAt(key, "expected one of " + names.list() + ", got \"" + s + "\"");
    }

    /// This value as a table [[nm, value], ...]: at least two pairs, wavelengths > 0 and
    /// strictly increasing, values in `range`.
    std::pair<std::vector<double>, std::vector<double>> wavelengthTable(Range range) const;

    /// Fails on any key that was not read (misspelt or unsupported parameters).
    void finish() const;

    /// Checks a number read by other means (e.g. from an array): a JSON number in `range`
    /// that float represents (finite, and not rounded to 0 unless it is 0).
    double checkNumber(const Json& v, const std::string& path, Range range) const;

  private:
    const Json* find(const std::string& key) const;
    void noteKey(const std::string& key) const;

    const Json& value_;
    std::string path_;
    const JsonSource& source_;
    mutable std::set<std::string> used_;
};

template <std::size_t N>
std::array<double, N> JsonReader::requiredArray(const std::string& key, Range range) const {
    const Json* v = find(key);
    if (!v) failAt(key, "missing; expected an array of " + std::to_string(N) + " numbers");
    if (!v->is_array() || v->size() != N)
        failAt(key, "expected an array of " + std::to_string(N) + " numbers, got " + shortDump(*v));
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i)
        out[i] = checkNumber((*v)[i], childPath(key) + "[" + std::to_string(i) + "]", range);
    return out;
}

/// Formats a number for messages (shortest round-trip form).
std::string formatNumber(double v);

}  // namespace lamina
