// The shipped scene scenes/polarisation/two-mirrors.json against its closed forms: two pairs of
// glass mirrors (index 1.5, reflection only) at Brewster's angle seen by an orthographic camera,
// the left pair's planes of incidence crossed, the right pair's parallel, each reflecting a lamp
// of radiance 10. Unpolarised light leaves a crossed pair with Rs Rp of its radiance and a
// parallel pair with (Rs^2 + Rp^2) / 2; the spectral mode, which averages s and p at each
// reflection, gives ((Rs + Rp) / 2)^2 for both (docs/polarisation.md). Rs and Rp come from
// lamina's complex Fresnel amplitudes, computed here apart from the renderer. Each pair's mean
// over the pixels its first mirror fills is checked per channel with a z-test at significance
// 0.001 (|z| < 3.29) against the film's own standard error, plus 1e-9 for the float rounding of
// a value that is 0 (crossed at Brewster's angle: every sample is 0 to within 1e-15).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include "lamina/core/fresnel_amplitudes.h"
#include "lamina/render/renderer.h"
#include "lamina/spectral/ior_spectrum.h"
#include "lamina/spectral/rgb_to_spectrum.h"
#include "render_helpers.h"
#include "source_files.h"

namespace lamina {
namespace {

constexpr double kZ = 3.29;       // two-sided significance 0.001
constexpr double kRadiance = 10;  // the scene's lamps
// Float rounding of a zero: the pair's light cancels in float arithmetic on values of order
// 10 Rs = 1.5, so a few float ulps of that (1.2e-7 each) is what "0" can mean.
constexpr double kRounding = 1e-6;

/// The pixels each pair's first mirror fills entirely (64x12 film; the mirrors' edges, which a
/// pixel's box filter straddles, left out).
struct Block {
    int x0, x1, y0, y1;  ///< inclusive
};
constexpr Block kCrossed{5, 18, 2, 9}, kParallel{45, 58, 2, 9};

struct BlockMean {
    double mean = 0, standardError = 0;
};

BlockMean blockMean(const render::Film& film, const Block& b, int channel) {
    double sum = 0, var = 0, n = 0;
    for (int y = b.y0; y <= b.y1; ++y)
        for (int x = b.x0; x <= b.x1; ++x) {
            sum += film.pixel(x, y)[channel];
            var += film.varianceOfMean(x, y);
            n += 1;
        }
    return {sum / n, std::sqrt(var) / n};
}

void expectBlock(const render::Film& film, const Block& b, double expected, const char* what) {
    for (int c = 0; c < 3; ++c) {
        const BlockMean m = blockMean(film, b, c);
        EXPECT_LT(std::abs(m.mean - expected), kZ * m.standardError + kRounding)
            << what << ", channel " << c << ": mean " << m.mean << " se " << m.standardError
            << ", expected " << expected;
    }
}

render::RenderResult renderShipped(render::RenderModeKind mode,
                                   const char* scene = "scenes/polarisation/two-mirrors.json") {
    render::RenderOptions o;
    o.mode = mode;
    o.spp = 16;
    return render::renderScene(render::loadScene(testing::sourceFile(scene)), o);
}

struct Reflectances {
    double rs, rp;
};

Reflectances atBrewstersAngle() {
    const double theta = std::atan(1.5);
    const auto a = fresnelAmplitudes(std::cos(theta), std::complex<double>(1.5, 0.0));
    return {std::norm(a.rs), std::norm(a.rp)};
}

TEST(TwoMirrorScene, PolarisedModeGivesRsRpCrossedAndTheMeanSquareParallel) {
    const auto [rs, rp] = atBrewstersAngle();
    const auto r = renderShipped(render::RenderModeKind::Polarised);
    expectBlock(*r.film, kCrossed, kRadiance * rs * rp, "polarised, crossed");
    expectBlock(*r.film, kParallel, kRadiance * (rs * rs + rp * rp) / 2, "polarised, parallel");
}

TEST(TwoMirrorScene, SpectralModeGivesTheSquaredMeanForBoth) {
    const auto [rs, rp] = atBrewstersAngle();
    const double unpolarised = kRadiance * (rs + rp) * (rs + rp) / 4;
    const auto r = renderShipped(render::RenderModeKind::Spectral);
    expectBlock(*r.film, kCrossed, unpolarised, "spectral, crossed");
    expectBlock(*r.film, kParallel, unpolarised, "spectral, parallel");
    // The scene tells the modes apart: at Brewster's angle the crossed pair is black in the
    // polarised mode and the parallel pair twice as bright as the spectral mode's.
    EXPECT_GT(unpolarised, 10000 * kRounding);
    EXPECT_NEAR((rs * rs + rp * rp) / 2, 2 * (rs + rp) * (rs + rp) / 4, 1e-12);
}

// scenes/polarisation/gold-mirrors.json: the same pairs of gold mirrors (Au, Johnson and Christy
// 1972) at 70 degrees of incidence, where Rs and Rp depend on the wavelength. Each closed form
// holds per wavelength, so a pair's pixels are the colour of 10 Rs Rp, 10 (Rs^2 + Rp^2) / 2 or
// 10 ((Rs + Rp) / 2)^2 as reflectance spectra under the lamp's white (an RGB white lamp is D65;
// reflectanceColor integrates against the CIE 1931 observer as the film does). The film and that
// integral sample the spectrum differently (hero wavelengths against a 1 nm table), so the
// z-test allows 0.2% of the value besides the film's standard error.
constexpr double kGoldDegrees = 70;
constexpr double kSpectralIntegration = 2e-3;

render::RenderResult renderGold(render::RenderModeKind mode) {
    return renderShipped(mode, "scenes/polarisation/gold-mirrors.json");
}

/// The colour of kRadiance times `f(Rs, Rp)` of gold at kGoldDegrees, per wavelength.
template <typename F>
Rgb<double> goldColour(F f) {
    const IorSpectrum gold = *namedIor("Au");
    const double cosTheta = std::cos(kGoldDegrees * std::numbers::pi / 180);
    return reflectanceColor([&](double nm) {
               const auto a =
                   fresnelAmplitudes(cosTheta, std::complex<double>(gold.n(nm), gold.k(nm)));
               return f(std::norm(a.rs), std::norm(a.rp));
           }) *
           kRadiance;
}

void expectGoldBlock(const render::Film& film, const Block& b, const Rgb<double>& expected,
                     const char* what) {
    for (int c = 0; c < 3; ++c) {
        const BlockMean m = blockMean(film, b, c);
        EXPECT_LT(std::abs(m.mean - expected[c]),
                  kZ * m.standardError + kSpectralIntegration * expected[c])
            << what << ", channel " << c << ": mean " << m.mean << " se " << m.standardError
            << ", expected " << expected[c];
    }
}

TEST(TwoMirrorScene, GoldPairsGiveRsRpCrossedAndTheMeanSquareParallelPerWavelength) {
    const Rgb<double> crossed = goldColour([](double rs, double rp) { return rs * rp; });
    const Rgb<double> parallel =
        goldColour([](double rs, double rp) { return (rs * rs + rp * rp) / 2; });
    const auto r = renderGold(render::RenderModeKind::Polarised);
    expectGoldBlock(*r.film, kCrossed, crossed, "polarised, crossed");
    expectGoldBlock(*r.film, kParallel, parallel, "polarised, parallel");
    // The pairs differ by more than the tolerances: 4% in the green channel.
    EXPECT_GT(parallel[1] - crossed[1], 0.03 * parallel[1]);
}

TEST(TwoMirrorScene, GoldPairsInTheSpectralModeGiveTheSquaredMean) {
    const Rgb<double> unpolarised =
        goldColour([](double rs, double rp) { return (rs + rp) * (rs + rp) / 4; });
    const auto r = renderGold(render::RenderModeKind::Spectral);
    expectGoldBlock(*r.film, kCrossed, unpolarised, "spectral, crossed");
    expectGoldBlock(*r.film, kParallel, unpolarised, "spectral, parallel");
}

}  // namespace
}  // namespace lamina
