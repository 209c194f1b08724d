#include "lamina/experiments/fresnel.h"
#include "lamina/experiments/kept_renders.h"
#include "lamina/experiments/noise_floor.h"

#include <algorithm>
#include <cmath>

#include "lamina/bsdf/fresnel.h"
#include "lamina/core/error.h"
#include "lamina/core/hash.h"
#include "lamina/core/thin_film.h"
#include "lamina/spectral/color_difference.h"
#include "lamina/spectral/color_space.h"
#include "lamina/spectral/fringe_colors.h"
#include "lamina/spectral/ior_spectrum.h"
#include "lamina/spectral/rgb_to_spectrum.h"

namespace lamina::experiments {

namespace {

/// A film on the materials: thickness (0: none) and index.
struct Film {
    double nm = 0, ior = 1.33;
};

/// The exact reflectance of an interface from air at one wavelength, with the film's Airy sum
/// (core/thin_film.h) when there is one.
double exactReflectance(const IorSpectrum& ior, double nm, double cosTheta, const Film& film) {
    const double k = ior.k(nm);
    if (film.nm > 0) {
        const FresnelAmplitudes<double> a = thinFilmAmplitudes(
            cosTheta, FilmStack<double>{1.0, film.ior, {ior.n(nm), k}}, film.nm / nm);
        return 0.5 * (std::norm(a.rs) + std::norm(a.rp));
    }
    if (k > 0) return fresnelConductor(cosTheta, ior.n(nm), k);
    return fresnelDielectric(cosTheta, ior.n(nm));
}

/// RGB mode's filmed Fresnel model of the material (material_builder.h: a conductor's n, k at
/// each channel's centre wavelength, a dielectric's index at the d-line).
Fresnel<Rgb<double>> rgbFilmModel(const IorSpectrum& ior, bool conductor, const Film& film) {
    Rgb<double> eta, k;
    for (int c = 0; c < 3; ++c) {
        const double nm = conductor ? FringeColors::rec709().meanWavelength(c) : kDLineNm;
        eta[c] = ior.n(nm);
        k[c] = conductor ? ior.k(nm) : 0.0;
    }
    Fresnel<Rgb<double>> f =
        conductor ? Fresnel<Rgb<double>>::conductor(eta, k) : Fresnel<Rgb<double>>::dielectric(eta);
    ThinFilm<Rgb<double>> t;
    t.thicknessNm = film.nm;
    t.ior = film.ior;
    for (int c = 0; c < 3; ++c)
        t.wavelengthsNm[c] = FringeColors::rec709().meanWavelength(c);
    f.film = t;
    return f;
}

bool isConductor(const IorSpectrum& ior) {
    for (double nm = 380; nm <= 780; nm += 10)
        if (ior.k(nm) > 0) return true;
    return false;
}

IorSpectrum loadMaterial(const std::string& name) {
    if (auto ior = namedIor(name)) return *ior;
    if (std::filesystem::exists(name)) return loadIorFile(name);
    std::string known;
    for (const auto& m : namedMetalNames())
        known += m + " ";
    for (const auto& g : namedGlassNames())
        known += g + " ";
    throw InputError("unknown material \"" + name + "\": expected a metal or glass name (" + known +
                     ") or an n/k file (YAML or CSV)");
}

double cosOf(int degrees) {
    return degrees == 90 ? 0.0 : std::cos(double(degrees) * kPi<double> / 180.0);
}

WavelengthCurve exactCurve(const IorSpectrum& ior, double nm, const Film& film) {
    WavelengthCurve c{nm, {}};
    for (int a = 0; a < kFresnelAngles; ++a)
        c.reflectance.push_back(exactReflectance(ior, nm, cosOf(a), film));
    return c;
}

FresnelMaterial analyse(const std::string& materialName, const Film& film) {
    const IorSpectrum ior = loadMaterial(materialName);
    const bool conductor = isConductor(ior);
    FresnelMaterial result;
    result.stem = std::filesystem::path(materialName).stem().string();
    result.name = ior.name();

    FresnelModel exact{"exact (spectral)", {}};
    for (int a = 0; a < kFresnelAngles; ++a) {
        const double c = cosOf(a);
        exact.rgb.push_back(
            reflectanceColor([&](double nm) { return exactReflectance(ior, nm, c, film); }));
    }
    // The approximations' F0 and F82 are the bare material's (with a film they show what RGB
    // mode would give without it).
    const Rgb<double> f0 =
        reflectanceColor([&](double nm) { return exactReflectance(ior, nm, 1.0, {}); });
    const Rgb<double> f82 =
        reflectanceColor([&](double nm) { return exactReflectance(ior, nm, kF82Cosine, {}); });
    const double f90Shadowed = std::min(1.0, luminance(f0) / 0.04);
    struct Named {
        std::string name;
        Fresnel<Rgb<double>> fresnel;
    };
    std::vector<Named> rgbModels = {
        {"Schlick", Fresnel<Rgb<double>>::schlick(f0)},
        {"Schlick, shadowed F90",
         Fresnel<Rgb<double>>::schlickShadowed(f0, Rgb<double>(f90Shadowed))},
        {"Hoffman F82", Fresnel<Rgb<double>>::hoffmanF82(f0, f82)},
        {"Lagarde spherical Gaussian", Fresnel<Rgb<double>>::schlickSphericalGaussian(f0)},
    };
    if (!conductor)
        rgbModels.push_back({"exact at the d-line index",
                             Fresnel<Rgb<double>>::dielectric(Rgb<double>(ior.n(kDLineNm)))});
    if (film.nm > 0)
        rgbModels = {{"thin film, Belcour-Barla (RGB mode)", rgbFilmModel(ior, conductor, film)},
                     {"Hoffman F82 without the film", Fresnel<Rgb<double>>::hoffmanF82(f0, f82)}};
    result.models.push_back(exact);
    for (const Named& n : rgbModels) {
        FresnelModel m{n.name, {}};
        for (int a = 0; a < kFresnelAngles; ++a)
            m.rgb.push_back(n.fresnel.evaluate(cosOf(a)));
        for (int a = 0; a < kFresnelAngles - 1; ++a) {  // 90 degrees: all models give 1
            for (int ch = 0; ch < 3; ++ch) {
                const double e =
                    std::abs(m.rgb[std::size_t(a)][ch] - exact.rgb[std::size_t(a)][ch]);
                m.maxError = std::max(m.maxError, e);
                m.meanError += e / (3.0 * (kFresnelAngles - 1));
            }
            const double de = ciede2000Rec709(m.rgb[std::size_t(a)], exact.rgb[std::size_t(a)]);
            m.maxDeltaE = std::max(m.maxDeltaE, de);
            m.meanDeltaE += de / (kFresnelAngles - 1);
        }
        result.models.push_back(std::move(m));
    }
    for (int nm = 380; nm <= 780; nm += 20)
        result.spectral.push_back(exactCurve(ior, nm, film));
    for (double nm : {450.0, 550.0, 650.0})
        result.plotted.push_back(exactCurve(ior, nm, film));
    return result;
}

double mean(const std::vector<float>& values) {
    double sum = 0;
    for (const float v : values)
        sum += v;
    return values.empty() ? 0 : sum / double(values.size());
}

FresnelSceneComparison compareModes(const FresnelInputs& in) {
    const render::SceneDesc scene = render::loadScene(in.scene);
    render::RenderOptions o = in.overrides;
    requireSeedDependentSampler(o.sampler.value_or(scene.settings.sampler), in.scene);
    if (in.spp > 0) o.spp = in.spp;
    KeptRenders kept(in.keepDirectory, in.resume);
    return keepingOnInterrupt(kept, [&] {
        const auto renderIn = [&](render::RenderModeKind mode, const std::string& name,
                                  const std::string& what) {
            o.mode = mode;
            return kept.render(name, scene, o, in.progress, in.scene + " in " + what);
        };
        FresnelSceneComparison c;
        c.scene = in.scene;
        c.rgb = renderIn(render::RenderModeKind::Rgb, "scene_rgb", "RGB mode");
        c.spectral = renderIn(render::RenderModeKind::Spectral, "scene_spectral", "spectral mode");
        // Both modes again with another seed: the second pair gives the noise of the modes'
        // difference (noise_floor.h, pairedNoise).
        o.seed = hashValues({o.seed.value_or(scene.settings.seed), 0x666c6f6f72});
        const render::RenderResult rgb2 = renderIn(render::RenderModeKind::Rgb, "scene_rgb_seed2",
                                                   "RGB mode with another seed (the noise floor)");
        const render::RenderResult spectral2 =
            renderIn(render::RenderModeKind::Spectral, "scene_spectral_seed2",
                     "spectral mode with another seed (the noise floor)");
        const render::RgbImage a = filmImage(*c.rgb.film), b = filmImage(*c.spectral.film);
        const render::RgbImage a2 = filmImage(*rgb2.film), b2 = filmImage(*spectral2.film);
        c.metrics = compareImages(a, b);
        c.ciede2000 = ciede2000Map(a, b);
        c.meanDeltaE = mean(c.ciede2000);
        c.maxDeltaE = c.ciede2000.empty()
                          ? 0
                          : double(*std::max_element(c.ciede2000.begin(), c.ciede2000.end()));
        c.p95DeltaE = percentileOf(c.ciede2000, 95);
        const NoiseOnlyPair noise = pairedNoise(a, b, a2, b2);
        const std::vector<float> floor = ciede2000Map(noise.a, noise.b);
        c.floorMeanDeltaE = mean(floor);
        c.floorP95DeltaE = percentileOf(floor, 95);
        const std::vector<float> otherSeed = ciede2000Map(a2, b2);
        c.otherSeedMeanDeltaE = mean(otherSeed);
        c.otherSeedP95DeltaE = percentileOf(otherSeed, 95);
        return c;
    });
}

}  // namespace

FresnelResult runFresnel(const FresnelInputs& in) {
    FresnelResult result;
    result.thinFilmNm = in.thinFilmNm;
    result.thinFilmIor = in.thinFilmIor;
    for (const std::string& m : in.materials)
        result.materials.push_back(analyse(m, Film{in.thinFilmNm, in.thinFilmIor}));
    if (!in.scene.empty()) result.scene = compareModes(in);
    return result;
}

}  // namespace lamina::experiments
