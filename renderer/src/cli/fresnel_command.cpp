// `lamina fresnel MATERIAL... -o DIR`: how far RGB mode's Fresnel models are from the exact
// spectral Fresnel reflectance of measured conductors and dispersive dielectrics.
//
// For each material, at every angle from 0 to 89 degrees (and 90, where all are 1):
//  - exact: the Fresnel equations per wavelength (complex index n + ik; 380-780 nm), and its
//    colour under D65 in linear Rec.709 (what a spectral render of a white-lit flat surface
//    shows);
//  - RGB models, built from that exact colour the way RGB mode builds them: Schlick from F0
//    (F90 = 1), Schlick with shadowed F90 = min(1, luminance(F0) / 0.04), Hoffman's F82 (F0
//    and the exact colour at cos = 1/7), Lagarde's spherical-Gaussian Schlick, and for
//    dielectrics the exact equations at the d-line index (RGB mode's dielectric).
// Reported per model: the maximum and mean absolute error of the RGB reflectance and the
// maximum and mean CIEDE2000 difference of its colour (as a reflectance under D65). Written:
// MATERIAL.csv (the RGB curves), MATERIAL_spectral.csv (one column per 20 nm),
// MATERIAL.svg (luminance against angle), MATERIAL_swatches.png (rows: exact, models; columns:
// 0, 30, 60, 75, 82, 87 degrees), summary.md. With --scene, renders the scene in both modes
// and writes the difference and a CIEDE2000 map.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "lamina/bsdf/fresnel.h"
#include "lamina/cli/svg_plot.h"
#include "lamina/core/error.h"
#include "lamina/render/image_metrics.h"
#include "lamina/render/image_output.h"
#include "lamina/render/renderer.h"
#include "lamina/spectral/color_difference.h"
#include "lamina/spectral/color_space.h"
#include "lamina/spectral/ior_spectrum.h"
#include "lamina/spectral/rgb_to_spectrum.h"

