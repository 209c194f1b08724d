// Environments seen through a portal (portal_environment.h): the two-angle map and its
// Jacobian, the window of directions through the rectangle from a point, next-event sampling
// against its density (chi-square), a diffuse floor under a window in a uniform sky against
// the closed form of its irradiance with all three integrators, and a closed room with an
// opening: the portal's environment renders as the plain environment there, and path, light
// and BDPT agree on it (blockwise Welch tests, as integrator_agreement_test.cpp).
#include <gtest/gtest.h>

#include <functional>

#include "chi2_helpers.h"
#include "lamina/core/pcg32.h"
#include "lamina/core/warp.h"
#include "lamina/experiments/estimator_agreement.h"
#include "lamina/image/image_io.h"
#include "lamina/lights/portal_environment.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::sceneFromText;

// A 2 x 1.5 rectangle tilted out of the axes, its outer side along (c3 - c0) x (c1 - c0).
std::array<Vec3d, 4> tiltedRectangle() {
    const Vec3d x = glm::normalize(Vec3d(1, 0.2, 0.1)), y0(0, 1, 0);
    const Vec3d y = glm::normalize(y0 - glm::dot(y0, x) * x);
    const Vec3d c0(0.3, -0.2, 1.0);
    return {c0, c0 + 1.5 * y, c0 + 2.0 * x + 1.5 * y, c0 + 2.0 * x};
}

TEST(PortalMapping, TheJacobianIntegratesToTheHemisphere) {
    const PortalMapping m(tiltedRectangle());
    // The midpoint rule converges only as 1/n here (the integrand falls to 0 at the square's
    // edges like the distance to them): Richardson's extrapolation of n = 1000 and 2000.
    const auto midpoint = [&](int n) {
        double sum = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                sum += m.jacobian(m.fromUv({(i + 0.5) / n, (j + 0.5) / n}));
        return sum / (double(n) * n);
    };
    EXPECT_NEAR(2 * midpoint(2000) - midpoint(1000), 2 * kPi<double>, 1e-6);
}

TEST(PortalMapping, UvAndDirectionsAreInverses) {
    const PortalMapping m(tiltedRectangle());
    Pcg32 rng(1);
    for (int k = 0; k < 1000; ++k) {
        const Vec2d uv(0.01 + 0.98 * rng.nextDouble(), 0.01 + 0.98 * rng.nextDouble());
        const auto back = m.toUv(m.fromUv(uv));
        ASSERT_TRUE(back);
        EXPECT_NEAR(back->x, uv.x, 1e-12);
        EXPECT_NEAR(back->y, uv.y, 1e-12);
    }
    EXPECT_FALSE(m.toUv(-m.normal()));
}

// From a point behind the rectangle a direction is in the window exactly when the ray along it
// crosses the rectangle; from a point in front no window exists.
TEST(PortalMapping, TheWindowHoldsTheDirectionsThroughTheRectangle) {
    const auto c = tiltedRectangle();
    const PortalMapping m(c);
    const Vec3d p = c[0] + Vec3d(0.4, 0.9, -0.1) - 1.3 * m.normal();
    const auto window = m.windowFrom(p);
    ASSERT_TRUE(window);
    const Vec3d ex = c[3] - c[0], ey = c[1] - c[0];
    Pcg32 rng(2);
    int through = 0;
    for (int k = 0; k < 20000; ++k) {
        const Vec3d w = squareToUniformSphere(Vec2d(rng.nextDouble(), rng.nextDouble()));
        bool crosses = false;
        const double dz = glm::dot(w, m.normal());
        if (dz > 0) {
            const double t = glm::dot(c[0] - p, m.normal()) / dz;
            const Vec3d q = p + t * w - c[0];
            const double s = glm::dot(q, ex) / glm::dot(ex, ex),
                         r = glm::dot(q, ey) / glm::dot(ey, ey);
            crosses = s >= 0 && s <= 1 && r >= 0 && r <= 1;
        }
        const auto uv = m.toUv(w);
        const bool inWindow = uv && uv->x >= window->lo.x && uv->x <= window->hi.x &&
                              uv->y >= window->lo.y && uv->y <= window->hi.y;
        // Directions within 1e-9 of an edge may fall either way.
        EXPECT_EQ(crosses, inWindow) << w.x << " " << w.y << " " << w.z;
        through += crosses;
    }
    EXPECT_GT(through, 500);
    EXPECT_FALSE(m.windowFrom(c[0] + 0.5 * (ex + ey) + 0.1 * m.normal()));
}

