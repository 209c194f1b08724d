// The polarised mode against closed forms: a camera looks into a mirror that reflects into a
// second mirror that reflects into a lamp, both at the angle of incidence theta. Unpolarised
// light leaves the pair with Rs Rp of its radiance when the planes of incidence are crossed
// and (Rs^2 + Rp^2) / 2 when they are parallel; a renderer that averages s and p at each
// reflection (the spectral mode) gives ((Rs + Rp) / 2)^2 for both. The mirrors are grey
// conductors (wavelength-independent index), so each closed form is the image's value in
// every channel. Each mean is checked with a z-test at significance 0.001 (|z| < 3.29) against
// the film's own standard error, plus the spread of the reflectances over the camera's 0.5
// degree field of view.
#include <gtest/gtest.h>

#include <complex>
#include <numbers>
#include <optional>
#include <sstream>

#include "lamina/core/fresnel_amplitudes.h"
#include "render_helpers.h"

namespace lamina {
namespace {

using testing::imageMean;
using testing::sceneFromText;

constexpr double kZ = 3.29;  // two-sided significance 0.001

std::string vec(const Vec3d& v) {
    std::ostringstream s;
    s.precision(17);
    s << "[" << v.x << ", " << v.y << ", " << v.z << "]";
    return s.str();
}

/// A rectangle (normal +z, [-1, 1]^2 before the scale) turned to face `normal`, centred at `at`.
std::string rectangle(const Vec3d& at, const Vec3d& normal, double size, const std::string& rest) {
    const Vec3d z(0, 0, 1);
    const Vec3d axis = glm::cross(z, normal);
    const double angle =
        std::atan2(glm::length(axis), glm::dot(z, normal)) * 180.0 / std::numbers::pi;
    const Vec3d a = glm::length(axis) > 1e-12 ? glm::normalize(axis) : Vec3d(1, 0, 0);
    return R"({"type": "rectangle", )" + rest + R"(, "transform": [{"scale": )" +
           std::to_string(size) + R"(}, {"rotate": {"axis": )" + vec(a) + R"(, "angle": )" +
           std::to_string(angle) + R"(}}, {"translate": )" + vec(at) + "}]}";
}

/// The two-mirror scene: incidence angle theta on both mirrors, the second plane of
/// incidence turned by `turn` about the ray between them; `optics` the mirrors' eta and k.
std::string twoMirrors(double theta, double turn, double eta, double k) {
    const Vec3d d0(0, 0, -1);
    const Vec3d n1(std::sin(theta), 0, std::cos(theta));
    const Vec3d d1 = d0 - n1 * (2.0 * glm::dot(d0, n1));
    const Vec3d u0 = glm::normalize(glm::cross(d1, Vec3d(0, 1, 0)));
    const Vec3d v0 = glm::cross(d1, u0);
    const Vec3d u = u0 * std::cos(turn) + v0 * std::sin(turn);
    const Vec3d n2 = -d1 * std::cos(theta) + u * std::sin(theta);
    const Vec3d d2 = d1 - n2 * (2.0 * glm::dot(d1, n2));
    const Vec3d p2 = d1 * 2.0, lamp = p2 + d2 * 2.0;
    std::ostringstream s;
    s << R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 0.5},
      "film": {"resolution": [8, 8]},
      "materials": {"mirror": {"type": "conductor", "eta": )"
      << eta << R"(, "k": )" << k << R"(},
                    "lamp": {"type": "lambert", "reflectance": 0}},
      "shapes": [)"
      << rectangle(Vec3d(0), n1, 0.5, R"("material": "mirror")") << ",\n"
      << rectangle(p2, n2, 1.0, R"("material": "mirror")") << ",\n"
      << rectangle(lamp, -d2, 0.4, R"("material": "lamp", "emission": {"radiance": 1})") << "]}";
    return s.str();
}

struct Reflectances {
    double rs, rp;
};
Reflectances reflectances(double theta, double eta, double k) {
    const auto a = fresnelAmplitudes(std::cos(theta), std::complex<double>(eta, k));
    return {std::norm(a.rs), std::norm(a.rp)};
}

/// The image's mean in every channel is `expected` (z-test, and `spread` for the field of view).
void expectImage(const std::string& scene, render::RenderModeKind mode, double expected,
                 double spread) {
    render::RenderOptions o;
    o.mode = mode;
    o.spp = 64;
    const auto r = render::renderScene(sceneFromText(scene), o);
    for (int c = 0; c < 3; ++c) {
        const auto m = imageMean(*r.film, c);
        EXPECT_LT(std::abs(m.mean - expected), kZ * m.standardError + spread)
            << render::kRenderModeNames.name(mode) << " channel " << c << ": mean " << m.mean
            << " se " << m.standardError << ", expected " << expected;
    }
}

struct MirrorCase {
    const char* name;
    double theta, eta, k;
    double differs;  ///< the least relative difference of Rs Rp from the unpolarised answer
};

void PrintTo(const MirrorCase& c, std::ostream* os) {
    *os << c.name;
}

class TwoMirrors : public ::testing::TestWithParam<MirrorCase> {};

TEST_P(TwoMirrors, CrossedPlanesReflectRsRpAndParallelOnesTheMeanSquare) {
    const MirrorCase& c = GetParam();
    const auto [rs, rp] = reflectances(c.theta, c.eta, c.k);
    // Over the field of view the angle of incidence varies by 0.25 degrees either way.
    const double dTheta = 0.25 * std::numbers::pi / 180.0;
    const auto spreadOf = [&](auto f) {
        const auto lo = reflectances(c.theta - dTheta, c.eta, c.k);
        const auto hi = reflectances(c.theta + dTheta, c.eta, c.k);
        return std::max(std::abs(f(lo) - f({rs, rp})), std::abs(f(hi) - f({rs, rp}))) + 1e-6;
    };
    const auto crossed = [](Reflectances r) { return r.rs * r.rp; };
    const auto parallel = [](Reflectances r) { return 0.5 * (r.rs * r.rs + r.rp * r.rp); };
    const auto unpolarised = [](Reflectances r) { return 0.25 * (r.rs + r.rp) * (r.rs + r.rp); };
    const double half = std::numbers::pi / 2.0;
    using render::RenderModeKind;
    expectImage(twoMirrors(c.theta, half, c.eta, c.k), RenderModeKind::Polarised, crossed({rs, rp}),
                spreadOf(crossed));
    expectImage(twoMirrors(c.theta, 0.0, c.eta, c.k), RenderModeKind::Polarised, parallel({rs, rp}),
                spreadOf(parallel));
    // The spectral mode averages s and p: the same value for both, and not the right one.
    expectImage(twoMirrors(c.theta, half, c.eta, c.k), RenderModeKind::Spectral,
                unpolarised({rs, rp}), spreadOf(unpolarised));
    // The test can tell the two apart: the difference is far above its tolerances.
    EXPECT_GT(std::abs(crossed({rs, rp}) - unpolarised({rs, rp})),
              c.differs * unpolarised({rs, rp}));
}

INSTANTIATE_TEST_SUITE_P(
    Mirrors, TwoMirrors,
    ::testing::Values(MirrorCase{"GlassAtBrewstersAngle", std::atan(1.5), 1.5, 0.0, 0.99},
                      MirrorCase{"GlassAt45Degrees", std::numbers::pi / 4.0, 1.5, 0.0, 0.6},
                      MirrorCase{"GreyMetalAt70Degrees", 70.0 * std::numbers::pi / 180.0, 0.5, 2.5,
                                 0.02}),
    [](const auto& test) { return std::string(test.param.name); });

// The Stokes layers: a camera looks straight down into one glass mirror whose plane of
// incidence is turned by psi from the image's right (towards its up). Unpolarised light leaves
// it with S0 = (Rs + Rp) / 2 and linearly polarised along s, the normal of the plane of
// incidence, at psi + 90 degrees in the image frame: S1 = -(Rs - Rp) / 2 cos(2 psi),
// S2 = -(Rs - Rp) / 2 sin(2 psi), S3 = 0 (real amplitudes, no retardance). An analyser at
// alpha then passes (S0 + cos(2 alpha) S1 + sin(2 alpha) S2) / 2: at Brewster's angle (Rp = 0,
// the light fully polarised) that is Malus's law, Rs / 2 cos^2(alpha - psi - 90 degrees).
// Every value is checked per channel (the mirror is grey) with a z-test at significance 0.001
// against the spread of the 64 pixels, plus the Fresnel spread over the 0.5 degree field of
// view.
std::string oneMirror(double theta, double psi, std::optional<double> analyserDegrees,
                      const std::string& optics = R"("eta": 1.5, "k": 0)") {
    const Vec3d d0(0, 0, -1);
    const Vec3d n1(std::sin(theta) * std::cos(psi), std::sin(theta) * std::sin(psi),
                   std::cos(theta));
    const Vec3d d1 = d0 - n1 * (2.0 * glm::dot(d0, n1));
    std::ostringstream s;
    s << R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 0.5)";
    if (analyserDegrees) s << R"(, "analyser": )" << *analyserDegrees;
    s << R"(},
      "film": {"resolution": [8, 8]},
      "materials": {"mirror": {"type": "conductor", )"
      << optics << R"(},
                    "lamp": {"type": "lambert", "reflectance": 0}},
      "shapes": [)"
      << rectangle(Vec3d(0), n1, 0.5, R"("material": "mirror")") << ",\n"
      << rectangle(d1 * 2.0, -d1, 0.4, R"("material": "lamp", "emission": {"radiance": 1})")
      << "]}";
    return s.str();
}

