// `lamina spectrum NAME|FILE`: what a named or loaded spectrum is, and what it becomes in RGB
// mode. NAME is a metal (Au, Ag, ... : n, k from the Lorentz-Drude model), a glass (bk7,
// fused_silica, water, diamond: n), a CIE illuminant (D65, A, ...), or blackbody:T (kelvin);
// FILE is a refractiveindex.info YAML or CSV n/k file.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <sstream>

#include "json_lines.h"
#include "lamina/core/error.h"
#include "lamina/core/output_files.h"
#include "lamina/experiments/figure_drawing.h"
#include "lamina/experiments/figure_spec.h"
#include "lamina/spectral/blackbody.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/color_space.h"
#include "lamina/spectral/ior_spectrum.h"
#include "lamina/spectral/rgb_to_spectrum.h"

namespace lamina::app {

namespace {

struct SpectrumArgs {
    std::string name;
    std::string wavelengths;
    bool rgb = false;
    std::string plot;
};

// One or two curves over wavelength, with labels and what their values are (with units).
struct Curves {
    std::string title;
    std::vector<std::string> labels;
    std::vector<std::function<double(double)>> f;
    std::string yLabel;
};

constexpr const char* kIorLabel = "refractive index n, extinction coefficient k (dimensionless)";

Curves resolve(const std::string& name) {
    // Before the file test: "blackbody:6500.5" holds a '.' but names no file.
    if (name.rfind("blackbody:", 0) == 0) {
        const std::string value = name.substr(10);
        char* end = nullptr;
        const double t = std::strtod(value.c_str(), &end);
        if (value.empty() || *end != '\0' || !(t > 0) || !std::isfinite(t))
            throw InputError(name + ": \"" + value +
                             "\" is not a temperature in kelvin (e.g. blackbody:6500)");
        return {name + " K (normalised to 1 at its peak)",
                {"value"},
                {[t](double nm) { return blackbodyNormalized(nm, t); }},
                "spectral radiance / its peak (dimensionless)"};
    }
    if (auto ior = namedIor(name);
        !ior && (name.find('.') != std::string::npos || name.find('/') != std::string::npos)) {
        auto loaded = std::make_shared<IorSpectrum>(loadIorFile(name));
        return {loaded->name(),
                {"n", "k"},
                {[loaded](double nm) { return loaded->n(nm); },
                 [loaded](double nm) { return loaded->k(nm); }},
                kIorLabel};
    } else if (ior) {
        auto s = std::make_shared<IorSpectrum>(*ior);
        return {s->name(),
                {"n", "k"},
                {[s](double nm) { return s->n(nm); }, [s](double nm) { return s->k(nm); }},
                kIorLabel};
    }
    if (const TabulatedCurve* c = findCieIlluminant(name))
        return {"CIE illuminant " + name,
                {"value"},
                {[c](double nm) { return (*c)(nm); }},
                "relative spectral power (dimensionless)"};
    std::string names;
    for (const auto& n : namedMetalNames())
        names += n + " ";
    for (const auto& n : namedGlassNames())
        names += n + " ";
    for (const auto& n : cieIlluminantNames())
        names += n + " ";
    throw InputError("unknown spectrum \"" + name +
                     "\"; expected an n/k file (.yml, .csv), "
                     "blackbody:T, or one of: " +
                     names);
}

// --plot NAME.png: a figure of the figure module (NAME.png and NAME.pdf, its data beside).
void checkPlotFile(const std::string& plot) {
    if (plot.empty()) return;
    const std::filesystem::path p(plot);
    if (p.extension() != ".png")
        throw CLI::ValidationError("--plot",
                                   "expected a .png file name (the figure is drawn as "
                                   "NAME.png and NAME.pdf), got \"" +
                                       plot + "\"");
    for (const char* suffix : {".png", ".pdf", ".figure.json"})
        checkOutputFile(std::filesystem::path(p).replace_extension(suffix));
}

// The curves over 360-830 nm in 1 nm steps, as a figure (figure_spec.h).
void writePlot(const std::filesystem::path& path, const Curves& c) {
    experiments::LineFigure plot;
    plot.title = c.title;
    plot.xLabel = "wavelength (nm)";
    plot.yLabel = c.yLabel;
    plot.xScale = experiments::AxisScale::Linear;
    experiments::LinePanel panel;
    for (std::size_t i = 0; i < c.f.size(); ++i) {
        experiments::LineSeries s;
        s.name = c.labels[i];
        for (double nm = kLambdaMin; nm <= kLambdaMax; nm += 1) {
            s.x.push_back(nm);
            s.y.push_back(c.f[i](nm));
        }
        panel.series.push_back(std::move(s));
    }
    plot.panels.push_back(std::move(panel));
    const std::filesystem::path directory =
        path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    const std::string stem = path.stem().string();
    experiments::writeFigureSpec(directory, stem, plot);
    const std::string note = experiments::drawFigures(directory / (stem + ".figure.json"));
    if (!note.empty()) std::fprintf(stderr, "lamina: note: %s\n", note.c_str());
    std::fprintf(stderr, "%s: %s over %g-%g nm\n", path.c_str(), c.title.c_str(), kLambdaMin,
                 kLambdaMax);
}

void run(const SpectrumArgs& a) {
    checkPlotFile(a.plot);
    const Curves c = resolve(a.name);
    std::vector<double> nm;
    if (a.wavelengths.empty()) {
        for (double l = kLambdaMin; l <= kLambdaMax; l += 10)
            nm.push_back(l);
    } else {
        std::stringstream s(a.wavelengths);
        for (std::string item; std::getline(s, item, ',');) {
            char* end = nullptr;
            const double v = std::strtod(item.c_str(), &end);
            if (item.empty() || *end != '\0' || !(v > 0))
                throw CLI::ValidationError("--wavelengths", "expected positive numbers in nm");
            nm.push_back(v);
        }
    }
    // Every line is a JSON object: the first names the spectrum, one per wavelength follows,
    // and with --rgb the RGB-mode reduction last.
    std::printf("{\"spectrum\":%s}\n", jsonString(c.title).c_str());
    for (double l : nm) {
        std::printf("{\"nm\":%s", jsonNumber(l).c_str());
        for (std::size_t i = 0; i < c.f.size(); ++i)
            std::printf(",%s:%s", jsonString(c.labels[i]).c_str(),
                        jsonNumber(c.f[i](l), 6).c_str());
        std::printf("}\n");
    }
    if (a.rgb) {
        if (c.f.size() == 2) {
            const auto ior = namedIor(a.name);
            const IorSpectrum s = ior ? *ior : loadIorFile(a.name);
            if (s.k(550) > 0.5) {
                const auto [f0, f82] = conductorF0F82(s);
                std::printf("{\"rgb_mode\":\"conductor\",\"f0\":%s,\"f82\":%s}\n",
                            jsonArray(f0, 3, 6).c_str(), jsonArray(f82, 3, 6).c_str());
            } else {
                std::printf("{\"rgb_mode\":\"dielectric\",\"ior\":%s,\"at_nm\":%s}\n",
                            jsonNumber(s.n(kDLineNm), 6).c_str(), jsonNumber(kDLineNm).c_str());
            }
        } else {
            // An emission spectrum's colour, scaled so that its luminance Y is 1.
            // A spectrum with no visible emission (blackbody:1) has no colour: black, said so.
            const Vec3d xyz = integrateAgainstCmf([&](double l) { return c.f[0](l); });
            const bool visible = xyz.y > 0 && std::isfinite(xyz.y);
            const Vec3d rgb = visible ? RgbColorSpace::rec709().toRgb(xyz / xyz.y) : Vec3d(0);
            std::printf("{\"rgb_mode\":\"emission\",\"rgb\":%s,\"note\":\"%s\"}\n",
                        jsonVec(rgb, 6).c_str(), visible ? "Y = 1" : "no visible emission");
        }
    }
    if (!a.plot.empty()) writePlot(a.plot, c);
}

}  // namespace

void registerSpectrumCommand(CLI::App& app) {
    auto a = std::make_shared<SpectrumArgs>();
    CLI::App* cmd = app.add_subcommand(
        "spectrum", "Print (and plot) a named or loaded spectrum and its RGB-mode reduction");
    cmd->add_option("name", a->name,
                    "A metal (Au, Ag, Cu, Al, ...), glass (bk7, fused_silica, water, diamond), "
                    "CIE illuminant (D65, A, ...), blackbody:T, or an n/k file")
        ->required();
    cmd->add_option("--wavelengths", a->wavelengths,
                    "Comma-separated wavelengths in nm (default 360 to 830 every 10 nm)");
    cmd->add_flag("--rgb", a->rgb,
                  "Also print what RGB mode uses: F0/F82 (metals), the d-line ior (glasses), "
                  "the colour (illuminants)");
    cmd->add_option("--plot", a->plot, "Draw the curve(s) as NAME.png (and NAME.pdf)");
    cmd->callback([a] { run(*a); });
}

}  // namespace lamina::app