/// A diffuse floor of reflectance 0.5, the square [-half, half]^2 at y = 0, seen by `camera`
/// and lit by `lights` (JSON objects) alone, one bounce.
std::string floorScene(const std::string& camera, const std::string& integrator, double half,
                       const std::string& lights) {
    return R"({
      "camera": )" +
           camera +
           R"(,
      "film": {"resolution": [12, 12], "filter": {"type": "box", "radius": 0.5}},
      "integrator": {"type": ")" +
           integrator + R"(", "max_depth": 1},
      "materials": {"floor": {"type": "lambert", "reflectance": 0.5}},
      "shapes": [{"type": "rectangle", "material": "floor",
                  "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}},
                                {"scale": )" +
           std::to_string(half) + R"(}]}],
      "lights": [)" +
           lights + "]\n    }";
}

/// An orthographic camera 1 above the floor looking straight down at its 0.6 x 0.6 patch.
constexpr const char* kDownOntoThePatch =
    R"({"type": "orthographic", "position": [0, 1, 0], "look_at": [0, 0, 0], "up": [0, 0, 1],
        "screen_window": [-0.3, 0.3, -0.3, 0.3]})";

// The scene of the closed-form tests: a diffuse floor patch of reflectance 0.5 under a 2 x 2
// window 2 above it, in a uniform sky of radiance [1, 2, 3]; an orthographic camera looks
// straight down at the 0.6 x 0.6 patch around the window's axis.
std::string floorUnderAWindow(const std::string& integrator) {
    return floorScene(kDownOntoThePatch, integrator, 0.3,
                      R"({"type": "environment", "radiance": [1, 2, 3],
                  "portal": [[-1, 2, 1], [-1, 2, -1], [1, 2, -1], [1, 2, 1]]})");
}

/// (1 / pi) x the integral of cos over the solid angle of the rectangle [0, a] x [0, b] at
/// height h above a point under its corner (the point-to-rectangle form factor; Howell's
/// catalogue of configuration factors, case B-3), odd in a and in b.
double cornerFormFactor(double a, double b, double h) {
    const double A = a / h, B = b / h;
    const double sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
    return (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb)) / (2 * kPi<double>);
}

/// A window 2 above the floor: x in [x0, x1], z in [z0, z1].
struct Window {
    double x0, x1, z0, z1;
};

/// The floor's radiance averaged over the camera's view: reflectance x L x the form factor of
/// the windows (by default the 2 x 2 window of floorUnderAWindow), over the floor's square
/// [-halfView, halfView]^2.
double expectedFloorRadiance(double L, std::initializer_list<Window> windows = {{-1, 1, -1, 1}},
                             double halfView = 0.3) {
    constexpr int n = 200;
    double sum = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double x = halfView * (2 * (i + 0.5) / n - 1),
                         z = halfView * (2 * (j + 0.5) / n - 1);
            for (const Window& w : windows)
                sum += cornerFormFactor(w.x1 - x, w.z1 - z, 2) -
                       cornerFormFactor(w.x0 - x, w.z1 - z, 2) -
                       cornerFormFactor(w.x1 - x, w.z0 - z, 2) +
                       cornerFormFactor(w.x0 - x, w.z0 - z, 2);
        }
    return 0.5 * L * sum / (double(n) * n);
}

