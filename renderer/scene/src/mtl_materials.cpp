// MTL libraries -> lamina materials (obj_materials.h). The file is scanned line by line here,
// so that every value and every ignored key can be named by its line; tinyobjloader reads
// the same text for the OBJ's face assignment (obj_reader.cpp).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "lamina/core/error.h"
#include "lamina/scene/obj_materials.h"

namespace lamina::render {

namespace {

// One newmtl entry as written: each key's numbers (or, for map_Kd, its words) and line.
struct MtlEntry {
    std::string name;
    int line = 0;
    struct Value {
        std::vector<std::string> words;
        int line = 0;
    };
    std::map<std::string, Value> keys;
};

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;)
        out.push_back(w);
    return out;
}

class MtlMapper {
  public:
    MtlMapper(const std::filesystem::path& file, std::vector<std::string>& warnings)
        : file_(file), warnings_(warnings) {}

    [[noreturn]] void fail(int line, const std::string& message) const {
        throw InputError(file_.string() + ":" + std::to_string(line) + ": " + message);
    }
    void warn(int line, const std::string& message) const {
        warnings_.push_back(file_.string() + ":" + std::to_string(line) + ": " + message);
    }

    bool has(const MtlEntry& e, const std::string& key) const { return e.keys.count(key) != 0; }

    double number(const MtlEntry& e, const std::string& key, double defaultValue, double min,
                  double max) const {
        const auto it = e.keys.find(key);
        if (it == e.keys.end()) return defaultValue;
        if (it->second.words.size() != 1) fail(it->second.line, key + ": expected one number");
        return parse(it->second, key, 0, min, max);
    }

    // r g b, or a single number for grey (as tinyobjloader reads it).
    std::optional<Rgb<double>> colour(const MtlEntry& e, const std::string& key, double max) const {
        const auto it = e.keys.find(key);
        if (it == e.keys.end()) return std::nullopt;
        const auto& v = it->second;
        if (!v.words.empty() && (v.words[0] == "spectral" || v.words[0] == "xyz"))
            fail(v.line, key + ": only r g b colours are supported, not " + v.words[0]);
        if (v.words.size() != 1 && v.words.size() != 3) fail(v.line, key + ": expected r g b");
        Rgb<double> c;
        for (int i = 0; i < 3; ++i)
            c[i] = parse(v, key, v.words.size() == 1 ? 0 : std::size_t(i), 0.0, max);
        return c;
    }

