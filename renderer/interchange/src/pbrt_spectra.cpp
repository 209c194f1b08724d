// pbrt-v4's spectra in lamina terms: illuminants (pbrt-v4 lights.cpp and util/spectrum.cpp),
// conductor eta and k (materials.cpp, ConductorMaterial), dielectric indices and the named
// spectra of util/spectrum.cpp (metal-*-eta/k, glass-*, stdillum-*).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "lamina/core/error.h"
#include "lamina/core/input_file.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/emission_spectrum.h"
#include "lamina/spectral/rgb_to_spectrum.h"
#include "pbrt_translation.h"

namespace lamina::render::pbrt {

namespace {

// pbrt-v4's metals that lamina has as named metals (measured tables, spectral/data/nk).
const std::set<std::string> kLaminaMetals = {"Ag", "Al", "Au", "Cu"};

// pbrt-v4's standard illuminants that lamina reads from colord-data by the same name.
const std::set<std::string> kLaminaIlluminants = {
    "A", "D50", "D65", "F1", "F2", "F3", "F4", "F5", "F6", "F7", "F8", "F9", "F10", "F11", "F12"};

struct Sellmeier {
    const char* pbrtName;
    const char* glass;
    double b[3], c[3];  // c in um^2
};

// pbrt-v4 tabulates these glasses (util/spectrum.cpp: GlassBAF10_eta, ...; "glass-F5" etc. are
// Schott's SF5, SF10, SF11); lamina uses the three-term Sellmeier formulas of the SCHOTT
// optical glass catalogue (via refractiveindex.info, n^2 = 1 + sum B l^2 / (l^2 - C)).
const Sellmeier kSellmeierGlasses[] = {
    {"glass-BAF10",
     "N-BAF10",
     {1.5851495, 0.143559385, 1.08521269},
     {0.00926681282, 0.0424489805, 105.613573}},
    {"glass-FK51A",
     "N-FK51A",
     {0.971247817, 0.216901417, 0.904651666},
     {0.00472301995, 0.0153575612, 168.68133}},
    {"glass-LASF9",
     "N-LASF9",
     {2.00029547, 0.298926886, 1.80691843},
     {0.0121426017, 0.0538736236, 156.530829}},
    {"glass-F5",
     "SF5",
     {1.52481889, 0.187085527, 1.42729015},
     {0.011254756, 0.0588995392, 129.141675}},
    {"glass-F10",
     "SF10",
     {1.62153902, 0.256287842, 1.64447552},
     {0.0122241457, 0.0595736775, 147.468793}},
    {"glass-F11",
     "SF11",
     {1.73759695, 0.313747346, 1.89878101},
     {0.013188707, 0.0623068142, 155.23629}},
};

// A spectrum file of pbrt-v4 (util/spectrum.cpp, PiecewiseLinearSpectrum::Read): numbers in
// (nm, value) pairs, '#' comments.
std::vector<double> readSpectrumFile(const std::filesystem::path& path, const Location& at) {
    std::istringstream in(readInputFile(path, kMaxTextFileBytes));
    std::vector<double> values;
    std::string line;
    while (std::getline(in, line)) {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::string word;
        while (words >> word) {
            char* end = nullptr;
            const double v = std::strtod(word.c_str(), &end);
            if (end != word.c_str() + word.size() || !std::isfinite(v))
                throw InputError(at.str() + ": spectrum file " + path.string() + ": \"" + word +
                                 "\" is not a number");
            values.push_back(v);
        }
    }
    if (values.size() < 4 || values.size() % 2 != 0)
        throw InputError(at.str() + ": spectrum file " + path.string() +
                         ": expected (nm, value) pairs, at least two");
    return values;
}

// The (nm, value) pairs of a numeric or file spectrum parameter, wavelengths increasing.
std::vector<double> spectrumPairs(TranslationContext& ctx, const ParamList& params,
                                  const Param& p) {
    std::vector<double> v = p.numbers;
    if (!p.strings.empty()) {
        if (p.strings.size() != 1) params.fail(p, "expected one named spectrum or file");
        std::filesystem::path file(p.strings[0]);
        if (file.is_relative()) file = ctx.scene.directory / file;
        if (!notARegularFile(file).empty())
            params.fail(p, "names neither a spectrum lamina knows nor a readable file (" +
                               notARegularFile(file) + ")");
        v = readSpectrumFile(file, p.location);
    }
    if (v.size() < 4 || v.size() % 2 != 0)
        params.fail(p, "expected (wavelength, value) pairs, at least two");
    for (std::size_t i = 2; i < v.size(); i += 2)
        if (!(v[i] > v[i - 2])) params.fail(p, "the wavelengths must increase");
    return v;
}

Json pairsJson(const std::vector<double>& v, double divisor) {
    Json list = Json::array();
    for (std::size_t i = 0; i + 1 < v.size(); i += 2)
        list.push_back({v[i], v[i + 1] / divisor});
    return list;
}

std::string namedMetal(const Param* p, const std::string& suffix) {
    if (!p || p->strings.size() != 1) return "";
    const std::string& s = p->strings[0];
    if (s.rfind("metal-", 0) != 0 || s.size() <= 6 + suffix.size() ||
        s.compare(s.size() - suffix.size(), suffix.size(), suffix) != 0)
        return "";
    return s.substr(6, s.size() - 6 - suffix.size());
}

}  // namespace

Json numericSpectrum(TranslationContext& ctx, const ParamList& params, const Param& p,
                     double divisor) {
    const std::string type = canonicalParamType(p.type);
    if (type == "float") {
        if (p.numbers.size() != 1) params.fail(p, "expected one number");
        return p.numbers[0] / divisor;
    }
    if (type == "rgb") {
        if (p.numbers.size() != 3) params.fail(p, "expected three numbers");
        return Json::array(
            {p.numbers[0] / divisor, p.numbers[1] / divisor, p.numbers[2] / divisor});
    }
    if (type == "spectrum") return pairsJson(spectrumPairs(ctx, params, p), divisor);
    params.expectType(p, {"float", "rgb", "spectrum"});
    return nullptr;
}

Json emissionValue(TranslationContext& ctx, const ParamList& params, const std::string& name,
                   double scale) {
    const Param* p = params.find(name);
    // Without a spectrum pbrt-v4 emits its colour space's illuminant (D65 for sRGB) at one
    // nit, which is lamina's grey emission.
    if (!p) return scale;
    params.expectType(*p, {"rgb", "blackbody", "spectrum"});
    const std::string type = canonicalParamType(p->type);
    if (type == "rgb") {
        // An RGBIlluminantSpectrum: the colour times the colour space's illuminant, whose
        // luminance pbrt divides out (SpectrumToPhotometric takes only the illuminant): a
        // white (1, 1, 1) light is D65 at one nit, lamina's [1, 1, 1].
        if (p->numbers.size() != 3) params.fail(*p, "expected three numbers");
        for (double v : p->numbers)
            if (v < 0) params.fail(*p, "has a negative component");
        return Json::array({p->numbers[0] * scale, p->numbers[1] * scale, p->numbers[2] * scale});
    }
    if (type == "blackbody") {
        // pbrt-v4's BlackbodySpectrum, normalised to luminance 1 like lamina's black body.
        if (p->numbers.size() != 1) params.fail(*p, "expected one temperature in kelvin");
        return Json{{"blackbody", p->numbers[0]}, {"scale", scale}};
    }
    if (p->strings.size() == 1 && p->strings[0].rfind("stdillum-", 0) == 0) {
        const std::string illuminant = p->strings[0].substr(9);
        if (!kLaminaIlluminants.count(illuminant))
            params.fail(*p, "\"" + p->strings[0] + "\" has no lamina equivalent (lamina knows " +
                                "stdillum-A, D50, D65 and F1 to F12)");
        return Json{{"illuminant", illuminant}, {"scale", scale}};
    }
    std::vector<double> pairs = spectrumPairs(ctx, params, *p);
    // pbrt-v4's PiecewiseLinearSpectrum is 0 outside its wavelengths; lamina's list keeps its
    // end values there, so the list is closed with zeros over lamina's range.
    constexpr double kStep = 1e-3;  // nm
    if (pairs.front() > kLambdaMin) {
        std::vector<double> head{kLambdaMin, 0.0};
        if (pairs.front() - kStep > kLambdaMin)
            head.insert(head.end(), {pairs.front() - kStep, 0.0});
        pairs.insert(pairs.begin(), head.begin(), head.end());
    }
    if (pairs[pairs.size() - 2] < kLambdaMax) {
        if (pairs[pairs.size() - 2] + kStep < kLambdaMax)
            pairs.insert(pairs.end(), {pairs[pairs.size() - 2] + kStep, 0.0});
        pairs.insert(pairs.end(), {kLambdaMax, 0.0});
    }
    std::vector<double> nm, values;
    for (std::size_t i = 0; i + 1 < pairs.size(); i += 2) {
        nm.push_back(pairs[i]);
        values.push_back(pairs[i + 1]);
        if (pairs[i + 1] < 0) params.fail(*p, "has a negative value");
    }
    // pbrt divides a light's spectrum by its luminance (scale /= SpectrumToPhotometric): the
    // light emits `scale` nits whatever the spectrum's magnitude. lamina takes a list as it
    // is, so the translation divides by the list's luminance as lamina computes it.
    const EmissionSpectrum curve = EmissionSpectrum::tabulated(nm, values, 1.0, p->location.str());
    const double y =
        integrateAgainstCmf([&](double lambda) { return curve(lambda); }).y / cieYIntegral();
    if (!(y > 0)) params.fail(*p, "has no luminance in 360-830 nm");
    return Json{{"spectrum", pairsJson(pairs, 1.0)}, {"scale", scale / y}};
}

void conductorOptics(TranslationContext& ctx, const Entity& e, const std::string& prefix,
                     double outsideIor, Json& material) {
    const ParamList& params = e.params;
    const Param* eta = params.find(prefix + "eta");
    const Param* k = params.find(prefix + "k");
    const Param* reflectance = params.find("reflectance");
    for (const Param* p : {eta, k, reflectance})
        if (p && canonicalParamType(p->type) == "texture")
            params.fail(*p,
                        "as a texture is not supported (lamina's conductor optics are "
                        "constants)");
    if (reflectance) {
        if (eta || k)
            params.fail(*reflectance, "cannot be combined with eta and k (pbrt-v4 refuses it too)");
        // pbrt-v4 (materials.h, ConductorMaterial::GetBxDF): eta = 1 and
        // k = 2 sqrt(r) / sqrt(1 - r), r clamped to [0, 0.9999]: normal-incidence Fresnel
        // reflectance r.
        auto kOf = [](double r) {
            r = std::clamp(r, 0.0, 0.9999);
            return 2 * std::sqrt(r) / std::sqrt(1 - r);
        };
        const std::string type = canonicalParamType(reflectance->type);
        Json kJson;
        const std::vector<double>& r = reflectance->numbers;
        if (type == "rgb" && r.size() == 3 && !(r[0] == r[1] && r[1] == r[2])) {
            // pbrt-v4 upsamples a coloured r as a reflectance (an albedo spectrum) and takes k
            // of it at each wavelength; k of the upsampled r, tabulated every 5 nm, is the same
            // metal (an rgb k triple would be upsampled as an unbounded spectrum instead).
            const RgbSpectrum spectrum(Rgb<double>(r[0], r[1], r[2]), RgbSpectrumKind::Reflectance);
            kJson = Json::array();
            for (double nm = kLambdaMin; nm <= kLambdaMax; nm += 5)
                kJson.push_back({nm, kOf(spectrum(nm)) / outsideIor});
        } else if (type == "float" || type == "rgb") {
            const std::size_t n = type == "rgb" ? 3 : 1;
            if (r.size() != n)
                params.fail(*reflectance, "expected " + std::to_string(n) + " numbers");
            kJson = Json::array();
            for (double v : r)
                kJson.push_back(kOf(v) / outsideIor);
            if (n == 1) kJson = kJson[0];
        } else if (type == "spectrum") {
            const auto pairs = spectrumPairs(ctx, params, *reflectance);
            kJson = Json::array();
            for (std::size_t i = 0; i + 1 < pairs.size(); i += 2)
                kJson.push_back({pairs[i], kOf(pairs[i + 1]) / outsideIor});
        } else {
            params.expectType(*reflectance, {"float", "rgb", "spectrum"});
        }
        material["eta"] = 1.0 / outsideIor;
        material["k"] = kJson;
        return;
    }
    // pbrt-v4's default conductor is copper (metal-Cu-eta, metal-Cu-k).
    const std::string etaMetal = eta ? namedMetal(eta, "-eta") : "Cu";
    const std::string kMetal = k ? namedMetal(k, "-k") : "Cu";
    if (!etaMetal.empty() || !kMetal.empty()) {
        const Param* named = !etaMetal.empty() && eta ? eta : k;
        if (etaMetal != kMetal) {
            const Param& p = eta ? *eta : *k;
            params.fail(p,
                        "and the other of eta and k must name the same metal-* spectra "
                        "(lamina has measured eta and k only together)");
        }
        if (!kLaminaMetals.count(etaMetal)) {
            const Param& p = named ? *named : *eta;
            params.fail(p, "\"metal-" + etaMetal +
                               "\" has no lamina equivalent (lamina knows "
                               "metal-Ag, Al, Au and Cu)");
        }
        material["material"] = etaMetal;
        ctx.warn(e.location, "metal-" + etaMetal + "-eta/k became lamina's conductor \"" +
                                 etaMetal + "\": lamina's measured table, not pbrt-v4's " +
                                 "(colours may differ slightly)");
        if (outsideIor != 1)
            ctx.warn(e.location, "metal-" + etaMetal + " under a coat of index " +
                                     std::to_string(outsideIor) +
                                     ": lamina uses the metal's eta and k as given, pbrt-v4 "
                                     "divides them by the coat's index");
        return;
    }
    if (!eta || !k)
        params.fail(eta ? *eta : *k, "needs both eta and k (or metal-* spectra for both)");
    // rgb eta and k are kept as triples without a warning: lamina's spectral mode upsamples
    // them as pbrt-v4 does (unbounded spectra, spectrum_context.h). Dividing the triple by
    // the coat's index divides that spectrum by it, as pbrt-v4 divides its spectrum.
    material["eta"] = numericSpectrum(ctx, params, *eta, outsideIor);
    material["k"] = numericSpectrum(ctx, params, *k, outsideIor);
}

Json dielectricIor(TranslationContext& ctx, const ParamList& params, const std::string& name,
                   const Location& at) {
    const Param* p = params.find(name);
    if (!p) return 1.5;  // pbrt-v4's default eta
    params.expectType(*p, {"float", "spectrum"});
    if (canonicalParamType(p->type) == "float") {
        if (p->numbers.size() != 1) params.fail(*p, "expected one number");
        return p->numbers[0];
    }
    if (p->strings.size() == 1) {
        const std::string& s = p->strings[0];
        if (s == "glass-BK7") {
            ctx.warn(at,
                     "glass-BK7 became lamina's \"bk7\" (the Sellmeier formula of SCHOTT "
                     "N-BK7, pbrt-v4 tabulates it)");
            return "bk7";
        }
        for (const Sellmeier& g : kSellmeierGlasses)
            if (s == g.pbrtName) {
                ctx.warn(at, s + " became the Sellmeier formula of SCHOTT " + g.glass +
                                 " (pbrt-v4 tabulates it)");
                return Json{{"sellmeier",
                             {{"b", {g.b[0], g.b[1], g.b[2]}}, {"c", {g.c[0], g.c[1], g.c[2]}}}}};
            }
    }
    const std::vector<double> pairs = spectrumPairs(ctx, params, *p);
    for (std::size_t i = 3; i < pairs.size(); i += 2)
        if (pairs[i] != pairs[1])
            params.fail(*p,
                        "a tabulated, wavelength-dependent eta is not supported (give a "
                        "float or a named glass-* spectrum)");
    return pairs[1];
}

}  // namespace lamina::render::pbrt