void expectFloorMatchesTheFormFactor(const std::string& integrator, int spp) {
    RenderOptions o;
    o.spp = spp;
    o.seed = 5;
    const RenderResult r = renderScene(sceneFromText(floorUnderAWindow(integrator)), o);
    for (int c = 0; c < 3; ++c) {
        const auto m = testing::imageMean(*r.film, c);
        const double expected = expectedFloorRadiance(c + 1.0);
        // Four standard errors and 0.3% (the sky grid's piecewise density does not bias; the
        // floor patch's float geometry and the form factor's midpoint rule are far below).
        EXPECT_NEAR(m.mean, expected, 4 * m.standardError + 0.003 * expected)
            << integrator << ", channel " << c;
    }
}

TEST(PortalEnvironment, AFloorUnderAWindowMatchesTheFormFactorByPathTracing) {
    expectFloorMatchesTheFormFactor("path", 256);
}

TEST(PortalEnvironment, AFloorUnderAWindowMatchesTheFormFactorByLightTracing) {
    expectFloorMatchesTheFormFactor("light", 4096);
}

TEST(PortalEnvironment, AFloorUnderAWindowMatchesTheFormFactorByBdpt) {
    expectFloorMatchesTheFormFactor("bdpt", 256);
}

void expectFloorRadiance(const std::string& scene, const std::string& integrator, int spp,
                         const std::function<double(int channel)>& expected) {
    RenderOptions o;
    o.spp = spp;
    o.seed = 8;
    const RenderResult r = renderScene(sceneFromText(scene), o);
    for (int c = 0; c < 3; ++c) {
        const auto m = testing::imageMean(*r.film, c);
        std::printf("  %-5s channel %d: %.5f +- %.5f, closed form %.5f\n", integrator.c_str(), c,
                    m.mean, m.standardError, expected(c));
        EXPECT_NEAR(m.mean, expected(c), 4 * m.standardError + 0.003 * expected(c))
            << integrator << ", channel " << c;
    }
}

// Two windows, two portal environments of the same sky (pbrt-v4-scenes' watercolor has a
// room with two): the floor receives the sum of both form factors, by every integrator.
void expectTwoWindowsAddUp(const std::string& integrator, int spp) {
    const Window second{1.5, 3.5, -1, 1};
    const std::string scene = floorScene(kDownOntoThePatch, integrator, 0.3,
                                         R"({"type": "environment", "radiance": [1, 2, 3],
                  "portal": [[-1, 2, 1], [-1, 2, -1], [1, 2, -1], [1, 2, 1]]},
                 {"type": "environment", "radiance": [1, 2, 3],
                  "portal": [[1.5, 2, 1], [1.5, 2, -1], [3.5, 2, -1], [3.5, 2, 1]]})");
    expectFloorRadiance(scene, integrator, spp, [&](int c) {
        return expectedFloorRadiance(c + 1.0, {{-1, 1, -1, 1}, second});
    });
}

TEST(PortalEnvironment, TwoWindowsAddUpByEveryIntegrator) {
    expectTwoWindowsAddUp("path", 256);
    expectTwoWindowsAddUp("light", 4096);
    expectTwoWindowsAddUp("bdpt", 256);
}

