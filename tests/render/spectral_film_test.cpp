// The spectral film (`render --spectral-film N`, spectral_film.h) against closed forms: an
// emitter with a known spectrum filling the view puts its mean over each bin into that bin
// (path tracing, and light tracing through the splat layer); the bins integrated against the
// CIE matching functions give back the image; asking for them changes no bit of the image; the
// rgb mode refuses them.
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/core/error.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/color_space.h"
#include "render_helpers.h"

namespace lamina::render {
namespace {

using testing::sceneFromText;

/// The lamp's spectral radiance: a list linearly interpolated (per nm, docs/scene-format.md).
const std::vector<std::pair<double, double>> kLamp = {
    {360, 0.2}, {500, 1.4}, {600, 0.6}, {830, 1.0}};

double lampAt(double nm) {
    for (std::size_t i = 1; i < kLamp.size(); ++i)
        if (nm <= kLamp[i].first) {
            const auto [a, fa] = kLamp[i - 1];
            const auto [b, fb] = kLamp[i];
            return fa + (fb - fa) * (nm - a) / (b - a);
        }
    return kLamp.back().second;
}

/// The mean of f over [a, b] (midpoint rule on 0.001 nm steps: f is piecewise linear, so the
/// error is below 1e-8 of its values).
template <typename F>
double meanOver(F&& f, double a, double b) {
    const int n = int(std::ceil((b - a) / 0.001));
    const double h = (b - a) / n;
    double sum = 0;
    for (int i = 0; i < n; ++i)
        sum += f(a + (i + 0.5) * h);
    return sum / n;
}

/// A camera whose 5-degree view the lamp fills.
std::string lampScene() {
    std::string spectrum;
    for (const auto& [nm, v] : kLamp)
        spectrum += (spectrum.empty() ? "" : ", ") + std::string("[") + std::to_string(nm) + ", " +
                    std::to_string(v) + "]";
    return R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 5},
      "film": {"resolution": [16, 16]},
      "materials": {"lamp": {"type": "lambert", "reflectance": 0}},
      "shapes": [{"type": "rectangle", "material": "lamp",
                  "emission": {"radiance": {"spectrum": [)" +
           spectrum + R"(]}}}]})";
}

/// Bin b's mean over the image, and its standard error from the spread of the pixels (each an
/// independent estimate).
testing::ImageMean binMean(const Film& film, int component, int bin) {
    const SpectralFilm& s = *film.spectralFilm();
    std::vector<double> v(s.valuesPerPixel());
    double sum = 0, sq = 0;
    const double n = double(film.width()) * film.height();
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            film.spectralMean(x, y, v.data());
            const double b =
                v[std::size_t(component) * std::size_t(s.bins().count) + std::size_t(bin)];
            sum += b;
            sq += b * b;
        }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sq / n - mean * mean) / (n - 1))};
}

// Every bin holds the lamp's mean spectral radiance over the bin, with the path integrator
// (camera samples, 256 per pixel) and the light integrator (splats, 1024 iterations). Each
// bin's mean over the 256 pixels is checked with a z-test at a family-wise significance of
// 0.001 over the 16 bins (Bonferroni: |z| < 4.0 each), and its standard error is held below 1%
// for the path integrator, so that the test tells a bin's mean from its neighbours' (they
// differ by 3 to 20%). Light tracing's splats land on random pixels, and the bins at the ends
// of the range get few wavelengths: its bound is 5%, still far below what a wrong weight
// (a factor of 4 wavelengths, or of the bin's width) would show.
TEST(SpectralFilm, ALampFillsEveryBinWithItsMeanOverTheBin) {
    const SceneDesc scene = sceneFromText(lampScene());
    for (const IntegratorKind integrator : {IntegratorKind::Path, IntegratorKind::Light}) {
        RenderOptions o;
        o.mode = RenderModeKind::Spectral;
        o.integrator = integrator;
        const bool path = integrator == IntegratorKind::Path;
        o.spp = path ? 256 : 1024;
        o.seed = 3;
        o.spectralBins = 16;
        const RenderResult r = renderScene(scene, o);
        const SpectralFilm* s = r.film->spectralFilm();
        ASSERT_NE(s, nullptr);
        ASSERT_EQ(s->components(), 1);
        const SpectralBins& bins = s->bins();
        EXPECT_DOUBLE_EQ(bins.width(), 470.0 / 16);
        for (int b = 0; b < bins.count; ++b) {
            const double expected = meanOver(lampAt, bins.start(b), bins.start(b + 1));
            const testing::ImageMean m = binMean(*r.film, 0, b);
            const std::string at = std::string(kIntegratorNames.name(integrator)) + ", bin " +
                                   std::to_string(b) + " at " + std::to_string(bins.centre(b)) +
                                   " nm";
            EXPECT_LT(std::abs(m.mean - expected), 4.0 * m.standardError + 1e-9 * expected)
                << at << ": mean " << m.mean << " se " << m.standardError << ", expected "
                << expected;
            EXPECT_LT(m.standardError, (path ? 0.01 : 0.05) * expected) << at;
        }
    }
}

/// The bins integrated against the CIE 1931 curves: XYZ = sum_b value_b x integral over bin b
/// of (x-bar, y-bar, z-bar) / integral of y-bar (the film's normalisation).
Vec3d binsToXyz(const SpectralFilm& s, const double* bins) {
    Vec3d xyz(0.0);
    for (int b = 0; b < s.bins().count; ++b) {
        const double a = s.bins().start(b), w = s.bins().width();
        Vec3d cmf(0.0);
        for (int i = 0; i < 200; ++i)
            cmf += cieXyz(a + (i + 0.5) * w / 200) * (w / 200);
        xyz += bins[b] * cmf;
    }
    return xyz / cieYIntegral();
}

// The Cornell box in spectral mode with 1 nm bins: the bins integrated back through the CIE
// curves are the image. Both estimate the same integral from the same samples; they differ
// only in that a sample weighs the curves' mean over its bin where the image takes the curves
// at its own wavelength, and the curves are linear within a nanometre (5 nm knots), so a
// sample's two values differ by the curves' slope times less than half a nanometre, with
// either sign. Checked: each of X, Y, Z to 2% at every pixel brighter (in Y) than a tenth of
// the brightest (the lamp's edge, seen by few samples, differs most: 1.0% in Z), and the
// image's mean in each channel of linear Rec.709 to 0.1%.
TEST(SpectralFilm, TheBinsIntegratedThroughTheCieCurvesAreTheImage) {
    const SceneDesc scene = loadScene(testing::sharedCornellBox());
    RenderOptions o;
    o.mode = RenderModeKind::Spectral;
    o.spp = 16;
    o.seed = 5;
    o.resolution = std::pair{24, 24};
    o.spectralBins = 470;
    const RenderResult r = renderScene(scene, o);
    const Film& film = *r.film;
    const SpectralFilm& s = *film.spectralFilm();
    const RgbColorSpace& rec709 = RgbColorSpace::rec709();
    std::vector<double> bins(s.valuesPerPixel());
    Vec3d imageSum(0.0), binSum(0.0);
    double brightest = 0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x)
            brightest = std::max(brightest, luminance(film.pixel(x, y)));
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            film.spectralMean(x, y, bins.data());
            const Vec3d fromBins = binsToXyz(s, bins.data());
            const Rgb<double> rgb = film.pixel(x, y);
            const Vec3d image = rec709.rgbToXyz() * Vec3d(rgb[0], rgb[1], rgb[2]);
            imageSum += rec709.toRgb(image);
            binSum += rec709.toRgb(fromBins);
            if (image.y < 0.1 * brightest) continue;
            for (int c = 0; c < 3; ++c)
                EXPECT_LT(std::abs(fromBins[c] - image[c]), 0.02 * image[c])
                    << "pixel " << x << "," << y << ": "
                    << "XYZ"[c] << " " << fromBins[c] << " from the bins, " << image[c];
        }
    for (int c = 0; c < 3; ++c)
        EXPECT_LT(std::abs(binSum[c] - imageSum[c]), 0.001 * imageSum[c])
            << "channel " << c << ": " << binSum[c] << " from the bins, " << imageSum[c];
}