namespace lamina::cli {

namespace {

struct FresnelArgs {
    std::vector<std::string> materials;
    std::string output;
    std::string scene;
    int spp = 0;
};

constexpr int kAngles = 91;  // 0, 1, ..., 90 degrees

/// The exact reflectance of an interface from air at one wavelength.
double exactReflectance(const IorSpectrum& ior, double nm, double cosTheta) {
    const double k = ior.k(nm);
    if (k > 0) return fresnelConductor(cosTheta, ior.n(nm), k);
    return fresnelDielectric(cosTheta, ior.n(nm));
}

bool isConductor(const IorSpectrum& ior) {
    for (double nm = 380; nm <= 780; nm += 10)
        if (ior.k(nm) > 0) return true;
    return false;
}

struct Model {
    std::string name;
    std::vector<Rgb<double>> rgb;  // per angle
    double maxError = 0, meanError = 0, maxDeltaE = 0, meanDeltaE = 0;
};

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

std::string table(const std::string& material, const std::vector<Model>& models) {
    std::ostringstream md;
    md << "### " << material << "\n\n"
       << "| model | max abs error | mean abs error | max CIEDE2000 | mean CIEDE2000 |\n"
       << "|---|---|---|---|---|\n";
    char line[256];
    for (std::size_t i = 1; i < models.size(); ++i) {
        const Model& m = models[i];
        std::snprintf(line, sizeof line, "| %s | %.4f | %.4f | %.2f | %.2f |\n", m.name.c_str(),
                      m.maxError, m.meanError, m.maxDeltaE, m.meanDeltaE);
        md << line;
    }
    md << "\n![" << material << " reflectance](" << material << ".svg)\n\n![" << material
       << " swatches](" << material << "_swatches.png)\n\n";
    return md.str();
}

std::string analyse(const std::string& materialName, const std::filesystem::path& dir) {
    const IorSpectrum ior = loadMaterial(materialName);
    const std::string stem = std::filesystem::path(materialName).stem().string();
    const bool conductor = isConductor(ior);

    std::vector<Model> models;
    Model exact{"exact (spectral)", {}};
    for (int a = 0; a < kAngles; ++a) {
        const double c = cosOf(a);
        exact.rgb.push_back(
            reflectanceColor([&](double nm) { return exactReflectance(ior, nm, c); }));
    }
    const Rgb<double> f0 = exact.rgb[0];
    const Rgb<double> f82 =
        reflectanceColor([&](double nm) { return exactReflectance(ior, nm, kF82Cosine); });
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
    models.push_back(exact);
    for (const Named& n : rgbModels) {
        Model m{n.name, {}};
        for (int a = 0; a < kAngles; ++a)
            m.rgb.push_back(n.fresnel.evaluate(cosOf(a)));
        for (int a = 0; a < kAngles - 1; ++a) {  // 90 degrees: all models give 1
            for (int ch = 0; ch < 3; ++ch) {
                const double e =
                    std::abs(m.rgb[std::size_t(a)][ch] - exact.rgb[std::size_t(a)][ch]);
                m.maxError = std::max(m.maxError, e);
                m.meanError += e / (3.0 * (kAngles - 1));
            }
            const double de = ciede2000Rec709(m.rgb[std::size_t(a)], exact.rgb[std::size_t(a)]);
            m.maxDeltaE = std::max(m.maxDeltaE, de);
            m.meanDeltaE += de / (kAngles - 1);
        }
        models.push_back(std::move(m));
    }

    // CSVs
    {
        std::ofstream csv(dir / (stem + ".csv"));
        csv << "degrees";
        for (const Model& m : models)
            for (const char* ch : {"R", "G", "B"})
                csv << ",\"" << m.name << " " << ch << "\"";
        csv << "\n";
        for (int a = 0; a < kAngles; ++a) {
            csv << a;
            for (const Model& m : models)
                for (int ch = 0; ch < 3; ++ch)
                    csv << "," << m.rgb[std::size_t(a)][ch];
            csv << "\n";
        }
        std::ofstream spec(dir / (stem + "_spectral.csv"));
        spec << "degrees";
        for (int nm = 380; nm <= 780; nm += 20)
            spec << "," << nm << "nm";
        spec << "\n";
        for (int a = 0; a < kAngles; ++a) {
            spec << a;
            for (int nm = 380; nm <= 780; nm += 20)
                spec << "," << exactReflectance(ior, nm, cosOf(a));
            spec << "\n";
        }
    }
    // Plot: luminance of each model, and the exact curve at three wavelengths.
    SvgPlot plot("Fresnel reflectance: " + ior.name(), "angle of incidence (degrees)",
                 "reflectance (luminance)");
    for (const Model& m : models) {
        SvgPlot::Series s{m.name, {}, {}};
        for (int a = 0; a < kAngles; ++a) {
            s.x.push_back(a);
            s.y.push_back(luminance(m.rgb[std::size_t(a)]));
        }
        plot.add(std::move(s));
    }
    for (double nm : {450.0, 550.0, 650.0}) {
        SvgPlot::Series s{"exact at " + std::to_string(int(nm)) + " nm", {}, {}, true};
        for (int a = 0; a < kAngles; ++a) {
            s.x.push_back(a);
            s.y.push_back(exactReflectance(ior, nm, cosOf(a)));
        }
        plot.add(std::move(s));
    }
    plot.write(dir / (stem + ".svg"));
    // Swatches, sRGB-encoded.
    const int angles[] = {0, 30, 60, 75, 82, 87};
    constexpr int kSwatch = 40;
    const int w = kSwatch * int(std::size(angles)), h = kSwatch * int(models.size());
    std::vector<float> px(std::size_t(w) * h * 3);
    for (std::size_t row = 0; row < models.size(); ++row)
        for (std::size_t col = 0; col < std::size(angles); ++col) {
            const Rgb<double>& c = models[row].rgb[std::size_t(angles[col])];
            for (int y = 0; y < kSwatch; ++y)
                for (int x = 0; x < kSwatch; ++x)
                    for (int ch = 0; ch < 3; ++ch) {
                        const double l = std::clamp(c[ch], 0.0, 1.0);
                        const double e =
                            l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1 / 2.4) - 0.055;
                        px[((std::size_t(row) * kSwatch + std::size_t(y)) * std::size_t(w) +
                            col * kSwatch + std::size_t(x)) *
                               3 +
                           std::size_t(ch)] = float(e);
                    }
        }
    render::writeRgb8(dir / (stem + "_swatches.png"), w, h, px);
    return table(stem, models);
}

std::string compareModes(const std::string& scenePath, int spp, const std::filesystem::path& dir) {
    const render::SceneDesc scene = render::loadScene(scenePath);
    render::RenderOptions o;
    if (spp > 0) o.spp = spp;
    o.mode = render::RenderModeKind::Rgb;
    std::fprintf(stderr, "rendering %s in RGB mode...\n", scenePath.c_str());
    const render::RenderResult rgb = render::renderScene(scene, o);
    o.mode = render::RenderModeKind::Spectral;
    std::fprintf(stderr, "rendering %s in spectral mode...\n", scenePath.c_str());
    const render::RenderResult spectral = render::renderScene(scene, o);
    render::ImageMetadata meta;
    meta.ints["spp"] = rgb.spp;
    render::writeExr(dir / "scene_rgb.exr", *rgb.film, false, meta);
    render::writeExr(dir / "scene_spectral.exr", *spectral.film, false, meta);
    const render::RgbImage a = render::filmImage(*rgb.film), b = render::filmImage(*spectral.film);
    const render::ImageMetrics m = render::compareImages(a, b);
    render::writeDifferenceImage(dir / "scene_difference.png", a, b, m.max);
    std::vector<float> de(std::size_t(a.width) * a.height);
    double sum = 0, worst = 0;
    for (std::size_t i = 0; i < de.size(); ++i) {
        const Rgb<double> ca(a.pixels[3 * i], a.pixels[3 * i + 1], a.pixels[3 * i + 2]);
        const Rgb<double> cb(b.pixels[3 * i], b.pixels[3 * i + 1], b.pixels[3 * i + 2]);
        de[i] = float(ciede2000Rec709(ca, cb));
        sum += de[i];
        worst = std::max(worst, double(de[i]));
    }
    render::writeFloatExr(dir / "scene_ciede2000.exr", a.width, a.height, {"Y"}, de);
    render::writeSignedHeatMap(dir / "scene_ciede2000.png", a.width, a.height, de, 10.0);
    char text[512];
    std::snprintf(text, sizeof text,
                  "### The scene in both modes: %s\n\n%d spp each (path integrator). RGB mode "
                  "against spectral mode: relMSE %.4g, MAE %.4g; CIEDE2000 mean %.2f, max %.2f "
                  "(noise included: both renders are noisy).\n\n"
                  "![CIEDE2000 map, red = 10](scene_ciede2000.png) "
                  "![|RGB - spectral|](scene_difference.png)\n\n",
                  scenePath.c_str(), rgb.spp, m.relmse, m.mae, sum / double(de.size()), worst);
    return text;
}

void run(const FresnelArgs& a) {
    const std::filesystem::path dir = a.output;
    std::filesystem::create_directories(dir);
    std::ostringstream md;
    md << "# Fresnel: exact spectral against RGB models\n\n"
       << "Reflectance of a flat interface from air, 0 to 89 degrees; errors are against the "
          "colour (linear Rec.709, under D65) of the exact spectral reflectance; the RGB models "
          "are built from that colour (F0, and F82 at cos = 1/7) as RGB mode builds them.\n\n";
    for (const std::string& m : a.materials)
        md << analyse(m, dir);
    if (!a.scene.empty()) md << compareModes(a.scene, a.spp, dir);
    std::ofstream(dir / "summary.md") << md.str();
    std::printf("%s", md.str().c_str());
}

}  // namespace

void registerFresnelCommand(CLI::App& app) {
    auto a = std::make_shared<FresnelArgs>();
    CLI::App* cmd = app.add_subcommand(
        "fresnel",
        "Exact spectral Fresnel against the RGB models (Schlick, shadowed F90, F82, spherical "
        "Gaussian): errors, CIEDE2000, curves, swatches; optionally a scene in both modes");
    cmd->add_option("materials", a->materials,
                    "Metals (Au, Ag, Cu, Al, ...), glasses (bk7, diamond, ...) or n/k files")
        ->required();
    cmd->add_option("-o,--output", a->output, "Output directory")->required();
    cmd->add_option("--scene", a->scene, "Also render this scene in both modes and compare")
        ->check(CLI::ExistingFile);
    cmd->add_option("--spp", a->spp, "Samples per pixel of the --scene renders")
        ->check(CLI::Range(1, 1 << 24));
    cmd->callback([a] { run(*a); });
}

}  // namespace lamina::cli