// A small window inside a larger one, each a portal environment of its own colour: the lines
// through the small window carry both. BDPT's weights see one light at infinity whose density
// along a line is the environments' together (bdpt_mis.cpp, pdfLight), and a light subpath
// must record that same density at its first vertex: recording its own portal's density (11
// times the large one's per unit area) makes the weights of a path's strategies sum to more or
// less than one, and BDPT 18% too red here (broken once on purpose). The floor is seen from
// close by a pinhole camera, over about the large window's area, so that the camera's density
// of a floor point and a particle's are alike and the strategies that connect a particle to the
// camera carry weight. (The windows side by side above cannot show this: a line crosses one of
// them.)
void expectNestedWindowsAddUp(const std::string& integrator, int spp) {
    const Window large{-0.6, 0.6, -0.6, 0.6}, small{-0.2, 0.2, -0.2, 0.2};
    const double largeRadiance[3] = {1, 2, 3}, smallRadiance[3] = {6, 1, 3};
    // The camera 1 above the floor sees [-0.6, 0.6] x [-0.6, 0.6] of it (a plane square to the axis
    // maps linearly to the film): fov 2 atan(0.6).
    const std::string scene = floorScene(
        R"({"position": [0, 1, 0], "look_at": [0, 0, 0], "up": [0, 0, 1],
            "fov": 61.9275130641471})",
        integrator, 0.8, R"({"type": "environment", "radiance": [1, 2, 3],
                  "portal": [[-0.6, 2, 0.6], [-0.6, 2, -0.6], [0.6, 2, -0.6], [0.6, 2, 0.6]]},
                 {"type": "environment", "radiance": [6, 1, 3],
                  "portal": [[-0.2, 2, 0.2], [-0.2, 2, -0.2], [0.2, 2, -0.2], [0.2, 2, 0.2]]})");
    expectFloorRadiance(scene, integrator, spp, [&](int c) {
        return expectedFloorRadiance(largeRadiance[c], {large}, 0.6) +
               expectedFloorRadiance(smallRadiance[c], {small}, 0.6);
    });
}

TEST(PortalEnvironment, NestedWindowsAddUpByEveryIntegrator) {
    expectNestedWindowsAddUp("path", 256);
    expectNestedWindowsAddUp("light", 4096);
    expectNestedWindowsAddUp("bdpt", 256);
}

// Without the portal the same floor sees the whole sky: L x reflectance, 6.5 times more here.
TEST(PortalEnvironment, WithoutThePortalTheFloorSeesTheWholeSky) {
    std::string scene = floorUnderAWindow("path");
    const auto at = scene.find(",\n                  \"portal\"");
    ASSERT_NE(at, std::string::npos);
    scene.erase(at, scene.find("]]", at) + 2 - at);
    RenderOptions o;
    o.spp = 16;
    const RenderResult r = renderScene(sceneFromText(scene), o);
    EXPECT_NEAR(testing::imageMean(*r.film, 0).mean, 0.5, 0.01);
}

// Next-event directions from a point under the window follow the density the path tracer's
// MIS weights read (chi-square over the sphere, significance 0.01).
class PortalSky : public lamina::testing::ScratchDirectoryTest {};

TEST_F(PortalSky, NextEventSamplesFollowTheirDensity) {
    // A sky with a bright patch, so that the grid is far from uniform.
    const int w = 64, h = 32;
    std::vector<float> px;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < 3; ++c)
                px.push_back((std::abs(x - 40) < 4 && std::abs(y - 10) < 3) ? 40.0f
                                                                            : 0.5f + 0.02f * y);
    writeFloatExr(dir_ / "sky.exr", w, h, {"R", "G", "B"}, px);
    const SceneDesc scene = sceneFromText(
        R"({"camera": {"position": [0, 0, -3]},
            "materials": {"m": {"type": "lambert"}},
            "shapes": [{"type": "sphere", "radius": 0.1, "center": [0, -5, 0], "material": "m"}],
            "lights": [{"type": "environment", "file": ")" +
        (dir_ / "sky.exr").string() + R"(",
                        "portal": [[-1, 2, 1], [-1, 2, -1], [1, 2, -1], [1, 2, 1]]}]})");
    const Geometry geometry(scene);
    const LightSet lights(scene, geometry, LightSelection::Power);
    ASSERT_EQ(lights.size(), 1u);
    const Light& light = lights.light(0);
    const Vec3f ref(0.4f, 0.5f, -0.3f);
    ChiSquareConfig c;
    c.testCount = 1;
    c.significance = testing::kSignificance;
    c.cosThetaBins = 64;
    c.phiBins = 128;
    c.sampleCount = 200000;
    const ChiSquareResult r = runChiSquareTest(
        c,
        [&](Pcg32& rng) -> std::optional<Vec3d> {
            const float a = rng.nextFloat();
            const auto s = light.sample(ref, {a, rng.nextFloat()});
            if (!s) return std::nullopt;
            // The density is piecewise constant in (u, v): the float direction may fall in the
            // next cell of the grid, whose value differs by a percent at most here.
            EXPECT_NEAR(s->pdf, light.environmentPdf(ref, s->wi), 1e-2f * s->pdf);
            EXPECT_FALSE(light.environment(ref, s->wi).isZero());
            return Vec3d(s->wi);
        },
        [&](const Vec3d& d) { return double(light.environmentPdf(ref, Vec3f(d))); });
    EXPECT_TRUE(testing::passes(r));
    EXPECT_NEAR(r.pdfIntegral, 1.0, 1e-2);
}