/// The mean over the image of Stokes component `i` in channel `c`, with its standard error from
/// the spread of the pixels (each an independent estimate).
testing::ImageMean stokesMean(const render::Film& film, int i, int c) {
    double sum = 0, sq = 0;
    const double n = double(film.width()) * film.height();
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const double v = film.stokes(x, y)[std::size_t(i)][c];
            sum += v;
            sq += v * v;
        }
    const double mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sq / n - mean * mean) / (n - 1))};
}

struct StokesCase {
    const char* name;
    double thetaDegrees, psiDegrees;
};

void PrintTo(const StokesCase& c, std::ostream* os) {
    *os << c.name;
}

class StokesLayers : public ::testing::TestWithParam<StokesCase> {};

TEST_P(StokesLayers, OneMirrorPolarisesAlongTheNormalOfItsPlaneOfIncidence) {
    const StokesCase& c = GetParam();
    const double deg = std::numbers::pi / 180.0;
    const double theta = c.thetaDegrees * deg, psi = c.psiDegrees * deg;
    const auto stokes = [&](double t) {
        const auto [rs, rp] = reflectances(t, 1.5, 0.0);
        return std::array<double, 4>{0.5 * (rs + rp), -0.5 * (rs - rp) * std::cos(2 * psi),
                                     -0.5 * (rs - rp) * std::sin(2 * psi), 0.0};
    };
    render::RenderOptions o;
    o.mode = render::RenderModeKind::Polarised;
    o.spp = 16;
    const auto r = render::renderScene(sceneFromText(oneMirror(theta, psi, std::nullopt)), o);
    ASSERT_TRUE(r.film->hasStokes());
    const auto expected = stokes(theta);
    const auto lo = stokes(theta - 0.25 * deg), hi = stokes(theta + 0.25 * deg);
    for (int i = 0; i < 4; ++i)
        for (int ch = 0; ch < 3; ++ch) {
            const auto m = stokesMean(*r.film, i, ch);
            const double spread = std::max(std::abs(lo[std::size_t(i)] - expected[std::size_t(i)]),
                                           std::abs(hi[std::size_t(i)] - expected[std::size_t(i)]));
            EXPECT_LT(std::abs(m.mean - expected[std::size_t(i)]),
                      kZ * m.standardError + spread + 1e-6)
                << "S" << i << " channel " << ch << ": mean " << m.mean << " se " << m.standardError
                << ", expected " << expected[std::size_t(i)];
        }
    // S0 is the image.
    for (int ch = 0; ch < 3; ++ch)
        EXPECT_EQ(r.film->stokes(3, 4)[0][ch], r.film->pixel(3, 4)[ch]);
}

