// The pieces parseMaterial is made of (internal to lamina_bsdf): the readers of parameters
// several material types share, and one reader per material family. material_parser.cpp
// holds the table of material types that names them.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "lamina/bsdf/diffuse.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/core/json_reader.h"

namespace lamina {

inline RgbInput toRgb(const std::array<double, 3>& a) {
    return RgbInput(a[0], a[1], a[2]);
}

// Shared parameters (material_parameters.cpp).

/// A colour: a number, [r, g, b], or {"spectrum": [[nm, reflectance], ...]}.
ColorInput readColor(const JsonReader& r, const std::string& key, double defaultValue);
/// `roughness`, `alpha`, or `alpha_x` and `alpha_y` (with `anisotropy` for the first two).
void readRoughness(const JsonReader& r, double defaultRoughness, MicrofacetParams& m);
/// `g2` and, with `allowSampling`, `sampling`.
void readMicrofacetSwitches(const JsonReader& r, MicrofacetParams& m, bool allowSampling);
/// `fresnel`; "auto" only with `allowAuto`.
FresnelChoice readFresnel(const JsonReader& r, FresnelChoice defaultValue, bool allowAuto);
/// An n, k or index file named by `key`, relative to the JSON file's directory (else to the
/// working directory).
std::shared_ptr<const IorSpectrum> loadIorAt(const JsonReader& r, const std::string& key);
/// `ior` (a number, a named glass or a dispersion formula) or `ior_file`: the RGB-mode index
/// and, unless a plain number, the spectrum (dielectric_reader.cpp).
std::pair<double, std::shared_ptr<const IorSpectrum>> readDielectricIor(const JsonReader& r);
/// `thin_film`: {"thickness_nm": ..., "ior": ...}, or nullopt without the key.
std::optional<ThinFilmParams> readThinFilm(const JsonReader& r);
/// What `lamina info` lists of a film (with the spectral data): "thin film 380 nm of index 1.33".
void describeThinFilm(const std::optional<ThinFilmParams>& film, std::vector<std::string>& out);
/// "a, b, c" for a message.
std::string knownNames(const std::vector<std::string>& names);

/// One of `table`'s names or "none" (nullopt); a message lists both.
template <typename E, std::size_t N>
std::optional<E> choiceOrNone(const JsonReader& r, const std::string& key,
                              std::optional<E> defaultValue, const NameTable<E, N>& table) {
    std::vector<std::string> names = table.names();
    names.emplace_back("none");
    r.noteNames(key, std::move(names));
    if (!r.has(key)) return defaultValue;
    const std::string s = r.string(key, "");
    if (s == "none") return std::nullopt;
    if (const auto e = table.find(s)) return e;
    r.failAt(key, "expected one of " + table.list() + ", none, got \"" + s + "\"");
}

struct StandardMaterial;
struct ConductorMaterial;

/// Fills in the tables a material's energy options need (called once, when it is parsed).
void prepareEnergyTables(StandardMaterial& s);   // standard_reader.cpp
void prepareEnergyTables(ConductorMaterial& c);  // conductor_reader.cpp

// One reader per material family; each reads the keys of one JSON object.

MaterialModel readStandard(const JsonReader& r);                     // standard_reader.cpp
MaterialModel readLayered(const JsonReader& r);                      // standard_reader.cpp
MaterialModel readConductor(const JsonReader& r);                    // conductor_reader.cpp
MaterialModel readDielectric(const JsonReader& r);                   // dielectric_reader.cpp
MaterialModel readDiffuse(const JsonReader& r, DiffuseModel model);  // lobe_readers.cpp
MaterialModel readPhong(const JsonReader& r);                        // lobe_readers.cpp
MaterialModel readCoated(const JsonReader& r);                       // coated_reader.cpp
MaterialModel readDiffuseTransmission(const JsonReader& r);          // lobe_readers.cpp
MaterialModel readThinDielectric(const JsonReader& r);               // dielectric_reader.cpp

/// readDiffuse for one model, for the table of material types.
template <DiffuseModel Model>
MaterialModel readDiffuseModel(const JsonReader& r) {
    return readDiffuse(r, Model);
}

}  // namespace lamina
