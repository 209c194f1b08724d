#include "lamina/core/json_reader.h"

#include <cmath>
#include <set>
#include <sstream>
#include <vector>

#include "lamina/core/input_file.h"

namespace lamina {

namespace {

// nlohmann reports a byte offset; users want a line and a column.
std::string lineAndColumn(const std::string& text, std::size_t byte) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

std::string typeName(const Json& v) {
    return v.is_number() ? "a number" : std::string("a ") + v.type_name() + " " + shortDump(v);
}

// Thrown by the parser callback when the nesting gets too deep; parseJsonText turns it into
// an InputError with the file name.
struct TooDeep {};

// Thrown by the parser callback at the second occurrence of a key in one object: `path` is the
// key's JSON path, as JsonReader writes paths.
struct DuplicateKey {
    std::string path;
};

// Follows the parser's events to know where it is (the JSON path of the value being read) and
// which keys each open object has had. nlohmann's parser keeps the last of two equal keys
// without a word; a scene that sets a key twice means one of them by mistake.
class KeyTracker {
  public:
    void event(Json::parse_event_t event, const Json& parsed) {
        switch (event) {
            case Json::parse_event_t::object_start:
                frames_.push_back({false, 0, {}, {}});
                break;
            case Json::parse_event_t::array_start:
                frames_.push_back({true, 0, {}, {}});
                break;
            case Json::parse_event_t::key: {
                Frame& top = frames_.back();
                top.key = parsed.get<std::string>();
                if (!top.keys.insert(top.key).second) throw DuplicateKey{path()};
                break;
            }
            case Json::parse_event_t::object_end:
            case Json::parse_event_t::array_end:
                frames_.pop_back();
                endValue();
                break;
            case Json::parse_event_t::value:
                endValue();
                break;
        }
    }

  private:
    struct Frame {
        bool array;
        std::size_t index;  ///< of the next element, in an array
        std::string key;    ///< the last key read, in an object
        std::set<std::string> keys;
    };

    void endValue() {
        if (!frames_.empty() && frames_.back().array) ++frames_.back().index;
    }

    std::string path() const {
        std::string p;
        for (const Frame& f : frames_)
            p += f.array ? "[" + std::to_string(f.index) + "]" : (p.empty() ? "" : ".") + f.key;
        return p;
    }