INSTANTIATE_TEST_SUITE_P(
    Mirrors, StokesLayers,
    ::testing::Values(StokesCase{"BrewsterPlaneAlongTheImagesRight", 56.30993247402022, 0.0},
                      StokesCase{"At45DegreesPlaneTurned30Degrees", 45.0, 30.0},
                      StokesCase{"At60DegreesPlaneTurned45Degrees", 60.0, 45.0},
                      StokesCase{"At70DegreesPlaneAlongTheImagesUp", 70.0, 90.0},
                      StokesCase{"At45DegreesPlaneTurnedMinus60Degrees", 45.0, -60.0}),
    [](const auto& test) { return std::string(test.param.name); });

// Malus's law in the path tracer: light made fully linear by a reflection at Brewster's angle
// (along the image's up, psi = 0), through the camera's analyser at 0..90 degrees in
// 15-degree steps.
TEST(PolarisedRender, AnAnalyserPassesMalussLawOfBrewsterLight) {
    const double theta = std::atan(1.5);
    const auto [rs, rp] = reflectances(theta, 1.5, 0.0);
    ASSERT_LT(rp, 1e-12);
    for (int alpha = 0; alpha <= 90; alpha += 15) {
        render::RenderOptions o;
        o.mode = render::RenderModeKind::Polarised;
        o.spp = 16;
        const auto r = render::renderScene(sceneFromText(oneMirror(theta, 0.0, double(alpha))), o);
        const double a = alpha * std::numbers::pi / 180.0;
        const double expected = 0.5 * rs * std::sin(a) * std::sin(a);
        // The reflectance's spread over the field of view (Rp rises from 0 on either side).
        const auto lo = reflectances(theta - 0.0044, 1.5, 0.0);
        const double spread = std::abs(0.5 * lo.rs - 0.5 * rs) + 0.5 * lo.rp + 1e-6;
        for (int ch = 0; ch < 3; ++ch) {
            const auto m = imageMean(*r.film, ch);
            EXPECT_LT(std::abs(m.mean - expected), kZ * m.standardError + spread)
                << "analyser at " << alpha << " degrees, channel " << ch << ": mean " << m.mean
                << ", expected " << expected;
        }
    }
}

