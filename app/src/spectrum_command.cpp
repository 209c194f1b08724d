// `lamina spectrum NAME|FILE`: what a named or loaded spectrum is, and what it becomes in RGB
// mode. NAME is a metal (Au, Ag, ... : n, k from the Lorentz-Drude model), a glass (bk7,
// fused_silica, water, diamond: n), a CIE illuminant (D65, A, ...), or blackbody:T (kelvin);
// FILE is a refractiveindex.info YAML or CSV n/k file.
#include <OpenImageIO/imageio.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <sstream>

#include "json_lines.h"
#include "lamina/core/error.h"
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

// One or two curves over wavelength, with labels.
struct Curves {
    std::string title;
    std::vector<std::string> labels;
    std::vector<std::function<double(double)>> f;
};

Curves resolve(const std::string& name) {
    // Before the file test: "blackbody:6500.5" holds a '.' but names no file.
    if (name.rfind("blackbody:", 0) == 0) {
        const std::string value = name.substr(10);
        char* end = nullptr;
        const double t = std::strtod(value.c_str(), &end);
        if (value.empty() || *end != '\0' || !(t > 0) || !std::isfinite(t))
            throw InputError(name + ": \"" + value +
                             "\" is not a temperature in kelvin (e.g. blackbody:6500)");
        return {name + " K (normalised to 1 at its peak)", {"value"}, {[t](double nm) {
                    return blackbodyNormalized(nm, t);
                }}};
    }
    if (auto ior = namedIor(name);
        !ior && (name.find('.') != std::string::npos || name.find('/') != std::string::npos)) {
        auto loaded = std::make_shared<IorSpectrum>(loadIorFile(name));
        return {loaded->name(),
                {"n", "k"},
                {[loaded](double nm) { return loaded->n(nm); },
                 [loaded](double nm) { return loaded->k(nm); }}};
    } else if (ior) {
        auto s = std::make_shared<IorSpectrum>(*ior);
        return {s->name(),
                {"n", "k"},
                {[s](double nm) { return s->n(nm); }, [s](double nm) { return s->k(nm); }}};
    }
    if (const TabulatedCurve* c = findCieIlluminant(name))
        return {"CIE illuminant " + name, {"value"}, {[c](double nm) { return (*c)(nm); }}};
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

void writePlot(const std::string& path, const Curves& c) {
    constexpr int w = 640, h = 400, margin = 40;
    std::vector<float> img(std::size_t(w) * h * 3, 1.0f);
    auto put = [&](int x, int y, const float* col) {
        if (x < 0 || y < 0 || x >= w || y >= h) return;
        float* p = &img[(std::size_t(y) * w + std::size_t(x)) * 3];
        for (int k = 0; k < 3; ++k)
            p[k] = col[k];
    };
    const float grey[3] = {0.6f, 0.6f, 0.6f};
    const float colours[2][3] = {{0.8f, 0.1f, 0.1f}, {0.1f, 0.3f, 0.85f}};
    double top = 0;
    for (const auto& f : c.f)
        for (double nm = kLambdaMin; nm <= kLambdaMax; nm += 1)
            top = std::max(top, f(nm));
    top = top > 0 ? top * 1.05 : 1.0;
    for (int x = margin; x < w - margin; ++x) {
        put(x, h - margin, grey);
        put(x, margin, grey);
    }
    for (int y = margin; y <= h - margin; ++y) {
        put(margin, y, grey);
        put(w - margin, y, grey);
    }
    for (int tick = 400; tick <= 800; tick += 100) {  // wavelength ticks every 100 nm
        const int x =
            margin + int((tick - kLambdaMin) / (kLambdaMax - kLambdaMin) * (w - 2 * margin));
        for (int y = h - margin; y < h - margin + 6; ++y)
            put(x, y, grey);
    }
    for (std::size_t i = 0; i < c.f.size(); ++i)
        for (int x = margin; x < w - margin; ++x) {
            const double nm =
                kLambdaMin + (x - margin) / double(w - 2 * margin) * (kLambdaMax - kLambdaMin);
            const int y = h - margin - int(c.f[i](nm) / top * (h - 2 * margin));
            put(x, y, colours[i % 2]);
            put(x, y + 1, colours[i % 2]);
        }
    auto out = OIIO::ImageOutput::create(path);
    if (!out) throw InputError(path + ": cannot write this image format (use .png)");
    OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, img.data()) ||
        !out->close())
        throw InputError(path + ": cannot write: " + out->geterror());
    std::fprintf(
        stderr, "%s: %s over 360-830 nm (ticks every 100 nm from 400), y from 0 to %.4g; %s\n",
        path.c_str(), c.title.c_str(), top, c.f.size() == 2 ? "n red, k blue" : "value red");
}

void run(const SpectrumArgs& a) {
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
    cmd->add_option("--plot", a->plot, "Write a PNG plot of the curve(s)");
    cmd->callback([a] { run(*a); });
}

}  // namespace lamina::app