// Asking for the spectral film adds layers and changes nothing else: the image, its variance
// and the Stokes layers are the same bits, in every integrator (path, light, bdpt) and both
// modes that take it.
TEST(SpectralFilm, TheImageIsTheSameBitsWithAndWithoutIt) {
    const SceneDesc scene = loadScene(testing::sharedCornellBox());
    for (const RenderModeKind mode : {RenderModeKind::Spectral, RenderModeKind::Polarised})
        for (const IntegratorKind integrator :
             {IntegratorKind::Path, IntegratorKind::Light, IntegratorKind::Bdpt}) {
            RenderOptions o;
            o.mode = mode;
            o.integrator = integrator;
            o.spp = 2;
            o.threads = 1;  // splats from several threads add in varying orders
            o.resolution = std::pair{12, 12};
            const RenderResult plain = renderScene(scene, o);
            o.spectralBins = 5;
            const RenderResult binned = renderScene(scene, o);
            for (int y = 0; y < 12; ++y)
                for (int x = 0; x < 12; ++x) {
                    for (int c = 0; c < 3; ++c) {
                        ASSERT_EQ(plain.film->pixel(x, y)[c], binned.film->pixel(x, y)[c]);
                        ASSERT_EQ(plain.film->varianceOfMeanRgb(x, y)[c],
                                  binned.film->varianceOfMeanRgb(x, y)[c]);
                    }
                    if (mode != RenderModeKind::Polarised) continue;
                    for (std::size_t i = 0; i < 4; ++i)
                        for (int c = 0; c < 3; ++c)
                            ASSERT_EQ(plain.film->stokes(x, y)[i][c],
                                      binned.film->stokes(x, y)[i][c]);
                }
        }
}

TEST(SpectralFilm, TheRgbModeRefusesIt) {
    RenderOptions o;
    o.spp = 1;
    o.spectralBins = 8;
    try {
        renderScene(sceneFromText(lampScene()), o);
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("--spectral-film: the rgb mode"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace lamina::render