// Optical sheets: the camera looks at a lamp of radiance 1 through a polariser whose axis is
// the image's right (nearer the lamp) and a second sheet (nearer the camera). Two polarisers at
// alpha apart pass cos^2(alpha) / 2 (Malus's law); the spectral mode, which renders
// unpolarised light, passes 1/4 at every angle. A quarter-wave plate with its fast axis at
// +45 degrees turns the light along x into S3 = -S0 (mueller_matrix.h, linearRetarder), at
// -45 degrees into S3 = +S0. The sheets are deltas and the camera and wavelength samples come
// before any scattering, so each image is the image of the lamp alone, with the same seed,
// times the closed form, to float rounding: checked to 1e-4 relative.
std::string lampAlone() {
    return R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 5},
      "film": {"resolution": [8, 8]},
      "materials": {"lamp": {"type": "lambert", "reflectance": 0}},
      "shapes": [{"type": "rectangle", "material": "lamp", "emission": {"radiance": 1},
                  "transform": [{"translate": [0, 0, -2]}]}]})";
}

std::string throughTwoSheets(const std::string& near) {
    return R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "fov": 5},
      "film": {"resolution": [8, 8]},
      "materials": {"far": {"type": "polariser", "axis": [1, 0, 0]},
                    "near": )" +
           near + R"(,
                    "lamp": {"type": "lambert", "reflectance": 0}},
      "shapes": [{"type": "rectangle", "material": "near"},
                 {"type": "rectangle", "material": "far", "transform": [{"translate": [0, 0, -1]}]},
                 {"type": "rectangle", "material": "lamp", "emission": {"radiance": 1},
                  "transform": [{"translate": [0, 0, -2]}]}]})";
}

