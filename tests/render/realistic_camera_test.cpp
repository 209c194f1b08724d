// The realistic camera (lens_system.h, realistic_camera.h) against closed forms, and its lens
// file reader against hostile files:
// - a single biconvex element focuses where the lens-maker's equation (with its thickness, and
//   the principal planes of Gaussian optics) puts the image, and a parallel ray crosses the
//   axis at its focal length;
// - a small emitter on the plane in focus renders into the central 3x3 pixels, and spreads
//   when the lens is focused elsewhere;
// - a uniform sky seen through the element is, in every pixel of the middle row and the
//   diagonal, the integral of cos^4(theta) / z^2 over the element's aperture (Kolb et al.'s
//   irradiance), which falls off towards the corners;
// - the lens file reader refuses every malformed line with one line naming file and line.
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/render/renderer.h"
#include "lamina/scene/lens_system.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

// A biconvex element: radii +-100 mm, 0.3 mm thick on the axis (its caps of 5 mm radius do not
// cross), index 1.5, aperture diameter 10 mm.
constexpr const char* kBiconvex = "# biconvex\n100 0.3 1.5 10\n-100 100 1 10\n";
constexpr double kR = 0.1, kD = 0.0003, kN = 1.5, kA = 0.005;

// The lens-maker's equation for a thick lens and the distance of each principal plane inside
// its vertex (Gaussian optics: h = f (n - 1) d / (n R) for a symmetric lens).
double focalLength() {
    return 1 / ((kN - 1) * (2 / kR - (kN - 1) * kD / (kN * kR * kR)));
}
double principalInset() {
    return focalLength() * (kN - 1) * kD / (kN * kR);
}

// The film-to-rear-vertex distance b that images the axis point at `focus` (from the film):
// 1 / s_o + 1 / s_i = 1 / f with s_i = b + h and s_o = focus - (b + d - h), by bisection.
double thinLensFilmDistance(double focus) {
    const double f = focalLength(), h = principalInset();
    double lo = f * 0.5, hi = f * 3;
    for (int i = 0; i < 200; ++i) {
        const double b = 0.5 * (lo + hi);
        const double g = 1 / (focus - (b + kD - h)) + 1 / (b + h) - 1 / f;
        (g > 0 ? lo : hi) = b;  // g falls as b grows
    }
    return 0.5 * (lo + hi);
}

LensSystem biconvex(double focus) {
    return LensSystem(parseLensFile(kBiconvex, "biconvex.dat"), 0, focus, 0.035);
}

TEST(RealisticCamera, AThinElementFocusesWhereTheLensMakersEquationSays) {
    for (const double focus : {0.5, 2.0, 10.0}) {
        const LensSystem lens = biconvex(focus);
        EXPECT_NEAR(lens.filmDistance(), thinLensFilmDistance(focus), 1e-6) << focus;
        // A paraxial ray parallel to the axis crosses it at the focal length behind the rear
        // principal plane.
        const auto out = lens.traceFromScene({{1e-5, 0, 1}, {0, 0, -1}});
        ASSERT_TRUE(out);
        const double t = -out->origin.x / out->direction.x;
        const double crossing = out->origin.z + t * out->direction.z;
        EXPECT_NEAR(lens.filmDistance() + principalInset() - crossing, focalLength(), 1e-6);
    }
    EXPECT_NEAR(focalLength(), 0.10005, 1e-7);  // 1 / (0.5 (20 - 0.01)) m
    // Nearer than twice the focal length there is no focus the iteration reaches: refused.
    EXPECT_THROW(biconvex(0.15), InputError);
}

std::string pointScene(double focus, const std::string& lensFile) {
    return R"({"camera": {"type": "realistic", "position": [0, 0, 0], "look_at": [0, 0, 1],
                          "lens_file": ")" +
           lensFile + R"(", "focus_distance": )" + std::to_string(focus) + R"(},
               "film": {"resolution": [65, 65]},
               "sampler": {"spp": 256, "seed": 5},
               "shapes": [{"type": "sphere", "center": [0, 0, 2], "radius": 0.002,
                           "material": {"type": "lambert", "reflectance": 0},
                           "emission": {"radiance": 1000}}]})";
}

class RealisticCameraRender : public lamina::testing::ScratchDirectoryTest {};

TEST_F(RealisticCameraRender, AnInFocusPointIsSharpAndADefocusedOneSpreads) {
    const std::string file = write("biconvex.dat", kBiconvex).string();
    const auto centralShare = [&](double focus) {
        const SceneDesc scene = lamina::testing::sceneFromText(pointScene(focus, file));
        const RenderResult r = renderScene(scene, RenderOptions{});
        double all = 0, centre = 0;
        for (int y = 0; y < 65; ++y)
            for (int x = 0; x < 65; ++x) {
                const double v = r.film->pixel(x, y)[1];
                all += v;
                if (std::abs(x - 32) <= 1 && std::abs(y - 32) <= 1) centre += v;
            }
        EXPECT_GT(all, 0.0);
        return centre / all;
    };
    EXPECT_GT(centralShare(2.0), 0.95);  // the sphere stands on the plane in focus
    EXPECT_LT(centralShare(0.5), 0.5);   // a blur circle about 7 pixels across
}