  private:
    double parse(const MtlEntry::Value& v, const std::string& key, std::size_t i, double min,
                 double max) const {
        const std::string& w = v.words[i];
        std::size_t used = 0;
        double x = 0;
        try {
            x = std::stod(w, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used != w.size() || !std::isfinite(x) || !std::isfinite(float(x)))
            fail(v.line, key + ": expected a number, got \"" + w + "\"");
        if (x < min || x > max)
            fail(v.line, key + ": expected a value in [" + formatNumber(min) + ", " +
                             formatNumber(max) + "], got " + w);
        return x;
    }

    const std::filesystem::path& file_;
    std::vector<std::string>& warnings_;
};

// The keys the mapping reads; any other key is warned about once (its first line).
const std::set<std::string> kMappedKeys = {"Kd", "Ks",    "Ns",     "Ni", "d",
                                           "Tr", "illum", "map_Kd", "Ke"};

Json rgbJson(const Rgb<double>& c) {
    return Json::array({c[0], c[1], c[2]});
}

MtlMaterial mapEntry(const MtlEntry& e, const MtlMapper& m, const std::filesystem::path& file) {
    MtlMaterial out;
    out.mtlName = e.name;
    out.name = file.string() + ":" + e.name;
    out.file = file;
    out.line = e.line;
    const Rgb<double> kd = m.colour(e, "Kd", 1.0).value_or(Rgb<double>(0.5));
    const Rgb<double> ks = m.colour(e, "Ks", 1.0).value_or(Rgb<double>(0.0));
    const double ns = m.number(e, "Ns", 0.0, 0.0, 1e7);
    const double ni = m.number(e, "Ni", 1.0, 1e-3, 100.0);
    double d = m.number(e, "d", 1.0, 0.0, 1.0);
    if (m.has(e, "Tr")) {
        if (m.has(e, "d"))
            m.warn(e.keys.at("Tr").line, "Tr and d both given: d is used");
        else
            d = 1.0 - m.number(e, "Tr", 0.0, 0.0, 1.0);
    }
    const double illum = m.number(e, "illum", 2.0, 0.0, 10.0);
    if (illum != std::floor(illum))
        m.fail(e.keys.at("illum").line, "illum: expected an integer 0-10");
    if (const auto ke = m.colour(e, "Ke", 1e6); ke && ke->maxValue() > 0) out.emission = *ke;

    if (const auto it = e.keys.find("map_Kd"); it != e.keys.end()) {
        const auto& w = it->second.words;
        if (w.empty()) m.fail(it->second.line, "map_Kd: expected a file name");
        if (w.size() > 1)
            m.warn(it->second.line,
                   "map_Kd options (" + w.front() + " ...) are not supported: ignored");
        out.diffuseMap = w.back();
        out.textureName = out.name + ":map_Kd";
        if (m.has(e, "Kd") && kd != Rgb<double>(1.0))
            m.warn(it->second.line,
                   "map_Kd is used as the colour alone: Kd does not multiply it in lamina");
    }

    const bool glass = (illum >= 4 && illum <= 7) || d < 1.0;
    if (glass) {
        double ior = ni;
        if (!m.has(e, "Ni") || ni == 1.0) {
            m.warn(e.line, "newmtl " + e.name + " is glass (illum " + formatNumber(illum) + ", d " +
                               formatNumber(d) + ") without an index Ni: ior 1.5");
            ior = 1.5;
        }
        if (out.diffuseMap)
            m.warn(e.keys.at("map_Kd").line, "map_Kd on glass (a dielectric) is ignored");
        out.diffuseMap.reset();
        if (d > 0.0 && d < 1.0)
            m.warn(e.keys.count("d") ? e.keys.at("d").line : e.keys.at("Tr").line,
                   "partial dissolve d " + formatNumber(d) + " becomes clear glass");
        out.material = {{"type", "dielectric"}, {"ior", ior}};
        return out;
    }
    const Json colour = out.diffuseMap ? Json{{"texture", out.textureName}} : rgbJson(kd);
    if (ks.maxValue() > 0.0) {
        // Walter et al. 2007, section 5.2: alpha_b = sqrt(2 / (alpha_p + 2)) relates the
        // Beckmann width to the Blinn-Phong exponent alpha_p (here Ns); lamina's standard
        // uses it as the GGX alpha.
        out.material = {{"type", "standard"},
                        {"base_color", colour},
                        {"specular_color", rgbJson(ks)},
                        {"alpha", std::sqrt(2.0 / (ns + 2.0))}};
    } else {
        out.material = {{"type", "lambert"}, {"reflectance", colour}};
    }
    return out;
}

}  // namespace

std::vector<MtlMaterial> readMtlLibrary(const std::filesystem::path& file, const std::string& text,
                                        std::vector<std::string>& warnings) {
    const MtlMapper mapper(file, warnings);
    std::vector<MtlEntry> entries;
    std::map<std::string, int> ignored;  // key -> first line
    std::map<std::string, int> defined;  // newmtl name -> its line
    std::istringstream in(text);
    int lineNumber = 0;
    for (std::string line; std::getline(in, line);) {
        ++lineNumber;
        if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        std::vector<std::string> w = words(line);
        if (w.empty()) continue;
        const std::string key = w.front();
        w.erase(w.begin());
        if (key == "newmtl") {
            if (w.size() != 1) mapper.fail(lineNumber, "newmtl: expected one name");
            if (const auto [at, added] = defined.emplace(w[0], lineNumber); !added)
                mapper.fail(lineNumber, "newmtl " + w[0] + " is defined twice (first at line " +
                                            std::to_string(at->second) + ")");
            entries.push_back({w[0], lineNumber, {}});
            continue;
        }
        if (!kMappedKeys.count(key)) {
            ignored.emplace(key, lineNumber);
            continue;
        }
        if (entries.empty()) mapper.fail(lineNumber, key + " before any newmtl");
        entries.back().keys.emplace(key, MtlEntry::Value{w, lineNumber});
    }
    std::vector<std::pair<int, std::string>> byLine;
    for (const auto& [key, line] : ignored)
        byLine.emplace_back(line, key);
    std::sort(byLine.begin(), byLine.end());
    for (const auto& [line, key] : byLine)
        mapper.warn(line, key + " is not supported: ignored (here and on any later line)");
    std::vector<MtlMaterial> out;
    for (const auto& e : entries)
        out.push_back(mapEntry(e, mapper, file));
    return out;
}

}  // namespace lamina::render
