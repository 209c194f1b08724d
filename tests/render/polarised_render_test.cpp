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

TEST(PolarisedRender, LightTracingAndBdptAreRefusedWithTheReason) {
    render::RenderOptions o;
    o.mode = render::RenderModeKind::Polarised;
    o.spp = 1;
    o.integrator = render::IntegratorKind::Bdpt;
    try {
        render::renderScene(sceneFromText(twoMirrors(0.8, 0.0, 1.5, 0.0)), o);
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("path integrator only"), std::string::npos);
    }
}

}  // namespace
}  // namespace lamina