TEST(PolarisedRender, TwoPolariserSheetsPassMalussLaw) {
    for (int alpha = 0; alpha <= 90; alpha += 15) {
        const double a = alpha * std::numbers::pi / 180.0;
        std::ostringstream near;
        near.precision(17);
        near << R"({"type": "polariser", "axis": [)" << std::cos(a) << ", " << std::sin(a)
             << ", 0]}";
        for (const auto mode :
             {render::RenderModeKind::Polarised, render::RenderModeKind::Spectral}) {
            render::RenderOptions o;
            o.mode = mode;
            o.spp = 4;
            const auto r = render::renderScene(sceneFromText(throughTwoSheets(near.str())), o);
            const auto lamp = render::renderScene(sceneFromText(lampAlone()), o);
            const double expected =
                mode == render::RenderModeKind::Polarised ? 0.5 * std::cos(a) * std::cos(a) : 0.25;
            for (int ch = 0; ch < 3; ++ch) {
                const double l = imageMean(*lamp.film, ch).mean;
                EXPECT_NEAR(imageMean(*r.film, ch).mean, expected * l, 1e-4 * l)
                    << render::kRenderModeNames.name(mode) << ", polarisers " << alpha
                    << " degrees apart, channel " << ch;
            }
        }
    }
}

TEST(PolarisedRender, AQuarterWavePlateAt45DegreesMakesLinearLightCircular) {
    for (const double sign : {1.0, -1.0}) {
        std::ostringstream near;
        near << R"({"type": "retarder", "axis": [1, )" << sign << R"(, 0], "retardance": 90})";
        render::RenderOptions o;
        o.mode = render::RenderModeKind::Polarised;
        o.spp = 4;
        const auto r = render::renderScene(sceneFromText(throughTwoSheets(near.str())), o);
        const auto lamp = render::renderScene(sceneFromText(lampAlone()), o);
        for (int ch = 0; ch < 3; ++ch) {
            const auto s = r.film->stokes(4, 4);
            const double l = lamp.film->pixel(4, 4)[ch];
            EXPECT_NEAR(s[0][ch], 0.5 * l, 1e-4 * l) << "fast axis at " << sign * 45 << " degrees";
            EXPECT_NEAR(s[1][ch], 0.0, 1e-4 * l);
            EXPECT_NEAR(s[2][ch], 0.0, 1e-4 * l);
            EXPECT_NEAR(s[3][ch], -sign * 0.5 * l, 1e-4 * l)
                << "fast axis at " << sign * 45 << " degrees";
        }
    }
}

