// Parameters several material types share: colours, roughness, the microfacet switches, the
// Fresnel model and files of optical constants (docs/bsdf.md, "Materials").
#include <cmath>
#include <filesystem>

#include "material_readers.h"

namespace lamina {

// A colour: a number, [r, g, b], or {"spectrum": [[nm, reflectance], ...]} (a measured
// reflectance; RGB mode uses its colour under D65).
ColorInput readColor(const JsonReader& r, const std::string& key, double defaultValue) {
    if (!r.has(key) || !r.value()[key].is_object())
        return toRgb(r.triple(key, {defaultValue, defaultValue, defaultValue}, Range::unit()));
    const JsonReader c = r.child(key);
    const JsonReader list = c.child("spectrum");
    auto [nm, values] = list.wavelengthTable(Range::unit());
    c.finish();
    ColorInput out;
    out.spectrum = std::make_shared<const std::function<double(double)>>(
        tabulatedCurve(std::move(nm), std::move(values), r.source().name + ": " + list.path()));
    out.rgb = reflectanceColor(*out.spectrum);
    return out;
}

// Roughness in one of three forms: perceptual `roughness` (alpha = roughness^2), `alpha`, or
// `alpha_x` and `alpha_y`; `anisotropy` in [0, 1) stretches the first two along the tangent
// (Kulla and Conty 2017, "Revisiting Physically Based Shading at Imageworks", slide 20:
// aspect = sqrt(1 - 0.9 anisotropy), alpha_x = alpha / aspect, alpha_y = alpha aspect).
void readRoughness(const JsonReader& r, double defaultRoughness, MicrofacetParams& m) {
    const int forms =
        int(r.has("roughness")) + int(r.has("alpha")) + int(r.has("alpha_x") || r.has("alpha_y"));
    if (forms > 1) r.fail("give only one of roughness, alpha, or alpha_x and alpha_y");
    if (r.has("alpha_x") || r.has("alpha_y")) {
        m.alphaX = r.requiredNumber("alpha_x", Range::unit());
        m.alphaY = r.requiredNumber("alpha_y", Range::unit());
        if (r.has("anisotropy")) r.failAt("anisotropy", "not allowed with alpha_x and alpha_y");
        return;
    }
    double alpha = sqr(defaultRoughness);
    if (r.has("alpha")) alpha = r.requiredNumber("alpha", Range::unit());
    if (r.has("roughness")) alpha = sqr(r.requiredNumber("roughness", Range::unit()));
    const double anisotropy = r.number("anisotropy", 0.0, {0.0, 0.99});
    const double aspect = std::sqrt(1.0 - 0.9 * anisotropy);
    m.alphaX = std::min(1.0, alpha / aspect);
    m.alphaY = alpha * aspect;
}

double MicrofacetParams::perceptualRoughness() const {
    return std::sqrt(0.5 * (alphaX + alphaY));
}

void readMicrofacetSwitches(const JsonReader& r, MicrofacetParams& m, bool allowSampling) {
    m.g2 = r.choice("g2", G2Form::HeightCorrelated, kG2FormNames);
    if (!allowSampling) return;
    m.sampling = r.choice("sampling", MicrofacetSampling::VisibleNormals, kMicrofacetSamplingNames);
    if (m.sampling == MicrofacetSampling::SphericalCaps && m.ndf != NdfKind::Ggx)
        r.failAt("sampling", "\"caps\" (Dupuy and Benyoub 2023) is defined for GGX only");
}

FresnelChoice readFresnel(const JsonReader& r, FresnelChoice defaultValue, bool allowAuto) {
    // What `standard` and `layered` take: every choice but the conductor's "auto".
    static constexpr auto kWithoutAuto = kFresnelChoiceNames.subset(std::array{
        FresnelChoice::Schlick, FresnelChoice::SchlickShadowed,
        FresnelChoice::SchlickSphericalGaussian, FresnelChoice::F82, FresnelChoice::Exact});
    return allowAuto ? r.choice("fresnel", defaultValue, kFresnelChoiceNames)
                     : r.choice("fresnel", defaultValue, kWithoutAuto);
}

std::optional<ThinFilmParams> readThinFilm(const JsonReader& r) {
    if (!r.has("thin_film")) return std::nullopt;
    const JsonReader f = r.child("thin_film");
    ThinFilmParams film;
    film.thicknessNm = f.requiredNumber("thickness_nm", {0.0, ThinFilmParams::kMaxThicknessNm});
    // A film less dense than the medium above it could be evanescent at grazing angles; lamina
    // films are coatings of index >= 1 under air (or glass).
    film.ior = f.number("ior", film.ior, {1.0, ThinFilmParams::kMaxIor});
    f.finish();
    return film;
}

void describeThinFilm(const std::optional<ThinFilmParams>& film, std::vector<std::string>& out) {
    if (film)
        out.push_back("thin film " + formatNumber(film->thicknessNm) + " nm of index " +
                      formatNumber(film->ior) +
                      " (spectral: Airy sum per wavelength; RGB: Belcour-Barla closed form)");
}

std::string knownNames(const std::vector<std::string>& names) {
    std::string list;
    for (const auto& n : names)
        list += (list.empty() ? "" : ", ") + n;
    return list;
}

std::shared_ptr<const IorSpectrum> loadIorAt(const JsonReader& r, const std::string& key) {
    const std::filesystem::path path = r.filePath(key);
    try {
        return std::make_shared<const IorSpectrum>(loadIorFile(path));
    } catch (const InputError& e) {
        r.failAt(key, e.what());
    }
}

}  // namespace lamina