    std::vector<Frame> frames_;
};

}  // namespace

std::string shortDump(const Json& v) {
    // Nesting is bounded by kMaxJsonDepth, so the dump cannot overflow the stack; a value
    // with a million elements still must not fill a message.
    constexpr std::size_t kMaxChars = 40;
    std::string text = v.dump(-1, ' ', false, Json::error_handler_t::replace);
    if (text.size() > kMaxChars) text = text.substr(0, kMaxChars) + "...";
    return text;
}

std::string formatNumber(double v) {
    std::ostringstream s;
    s.precision(10);
    s << v;
    return s.str();
}

Json parseJsonText(const std::string& text, const JsonSource& source) {
    // A value nested 100 000 levels deep would overflow the stack of everything that walks
    // it recursively (dump, destruction in some versions, the readers); refuse it here.
    // Duplicate keys are refused with their path (KeyTracker).
    KeyTracker keys;
    const Json::parser_callback_t check = [&keys](int depth, Json::parse_event_t event,
                                                  Json& parsed) {
        if (depth > kMaxJsonDepth) throw TooDeep{};
        keys.event(event, parsed);
        return true;
    };
    try {
        return Json::parse(text, check, true, /*ignore_comments=*/true);
    } catch (const TooDeep&) {
        throw InputError(source.name + ": malformed JSON: arrays and objects nested deeper than " +
                         std::to_string(kMaxJsonDepth) + " levels");
    } catch (const DuplicateKey& d) {
        throw InputError(source.name + ": " + d.path +
                         ": duplicate key: expected each key once in an object (JSON keeps only "
                         "one of them)");
    } catch (const Json::parse_error& e) {
        // e.what() is "[json.exception.parse_error.101] parse error at line 3, column 5: ...";
        // keep the part after the position, which says what was expected.
        std::string what = e.what();
        const auto colon = what.find(": ", what.find("parse error"));
        const std::string detail = colon == std::string::npos ? what : what.substr(colon + 2);
        throw InputError(source.name + ": malformed JSON at " +
                         lineAndColumn(text, e.byte == 0 ? 0 : e.byte - 1) + ": " + detail);
    } catch (const Json::exception& e) {
        // e.g. "number overflow parsing '1e999'": keep the part after the exception id.
        std::string what = e.what();
        const auto bracket = what.find("] ");
        throw InputError(source.name + ": malformed JSON: " +
                         (bracket == std::string::npos ? what : what.substr(bracket + 2)));
    }
}

Json readJsonFile(const std::filesystem::path& path) {
    JsonSource source{path.string(), path.parent_path()};
    return parseJsonText(readInputFile(path, kMaxTextFileBytes), source);
}

std::string Range::describe() const {
    const bool lo = std::isfinite(min), hi = std::isfinite(max);
    if (lo && hi)
        return "a number in " + std::string(minOpen ? "(" : "[") + formatNumber(min) + ", " +
               formatNumber(max) + (maxOpen ? ")" : "]");
    if (lo) return std::string("a number ") + (minOpen ? "> " : ">= ") + formatNumber(min);
    if (hi) return std::string("a number ") + (maxOpen ? "< " : "<= ") + formatNumber(max);
    return "a finite number";
}

JsonReader::JsonReader(const Json& value, std::string path, const JsonSource& source)
    : value_(value), path_(std::move(path)), source_(source) {}

void JsonReader::fail(const std::string& message) const {
    throw InputError(source_.name + ": " + (path_.empty() ? "(top level)" : path_) + ": " +
                     message);
}

void JsonReader::failAt(const std::string& key, const std::string& message) const {
    throw InputError(source_.name + ": " + childPath(key) + ": " + message);
}

std::string JsonReader::childPath(const std::string& key) const {
    return path_.empty() ? key : path_ + "." + key;
}

std::string JsonReader::indexPath(std::size_t index) const {
    return path_ + "[" + std::to_string(index) + "]";
}

void JsonReader::expectObject() const {
    if (!value_.is_object()) fail("expected a JSON object, got " + typeName(value_));
}

void JsonReader::noteKey(const std::string& key) const {
    used_.insert(key);  // every key asked for is a known one, present or not
    if (source_.keyLog) source_.keyLog->keys.push_back({path_, key, {}});
}

void JsonReader::noteNames(const std::string& key, std::vector<std::string> names) const {
    if (source_.keyLog) source_.keyLog->keys.push_back({path_, key, std::move(names)});
}

const Json* JsonReader::find(const std::string& key) const {
    noteKey(key);
    if (!value_.is_object()) return nullptr;
    const auto it = value_.find(key);
    return it == value_.end() ? nullptr : &*it;
}

bool JsonReader::has(const std::string& key) const {
    noteKey(key);
    return value_.is_object() && value_.contains(key);
}

JsonReader JsonReader::child(const std::string& key) const {
    const Json* v = find(key);
    if (!v) failAt(key, "missing");
    return JsonReader(*v, childPath(key), source_);
}

std::optional<JsonReader> JsonReader::optionalChild(const std::string& key) const {
    const Json* v = find(key);
    if (!v) return std::nullopt;
    return JsonReader(*v, childPath(key), source_);
}

double JsonReader::checkNumber(const Json& v, const std::string& path, Range range) const {
    // NaN and Inf cannot be written in JSON, but a string "nan" or a huge literal can.
    if (!v.is_number())
        throw InputError(source_.name + ": " + path + ": expected " + range.describe() + ", got " +
                         typeName(v));
    const double d = v.get<double>();
    if (!std::isfinite(d) || !range.contains(d))
        throw InputError(source_.name + ": " + path + ": expected " + range.describe() + ", got " +
                         formatNumber(d));
    // Rendering is in float: a number beyond its range becomes Inf (1e39 as a radiance is a
    // black image) and one below its smallest normal value loses its precision or becomes 0
    // (an emitter of zero size). One rule here covers every number of every reader.
    const float f = float(d);
    if (!std::isfinite(f) || (d != 0 && !(std::abs(f) >= std::numeric_limits<float>::min())))
        throw InputError(source_.name + ": " + path + ": expected " + range.describe() +
                         " representable in float (0 or a magnitude in [" +
                         formatNumber(std::numeric_limits<float>::min()) + ", " +
                         formatNumber(std::numeric_limits<float>::max()) + "]), got " +
                         formatNumber(d));
    return d;
}

double JsonReader::number(const std::string& key, double defaultValue, Range range) const {
    const Json* v = find(key);
    return v ? checkNumber(*v, childPath(key), range) : defaultValue;
}

double JsonReader::requiredNumber(const std::string& key, Range range) const {
    const Json* v = find(key);
    if (!v) failAt(key, "missing; expected " + range.describe());
    return checkNumber(*v, childPath(key), range);
}

std::optional<double> JsonReader::optionalNumber(const std::string& key, Range range) const {
    const Json* v = find(key);
    if (!v) return std::nullopt;
    return checkNumber(*v, childPath(key), range);
}

int JsonReader::integer(const std::string& key, int defaultValue, int min, int max) const {
    const Json* v = find(key);
    if (!v) return defaultValue;
    if (!v->is_number_integer() || v->get<long long>() < min || v->get<long long>() > max)
        failAt(key, "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
                        "], got " + shortDump(*v));
    return int(v->get<long long>());
}

bool JsonReader::boolean(const std::string& key, bool defaultValue) const {
    const Json* v = find(key);
    if (!v) return defaultValue;
    if (!v->is_boolean()) failAt(key, "expected true or false, got " + shortDump(*v));
    return v->get<bool>();
}

std::string JsonReader::string(const std::string& key, const std::string& defaultValue) const {
    const Json* v = find(key);
    if (!v) return defaultValue;
    if (!v->is_string()) failAt(key, "expected a string, got " + shortDump(*v));
    return v->get<std::string>();
}

std::string JsonReader::requiredString(const std::string& key) const {
    if (!has(key)) failAt(key, "missing; expected a string");
    return string(key, "");
}

std::filesystem::path JsonReader::filePath(const std::string& key) const {
    std::filesystem::path p = requiredString(key);
    if (p.is_relative()) {
        const auto beside = (source_.directory / p).lexically_normal();
        if (std::filesystem::exists(beside) || !std::filesystem::exists(p)) p = beside;
    }
    // A directory, a FIFO or a device is refused here, where the JSON path can be named;
    // the reader of the file checks again (and its size) for callers that bypass the scene.
    if (const std::string why = notARegularFile(p); !why.empty())
        failAt(key, p.string() + ": " + why);
    if (source_.readFiles) source_.readFiles->push_back(p);
    return p;
}

std::optional<std::array<double, 3>> JsonReader::optionalTriple(const std::string& key,
                                                                Range range) const {
    const Json* v = find(key);
    if (!v) return std::nullopt;
    if (v->is_number()) {
        const double d = checkNumber(*v, childPath(key), range);
        return std::array<double, 3>{d, d, d};
    }
    if (!v->is_array() || v->size() != 3)
        failAt(key, "expected a number or an array [r, g, b] of numbers, got " + shortDump(*v));
    std::array<double, 3> out{};
    for (std::size_t i = 0; i < 3; ++i)
        out[i] = checkNumber((*v)[i], childPath(key) + "[" + std::to_string(i) + "]", range);
    return out;
}

std::array<double, 3> JsonReader::triple(const std::string& key, std::array<double, 3> defaultValue,
                                         Range range) const {
    return optionalTriple(key, range).value_or(defaultValue);
}

std::pair<std::vector<double>, std::vector<double>> JsonReader::wavelengthTable(Range range) const {
    if (!value_.is_array() || value_.size() < 2) fail("expected at least two [nm, value] pairs");
    std::vector<double> nm, values;
    for (std::size_t i = 0; i < value_.size(); ++i) {
        const Json& pair = value_[i];
        if (!pair.is_array() || pair.size() != 2)
            fail("expected [nm, value] pairs, got " + shortDump(pair) + " at index " +
                 std::to_string(i));
        nm.push_back(checkNumber(pair[0], indexPath(i) + "[0]", Range::positive()));
        values.push_back(checkNumber(pair[1], indexPath(i) + "[1]", range));
        if (i > 0 && !(nm[i] > nm[i - 1]))
            fail("wavelengths must increase (index " + std::to_string(i) + ")");
    }
    return {std::move(nm), std::move(values)};
}

void JsonReader::finish() const {
    if (!value_.is_object()) return;
    for (const auto& [key, v] : value_.items()) {
        if (used_.count(key)) continue;
        std::string known;
        for (const auto& k : used_)
            known += (known.empty() ? "" : ", ") + k;
        failAt(key, "unknown key" +
                        (known.empty() ? std::string() : " (expected one of: " + known + ")"));
    }
}

}  // namespace lamina