// Kolb et al.'s irradiance at film point p under a sky of radiance 1: the integral over the
// aperture disk (radius a, in the plane of the rear vertex at distance b) of cos^4 / b^2, in
// polar coordinates about the axis (midpoint rule, 400 x 400).
double irradiance(double px, double py, double b) {
    constexpr int n = 400;
    double sum = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double rho = (i + 0.5) / n * kA, phi = (j + 0.5) / n * 2 * kPi<double>;
            const double dx = rho * std::cos(phi) - px, dy = rho * std::sin(phi) - py;
            const double c2 = b * b / (b * b + dx * dx + dy * dy);
            sum += c2 * c2 / (b * b) * rho * (kA / n) * (2 * kPi<double> / n);
        }
    return sum;
}

TEST_F(RealisticCameraRender, AUniformSkyFallsOffAsTheApertureIntegral) {
    const std::string file = write("biconvex.dat", kBiconvex).string();
    const SceneDesc scene = lamina::testing::sceneFromText(
        R"({"camera": {"type": "realistic", "position": [0, 0, 0], "look_at": [0, 0, 1],
                       "lens_file": ")" +
        file + R"(", "focus_distance": 2, "film_diagonal": 100},
            "film": {"resolution": [33, 33]},
            "sampler": {"spp": 1024, "seed": 7},
            "lights": [{"type": "environment", "radiance": 1}]})");
    const RenderResult r = renderScene(scene, RenderOptions{});
    const double b = scene.camera.lensSystem->filmDistance();
    const double side = 0.1 / std::sqrt(2.0);  // a square film of diagonal 100 mm
    double centre = 0, corner = 0;
    for (int k = 0; k < 33; ++k)
        for (const auto& [x, y] : {std::pair{k, 16}, std::pair{k, k}}) {
            const double px = (x + 0.5) / 33 * side - side / 2,
                         py = (y + 0.5) / 33 * side - side / 2;
            const double expected = irradiance(px, py, b);
            const double sigma = std::sqrt(r.film->varianceOfMean(x, y));
            EXPECT_NEAR(r.film->pixel(x, y)[1], expected, 4 * sigma + 0.01 * expected)
                << x << ", " << y;
            if (x == 16 && y == 16) centre = expected;
            if (x == 0 && y == 0) corner = expected;
        }
    // The closed form at the centre, pi a^2 / (a^2 + b^2), and a real fall-off to the corner.
    EXPECT_NEAR(irradiance(0, 0, b), kPi<double> * kA * kA / (kA * kA + b * b), 1e-6);
    EXPECT_LT(corner, 0.9 * centre);
}

TEST(LensFile, HostileFilesAreRefusedWithOneLine) {
    const auto error = [](const std::string& text) {
        return lamina::testing::errorOf([&] { parseLensFile(text, "l.dat"); });
    };
    EXPECT_EQ(error(""), "l.dat: a lens file without interfaces");
    EXPECT_EQ(error("# only a comment\n"), "l.dat: a lens file without interfaces");
    EXPECT_EQ(error("1 2 3\n"),
              "l.dat:1: expected four numbers (radius, thickness, index, aperture diameter in "
              "mm), got 3");
    EXPECT_EQ(error("10 1 1.5 5 7\n"),
              "l.dat:1: expected four numbers (radius, thickness, index, aperture diameter in "
              "mm), got more");
    EXPECT_EQ(error("10 1 1.5 5\nnan 1 1 5\n"),
              "l.dat:2: expected four finite numbers (radius, thickness, index, aperture "
              "diameter in mm), got \"nan\"");
    EXPECT_EQ(error("10 1x 1.5 5\n"),
              "l.dat:1: expected four finite numbers (radius, thickness, index, aperture "
              "diameter in mm), got \"1x\"");
    EXPECT_EQ(error("1e300 1 1.5 5\n"),
              "l.dat:1: the curvature radius must be below 1e5 mm in magnitude");
    EXPECT_EQ(error("10 -1 1.5 5\n"), "l.dat:1: the thickness must be in [0, 1e5) mm");
    EXPECT_EQ(error("10 1 1.5 0\n"), "l.dat:1: the aperture diameter must be in (0, 1e5) mm");
    EXPECT_EQ(error("10 1 0.5 5\n"),
              "l.dat:1: the index of refraction must be 0 (air) or in [1, 4]");
    EXPECT_EQ(error("0 1 0 5\n0 1 0 5\n"),
              "l.dat:2: a second aperture stop (radius 0): a lens system has one");
    EXPECT_EQ(error("2 1 1.5 5\n"),
              "l.dat:1: the aperture diameter is wider than the sphere of its curvature radius");
    std::string many;
    for (int i = 0; i < 65; ++i)
        many += "10 1 1.5 5\n";
    EXPECT_EQ(error(many), "l.dat:65: more than 64 interfaces");
    EXPECT_EQ(error(std::string(70000, ' ')), "l.dat: a lens file of more than 65536 bytes");
    // A diverging lens has no real image to focus: refused when the camera is made.
    EXPECT_THROW(LensSystem(parseLensFile("-50 1 1.5 20\n50 50 1 20\n", "l.dat"), 0, 2, 0.035),
                 InputError);
}

TEST_F(RealisticCameraRender, LightTracingAndBdptRefuseIt) {
    const std::string file = write("biconvex.dat", kBiconvex).string();
    const SceneDesc scene = lamina::testing::sceneFromText(pointScene(2, file));
    RenderOptions o;
    o.integrator = IntegratorKind::Bdpt;
    EXPECT_EQ(lamina::testing::errorOf([&] { renderScene(scene, o); }),
              "<test scene>: camera.type: the realistic camera renders with the path integrator "
              "only (light tracing and BDPT connect to the lens by its importance, which a lens "
              "system has in no closed form); use \"integrator\": {\"type\": \"path\"}");
}

}  // namespace
}  // namespace lamina::render