// In a room closed but for its window, the portal changes how the sky is found, not what it
// lights: the path tracer renders scenes/reciprocity/portal-window.json with and without the
// portal to the same image (the blockwise Welch test of integrator_agreement_test.cpp, 2 x 2
// blocks of a 32 x 32 image, alpha 0.01: at most 3% of the blocks rejected, means within three
// standard errors).
TEST(PortalEnvironment, InAClosedRoomThePortalRendersThePlainEnvironment) {
    using namespace lamina::experiments;
    const SceneDesc portal =
        loadScene(testing::sourceFile("scenes/reciprocity/portal-window.json"));
    SceneDesc plain = portal;
    std::get<EnvironmentLightDesc>(plain.lights[0]).portal.reset();
    RenderOptions o;
    o.integrator = IntegratorKind::Path;
    o.resolution = std::make_pair(32, 32);
    o.seed = 3;
    const BatchImages a = renderBatches(portal, o, 256, 32);
    o.seed = 4;
    const BatchImages b = renderBatches(plain, o, 512, 32);
    AgreementTest test;
    test.alpha = 0.01;
    test.blockSize = 2;
    const AgreementResult r = testAgreement(a, b, test);
    std::printf("  portal vs plain: blocks %.2f%% rejected; mean rel. diff %+.4f +- %.4f\n",
                100 * r.blockRejectionRate(), r.relativeDifference, r.standardError);
    EXPECT_EQ(r.blocksTested, 256);
    EXPECT_LE(r.blockRejectionRate(), 0.03);
    EXPECT_GE(r.meanPValue, 0.0027);
}

// A portal that is not a rectangle is refused at its key.
TEST(PortalEnvironment, RefusesWhatIsNotARectangle) {
    const auto error = [](const std::string& lights) {
        return lamina::testing::errorOf([&] {
            sceneFromText(R"({"materials": {"m": {"type": "lambert"}},
                              "shapes": [{"type": "sphere", "material": "m"}],
                              "lights": [)" +
                          lights + "]}");
        });
    };
    const std::string env = R"({"type": "environment", "radiance": 1, "portal": )";
    EXPECT_EQ(error(env + "[[0, 0, 0], [1, 0, 0], [1.5, 1, 0], [0, 1, 0]]}"),
              "<test scene>: lights[0].portal: expected a rectangle, corners in order around it "
              "(opposite sides parallel, sides perpendicular, within 1e-3)");
    EXPECT_EQ(error(env + "[[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.2]]}"),
              "<test scene>: lights[0].portal: expected a rectangle, corners in order around it "
              "(opposite sides parallel, sides perpendicular, within 1e-3)");
    EXPECT_EQ(error(env + "[[0, 0, 0], [0, 0, 0], [1, 1, 0], [0, 1, 0]]}"),
              "<test scene>: lights[0].portal: corners 0 and 1 coincide: expected a rectangle");
    EXPECT_EQ(error(env + "[[0, 0, 0], [1, 0, 0], [1, 1, 0]]}"),
              "<test scene>: lights[0].portal: expected the portal's four corners, [[x, y, z], "
              "...] in order around it");
    EXPECT_EQ(error(env + "[[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]}"), "(accepted)");
}

}  // namespace
}  // namespace lamina::render
