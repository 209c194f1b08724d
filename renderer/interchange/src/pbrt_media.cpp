// pbrt-v4's MakeNamedMedium -> the lamina document's `media` (docs/interchange.md, "Media").
// Homogeneous media translate exactly (pbrt-v4's HomogeneousMedium: sigma_a and sigma_s,
// `scale` on both, Henyey-Greenstein `g`, emission `Le` times `Lescale`); grid, cloud and
// NanoVDB media in pbrt_grid_media.cpp.
#include <array>
#include <cmath>

#include "document_names.h"
#include "pbrt_translation.h"

namespace lamina::render::pbrt {

namespace {

// pbrt-v4's named media ("string preset"): reduced scattering sigma'_s and absorption sigma_a
// in RGB, in mm^-1, which pbrt-v4 uses as they are, per scene unit (media.cpp,
// GetMediumScatteringProperties). Measured by Jensen, Marschner, Levoy and Hanrahan, "A
// Practical Model for Subsurface Light Transport", SIGGRAPH 2001, table 2 (the first twelve),
// and by Narasimhan, Gupta, Donner, Ramamoorthi, Nayar and Jensen, "Acquiring Scattering
// Properties of Participating Media by Dilution", SIGGRAPH 2006, table 1 (the others).
struct MeasuredMedium {
    const char* name;
    std::array<double, 3> sigmaPrimeS, sigmaA;
};
constexpr MeasuredMedium kMeasuredMedia[] = {
    {"Apple", {2.29, 2.39, 1.97}, {0.0030, 0.0034, 0.046}},
    {"Chicken1", {0.15, 0.21, 0.38}, {0.015, 0.077, 0.19}},
    {"Chicken2", {0.19, 0.25, 0.32}, {0.018, 0.088, 0.20}},
    {"Cream", {7.38, 5.47, 3.15}, {0.0002, 0.0028, 0.0163}},
    {"Ketchup", {0.18, 0.07, 0.03}, {0.061, 0.97, 1.45}},
    {"Marble", {2.19, 2.62, 3.00}, {0.0021, 0.0041, 0.0071}},
    {"Potato", {0.68, 0.70, 0.55}, {0.0024, 0.0090, 0.12}},
    {"Skimmilk", {0.70, 1.22, 1.90}, {0.0014, 0.0025, 0.0142}},
    {"Skin1", {0.74, 0.88, 1.01}, {0.032, 0.17, 0.48}},
    {"Skin2", {1.09, 1.59, 1.79}, {0.013, 0.070, 0.145}},
    {"Spectralon", {11.6, 20.4, 14.9}, {0.00, 0.00, 0.00}},
    {"Wholemilk", {2.55, 3.21, 3.77}, {0.0011, 0.0024, 0.014}},
    {"Lowfat Milk", {0.89187, 1.5136, 2.532}, {0.002875, 0.00575, 0.0115}},
    {"Reduced Milk", {2.4858, 3.1669, 4.5214}, {0.0025556, 0.0051111, 0.012778}},
    {"Regular Milk", {4.5513, 5.8294, 7.136}, {0.0015333, 0.0046, 0.019933}},
    {"Espresso", {0.72378, 0.84557, 1.0247}, {4.7984, 6.5751, 8.8493}},
    {"Mint Mocha Coffee", {0.31602, 0.38538, 0.48131}, {3.772, 5.8228, 7.82}},
    {"Lowfat Soy Milk", {0.30576, 0.34233, 0.61664}, {0.0014375, 0.0071875, 0.035937}},
    {"Regular Soy Milk", {0.59223, 0.73866, 1.4693}, {0.0019167, 0.0095833, 0.065167}},
    {"Lowfat Chocolate Milk", {0.64925, 0.83916, 1.1057}, {0.0115, 0.0368, 0.1564}},
    {"Regular Chocolate Milk", {1.4585, 2.1289, 2.9527}, {0.010063, 0.043125, 0.14375}},
    {"Coke", {8.9053e-05, 8.372e-05, 0}, {0.10014, 0.16503, 0.2468}},
    {"Pepsi", {6.1697e-05, 4.2564e-05, 0}, {0.091641, 0.14158, 0.20729}},
    {"Sprite", {6.0306e-06, 6.4139e-06, 6.5504e-06}, {0.001886, 0.0018308, 0.0020025}},
    {"Gatorade", {0.0024574, 0.003007, 0.0037325}, {0.024794, 0.019289, 0.008878}},
    {"Chardonnay", {1.7982e-05, 1.3758e-05, 1.2023e-05}, {0.010782, 0.011855, 0.023997}},
    {"White Zinfandel", {1.7501e-05, 1.9069e-05, 1.288e-05}, {0.012072, 0.016184, 0.019843}},
    {"Merlot", {2.1129e-05, 0, 0}, {0.11632, 0.25191, 0.29434}},
    {"Budweiser Beer", {2.4356e-05, 2.4079e-05, 1.0564e-05}, {0.011492, 0.024911, 0.057786}},
    {"Coors Light Beer", {5.0922e-05, 4.301e-05, 0}, {0.006164, 0.013984, 0.034983}},
    {"Clorox", {0.0024035, 0.0031373, 0.003991}, {0.0033542, 0.014892, 0.026297}},
    {"Apple Juice", {0.00013612, 0.00015836, 0.000227}, {0.012957, 0.023741, 0.052184}},
    {"Cranberry Juice", {0.00010402, 0.00011646, 7.8139e-05}, {0.039437, 0.094223, 0.12426}},
    {"Grape Juice", {5.382e-05, 0, 0}, {0.10404, 0.23958, 0.29325}},
    {"Ruby Grapefruit Juice", {0.011002, 0.010927, 0.011036}, {0.085867, 0.18314, 0.25262}},
    {"White Grapefruit Juice", {0.22826, 0.23998, 0.32748}, {0.0138, 0.018831, 0.056781}},
    {"Shampoo", {0.0007176, 0.0008303, 0.0009016}, {0.014107, 0.045693, 0.061717}},
    {"Strawberry Shampoo", {0.00015671, 0.00015947, 1.518e-05}, {0.01449, 0.05796, 0.075823}},
    {"Head & Shoulders Shampoo", {0.023805, 0.028804, 0.034306}, {0.084621, 0.15688, 0.20365}},
    {"Lemon Tea Powder", {0.040224, 0.045264, 0.051081}, {2.4288, 4.5757, 7.2127}},
    {"Orange Powder", {0.00015617, 0.00017482, 0.0001762}, {0.001449, 0.003441, 0.007863}},
    {"Pink Lemonade Powder", {0.00012103, 0.00013073, 0.00012528}, {0.001165, 0.002366, 0.003195}},
    {"Cappuccino Powder", {1.8436, 2.5851, 2.1662}, {35.844, 49.547, 61.084}},
    {"Salt Powder", {0.027333, 0.032451, 0.031979}, {0.28415, 0.3257, 0.34148}},
    {"Sugar Powder", {0.00022272, 0.00025513, 0.000271}, {0.012638, 0.031051, 0.050124}},
    {"Suisse Mocha Powder", {2.7979, 3.5452, 4.3365}, {17.502, 27.004, 35.433}},
    {"Pacific Ocean Surface Water",
     {0.0001764, 0.00032095, 0.00019617},
     {0.031845, 0.031324, 0.030147}},
};

Json triple(const std::array<double, 3>& v) {
    return Json::array({v[0], v[1], v[2]});
}

}  // namespace

std::optional<std::pair<Json, Json>> measuredMediumCoefficients(const std::string& name) {
    for (const MeasuredMedium& mm : kMeasuredMedia)
        if (name == mm.name) return std::pair{triple(mm.sigmaA), triple(mm.sigmaPrimeS)};
    return std::nullopt;
}

// A scattering coefficient: a float, an rgb triple (both as lamina reads them: spectral mode
// upsamples an rgb coefficient as an unbounded spectrum, as pbrt-v4 does) or spectrum pairs of
// one value (a constant). Pairs that vary are refused: lamina's media take RGB coefficients.
Json mediumCoefficient(TranslationContext& ctx, const ParamList& params, const std::string& name) {
    const Param* p = params.find(name);
    if (!p) return 1.0;  // pbrt-v4's default for both coefficients
    Json v = numericSpectrum(ctx, params, *p, 1.0);
    if (v.is_array() && !v.empty() && v[0].is_array()) {
        const double first = v[0][1].get<double>();
        for (const Json& pair : v)
            if (pair[1].get<double>() != first)
                params.fail(*p,
                            "varies with wavelength: lamina's media take a number or an rgb "
                            "triple (give \"rgb " +
                                name + "\")");
        v = first;
    }
    const auto check = [&](double c) {
        if (!(c >= 0) || !std::isfinite(c)) params.fail(*p, "must be finite and >= 0");
    };
    if (v.is_array())
        for (const Json& c : v)
            check(c.get<double>());
    else
        check(v.get<double>());
    return v;
}

void mediumScaleAndPhase(const ParamList& params, Json& medium) {
    const double scale = params.number("scale", 1.0);
    if (!(scale >= 0) || !std::isfinite(scale))
        params.fail(*params.find("scale"), "must be finite and >= 0");
    medium["scale"] = scale;
    mediumPhase(params, medium);
}

void mediumPhase(const ParamList& params, Json& medium) {
    const double g = params.number("g", 0.0);
    if (!(std::abs(g) < 1))
        params.fail(*params.find("g"),
                    "must lie in (-1, 1): lamina's Henyey-Greenstein phase function has no "
                    "delta limit");
    medium["g"] = g;
}

namespace {

Json translateMedium(TranslationContext& ctx, const MediumDef& m) {
    const Entity& e = m.entity;
    const ParamList& params = e.params;
    if (e.type != "homogeneous") return translateGridMedium(ctx, m);
    Json medium{{"type", "homogeneous"}};
    const std::string preset = params.string("preset", "");
    const auto measured = measuredMediumCoefficients(preset);
    if (!preset.empty() && !measured)
        // pbrt-v4 warns and falls back to sigma_a and sigma_s; so does lamina.
        ctx.warn(e.location, "MakeNamedMedium \"" + m.name + "\": no preset \"" + preset +
                                 "\" (pbrt-v4's names, e.g. \"Wholemilk\"): sigma_a and sigma_s "
                                 "are used instead");
    if (measured) {
        medium["sigma_a"] = measured->first;
        medium["sigma_s"] = measured->second;
        for (const char* ignored : {"sigma_a", "sigma_s"})
            if (params.find(ignored))
                ctx.warn(e.location, std::string("MakeNamedMedium \"") + m.name + "\": \"" +
                                         ignored +
                                         "\" ignored: the preset sets it (as in pbrt-v4)");
    } else {
        medium["sigma_a"] = mediumCoefficient(ctx, params, "sigma_a");
        medium["sigma_s"] = mediumCoefficient(ctx, params, "sigma_s");
    }
    mediumScaleAndPhase(params, medium);
    const double leScale = params.number("Lescale", 1.0);
    if (const Param* le = params.find("Le")) {
        // An illuminant spectrum normalised to one nit and times Lescale, as pbrt-v4
        // normalises a medium's Le (and its lights).
        const bool zero = canonicalParamType(le->type) == "rgb" && le->numbers.size() == 3 &&
                          le->numbers[0] == 0 && le->numbers[1] == 0 && le->numbers[2] == 0;
        if (!zero && leScale > 0) medium["Le"] = emissionValue(ctx, params, "Le", leScale);
    }
    params.refuseUnused();
    return medium;
}

}  // namespace

std::string useMedium(TranslationContext& ctx, const std::string& name, const Location& usedAt) {
    if (name.empty()) return kDocumentVacuum;
    const MediumDef* def = nullptr;
    for (const MediumDef& m : ctx.scene.media)
        if (m.name == name) def = &m;
    if (!def)
        ctx.fail(usedAt, "MediumInterface: no medium \"" + name +
                             "\" (MakeNamedMedium defines one; \"\" is vacuum)");
    // "vacuum" names no medium in lamina's documents.
    const std::string lamina = name == kDocumentVacuum ? "pbrt_vacuum" : name;
    if (ctx.writtenMedia.insert(name).second)
        ctx.document["media"][lamina] = translateMedium(ctx, *def);
    return lamina;
}

void warnUnusedMedia(TranslationContext& ctx) {
    for (const MediumDef& m : ctx.scene.media)
        if (!ctx.writtenMedia.count(m.name))
            ctx.warn(m.entity.location, "medium \"" + m.name +
                                            "\" bounds no shape and holds no camera: not "
                                            "translated");
}

}  // namespace lamina::render::pbrt