// The polarised mode's spectral film (`render --spectral-film`): per bin, the light of the one
// mirror above has S1 / S0 = -(Rs - Rp) / (Rs + Rp) cos(2 psi) and S2 / S0 the same with
// sin(2 psi) at the bin's wavelengths, and S3 = 0. A bin's S1 and S0 sum the same samples, each
// sample's S1 its S0 times that ratio at its wavelength and angle of incidence, so their
// quotient is a positively weighted mean of the ratio over the bin's wavelengths and the 0.5
// degree field of view: it lies between the ratio's least and greatest value there, with no
// noise term (checked to 1e-4 for the float arithmetic). A dispersionless glass has the same
// ratio in every bin; a conductor whose n rises from 0.5 to 3 and k falls from 3 to 0.5 over
// 360 to 830 nm has one that changes from -0.12 to -0.80 across the bins, far more than the
// margin, which the test checks too.
TEST(PolarisedRender, TheSpectralFilmHoldsEachBinsDiattenuation) {
    struct Optics {
        const char* name;
        std::string json;
        double n360, n830, k360, k830;
    };
    const double deg = std::numbers::pi / 180.0;
    const double theta = 60 * deg, psi = 30 * deg;
    for (const Optics& optics :
         {Optics{"glass", R"("eta": 1.5, "k": 0)", 1.5, 1.5, 0, 0},
          Optics{"conductor", R"("eta": [[360, 0.5], [830, 3]], "k": [[360, 3], [830, 0.5]])", 0.5,
                 3, 3, 0.5}}) {
        render::RenderOptions o;
        o.mode = render::RenderModeKind::Polarised;
        o.spp = 16;
        o.spectralBins = 10;
        const auto r =
            render::renderScene(sceneFromText(oneMirror(theta, psi, std::nullopt, optics.json)), o);
        const render::SpectralFilm& s = *r.film->spectralFilm();
        ASSERT_EQ(s.components(), 4);
        const int n = s.bins().count;
        std::vector<double> sum(s.valuesPerPixel(), 0.0), pixel(s.valuesPerPixel());
        for (int y = 0; y < r.film->height(); ++y)
            for (int x = 0; x < r.film->width(); ++x) {
                r.film->spectralMean(x, y, pixel.data());
                for (std::size_t i = 0; i < pixel.size(); ++i)
                    sum[i] += pixel[i];
            }
        // The diattenuation -(Rs - Rp) / (Rs + Rp) at a wavelength and angle of incidence.
        const auto diattenuation = [&](double nm, double t) {
            const double f = (nm - 360) / 470;
            const auto [rs, rp] = reflectances(t, optics.n360 + f * (optics.n830 - optics.n360),
                                               optics.k360 + f * (optics.k830 - optics.k360));
            return -(rs - rp) / (rs + rp);
        };
        double first = 0, last = 0;
        for (int b = 0; b < n; ++b) {
            double lo = 1e9, hi = -1e9;
            for (int i = 0; i <= 40; ++i)
                for (int j = -2; j <= 2; ++j) {
                    const double d = diattenuation(s.bins().start(b) + s.bins().width() * i / 40,
                                                   theta + j * 0.125 * deg);
                    lo = std::min(lo, d);
                    hi = std::max(hi, d);
                }
            const double s0 = sum[std::size_t(b)];
            ASSERT_GT(s0, 0) << optics.name << " bin " << b;
            const double q1 = sum[std::size_t(n + b)] / s0 / std::cos(2 * psi),
                         q2 = sum[std::size_t(2 * n + b)] / s0 / std::sin(2 * psi),
                         q3 = sum[std::size_t(3 * n + b)] / s0;
            const std::string at = std::string(optics.name) + " bin " + std::to_string(b) + " at " +
                                   std::to_string(s.bins().centre(b)) + " nm";
            EXPECT_GT(q1, lo - 1e-4)
                << at << ": S1 / S0 / cos(2 psi) " << q1 << " in [" << lo << ", " << hi << "]";
            EXPECT_LT(q1, hi + 1e-4)
                << at << ": S1 / S0 / cos(2 psi) " << q1 << " in [" << lo << ", " << hi << "]";
            EXPECT_GT(q2, lo - 1e-4) << at << ": S2 / S0 / sin(2 psi) " << q2;
            EXPECT_LT(q2, hi + 1e-4) << at << ": S2 / S0 / sin(2 psi) " << q2;
            EXPECT_LT(std::abs(q3), 1e-4) << at << ": S3 / S0";
            if (b == 0) first = q1;
            last = q1;
        }
        if (optics.n360 != optics.n830) {
            EXPECT_GT(std::abs(last - first), 0.5) << "the conductor's bins differ";
        }
    }
}

TEST(PolarisedRender, AnAnalyserOutsideThePolarisedModeIsRefused) {
    render::RenderOptions o;
    o.mode = render::RenderModeKind::Spectral;
    o.spp = 1;
    try {
        render::renderScene(sceneFromText(oneMirror(0.8, 0.0, 30.0)), o);
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("camera.analyser"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace lamina
