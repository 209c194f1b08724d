// Rectangle emitters are sampled by solid angle (Urena et al. 2013): the sampler matches its
// density (chi-square, significance 0.01, Sidak over the cases) from near, oblique, far (area
// fallback) and behind (two-sided) points, for a `rectangle` shape and for a quad given in
// pbrt-v4's bilinear corner order, and a scene lit by a `rectangle` renders the same
// (z-test) as by the same quad given as a `mesh` (sampled by area).
#include <gtest/gtest.h>

#include "lamina/core/chi_square_test.h"
#include "lamina/lights/area_lights.h"
#include "lamina/lights/lights.h"
#include "render_helpers.h"

namespace lamina {
namespace {

const char* kScene = R"({
  "materials": {"m": {"type": "lambert", "reflectance": 0}},
  "shapes": [{"type": "rectangle", "material": "m",
              "transform": [{"scale": [0.7, 0.4, 1]}, {"rotate": {"axis": [1, 0.3, 0], "angle": 35}},
                            {"translate": [0.2, 0.1, 2]}],
              "emission": {"radiance": 1, "two_sided": true}}]
})";

// The same kind of rectangle as a mesh whose two triangles are a pbrt-v4 bilinear patch's
// (corners p00, p10, p01, p11, the face (0, 1, 3, 2): triangles (0, 1, 3), (0, 3, 2)), so the
// light's corner and sides come from another vertex order than a `rectangle` shape's. Its
// corners are those of kScene's rectangle.
const char* kBilinearPatchScene = R"({
  "materials": {"m": {"type": "lambert", "reflectance": 0}},
  "shapes": [{"type": "mesh", "material": "m",
              "positions": [[-0.7, -0.4, 0], [0.7, -0.4, 0], [-0.7, 0.4, 0], [0.7, 0.4, 0]],
              "faces": [[0, 1, 3, 2]],
              "transform": [{"rotate": {"axis": [1, 0.3, 0], "angle": 35}},
                            {"translate": [0.2, 0.1, 2]}],
              "emission": {"radiance": 1, "two_sided": true}}]
})";

TEST(RectangleLight, SamplingMatchesItsDensity) {
    for (const char* text : {kScene, kBilinearPatchScene}) {
        const auto scene = testing::sceneFromText(text);
        render::Geometry geometry(scene);
        const render::LightSet lights(scene, geometry, render::LightSelection::Power);
        ASSERT_EQ(lights.size(), 1u);  // one light for the whole rectangle
        const render::Light& light = lights.light(0);
        const Vec3f refs[] = {{0, 0, 0}, {1.5f, -0.5f, 1.2f}, {0.2f, 0.1f, 2.6f}};
        for (const Vec3f& ref : refs) {
            ChiSquareConfig config;
            config.sampleCount = 300000;
            config.testCount = 6;
            const auto r = runChiSquareTest(
                config,
                [&](Pcg32& rng) -> std::optional<Vec3d> {
                    const auto s = light.sample(ref, Vec2f(rng.nextFloat(), rng.nextFloat()));
                    if (!s) return std::nullopt;
                    return Vec3d(s->wi);
                },
                [&](const Vec3d& w) {
                    const auto hit = geometry.intersect(ref, Vec3f(w));
                    return hit ? double(light.pdf(ref, *hit)) : 0.0;
                });
            EXPECT_TRUE(r.passed) << "from " << ref.x << "," << ref.y << "," << ref.z << ": "
                                  << r.message;
        }
    }
}

// From a point nearer the plane than the diagonal (here 1.61) the samples are uniform in solid
// angle: every one has the same density. From farther away they are drawn by area: the density
// is the area one, d^2 / (|cos| A), and varies over the rectangle. Behind a one-sided
// rectangle nothing is sampled.
TEST(RectangleLight, NearerThanItsDiagonalItIsSampledBySolidAngle) {
    const auto scene = testing::sceneFromText(kScene);
    render::Geometry geometry(scene);
    const render::LightSet lights(scene, geometry, render::LightSelection::Power);
    const render::Light& light = lights.light(0);
    const auto& m = std::get<render::MeshDesc>(scene.shapes[0]);
    const Vec3d p0(m.positions[0]), ex = Vec3d(m.positions[1]) - p0,
                                    ey = Vec3d(m.positions[3]) - p0;
    const Vec3d n = glm::normalize(glm::cross(ex, ey)), centre = p0 + 0.5 * (ex + ey);
    const double diagonal = glm::length(ex + ey), area = glm::length(glm::cross(ex, ey));
    Pcg32 rng(5);
    for (const double height : {0.3 * diagonal, 0.9 * diagonal, 1.1 * diagonal, 3.0 * diagonal})
        for (const double side : {1.0, -1.0}) {
            const Vec3f ref(centre + 0.2 * ex + side * height * n);
            double lowest = 1e300, highest = 0;
            for (int i = 0; i < 2000; ++i) {
                const auto s = light.sample(ref, Vec2f(rng.nextFloat(), rng.nextFloat()));
                ASSERT_TRUE(s);
                lowest = std::min(lowest, double(s->pdf));
                highest = std::max(highest, double(s->pdf));
                // The density pdf() gives the point hit along the sample, as MIS asks it.
                const auto hit = geometry.intersect(ref, s->wi);
                ASSERT_TRUE(hit);
                ASSERT_NEAR(light.pdf(ref, *hit), s->pdf, 1e-3 * s->pdf);
                if (height > diagonal) {
                    const Vec3d d = Vec3d(s->point) - Vec3d(ref);
                    const double byArea =
                        glm::dot(d, d) / (std::abs(glm::dot(n, glm::normalize(d))) * area);
                    ASSERT_NEAR(s->pdf, byArea, 1e-4 * byArea);
                }
            }
            if (height < diagonal)
                EXPECT_LT(highest, lowest * (1 + 1e-6)) << "height " << height;
            else
                EXPECT_GT(highest, lowest * 1.01) << "height " << height;
        }
    // One-sided, from behind: nothing.
    const auto oneSided = testing::sceneFromText(
        R"({"materials": {"m": {"type": "lambert", "reflectance": 0}},
            "shapes": [{"type": "rectangle", "material": "m", "emission": {"radiance": 1}}]})");
    const render::Geometry g1(oneSided);
    const render::LightSet l1(oneSided, g1, render::LightSelection::Power);
    for (const float z : {-0.5f, -5.0f, 0.0f}) {
        EXPECT_FALSE(l1.light(0).sample(Vec3f(0.1f, 0.2f, z), Vec2f(0.3f, 0.6f))) << z;
        EXPECT_TRUE(l1.light(0).sample(Vec3f(0.1f, 0.2f, -z + 0.5f), Vec2f(0.3f, 0.6f))) << z;
    }
}

// A one-sided rectangle under a mirroring transform is sampled from the side its triangles
// face (the side that emits when hit), for the `rectangle` shape and for a mesh face alike.
TEST(RectangleLight, AMirroredRectangleIsSampledFromTheSideItEmitsTo) {
    for (const char* shape : {R"({"type": "rectangle", "material": "m", "emission": {"radiance": 1},
              "transform": [{"scale": [-1, 1, 1]}]})",
                              R"({"type": "mesh", "material": "m", "emission": {"radiance": 1},
              "positions": [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]],
              "faces": [[0, 1, 2, 3]], "transform": [{"scale": [1, -1, 1]}]})"}) {
        const auto scene = testing::sceneFromText(
            std::string(R"({"materials": {"m": {"type": "lambert", "reflectance": 0}},
                            "shapes": [)") +
            shape + "]}");
        const render::Geometry geometry(scene);
        const render::LightSet lights(scene, geometry, render::LightSelection::Power);
        ASSERT_EQ(lights.size(), 1u) << shape;
        for (const float z : {0.5f, 3.0f, -0.5f, -3.0f}) {
            const Vec3f ref(0.1f, 0.2f, z);
            const auto hit = geometry.intersect(ref, Vec3f(0.0f, 0.0f, z > 0 ? -1.0f : 1.0f));
            ASSERT_TRUE(hit);
            const bool emitsToRef =
                !lights.light(0).radiance(*hit, glm::normalize(ref - hit->p)).isZero();
            const auto s = lights.light(0).sample(ref, Vec2f(0.4f, 0.7f));
            EXPECT_EQ(s.has_value(), emitsToRef) << shape << " z " << z;
            if (s) {
                EXPECT_GT(glm::dot(s->normal, hit->ng), 0.99f);
            }
        }
    }
}

TEST(RectangleLight, FarAwayTheAreaFallbackIsUnbiased) {
    // From far away (solid angle below 1e-4 sr) the light is sampled by area; E[1 / pdf] over
    // its samples is the solid angle, A cos(theta) / d^2 to first order.
    const auto scene = testing::sceneFromText(kScene);
    render::Geometry geometry(scene);
    const render::LightSet lights(scene, geometry, render::LightSelection::Power);
    const Vec3f ref(0.2f, 0.1f, -120.0f);
    Pcg32 rng(3);
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const auto s = lights.light(0).sample(ref, Vec2f(rng.nextFloat(), rng.nextFloat()));
        ASSERT_TRUE(s);
        sum += 1.0 / s->pdf;
    }
    const auto& m = std::get<render::MeshDesc>(scene.shapes[0]);
    const Vec3<double> ex(m.positions[1] - m.positions[0]), ey(m.positions[3] - m.positions[0]);
    const Vec3<double> n0 = glm::normalize(glm::cross(ex, ey));
    const Vec3<double> centre = Vec3<double>(m.positions[0]) + 0.5 * (ex + ey);
    const Vec3<double> d = centre - Vec3<double>(ref);
    const double expected = glm::length(glm::cross(ex, ey)) *
                            std::abs(glm::dot(n0, glm::normalize(d))) / glm::dot(d, d);
    EXPECT_LT(expected, 1e-4);
    EXPECT_NEAR(sum / n, expected, 1e-3 * expected);
}

TEST(RectangleLight, RendersTheSameAsTheQuadSampledByArea) {
    auto sceneWith = [](const std::string& light) {
        return R"({
          "camera": {"position": [0, 1, -3], "look_at": [0, 0.5, 0], "fov": 50},
          "film": {"resolution": [24, 24]},
          "materials": {"grey": {"type": "lambert", "reflectance": 0.5},
                        "lamp": {"type": "lambert", "reflectance": 0}},
          "shapes": [
            {"type": "rectangle", "material": "grey",
             "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"scale": 4}]},
            {"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5, "material": "grey"},
            )" +
               light + R"(]})";
    };
    const auto rectScene = testing::sceneFromText(sceneWith(
        R"({"type": "rectangle", "material": "lamp", "emission": {"radiance": 5},
            "transform": [{"scale": [0.5, 0.3, 1]}, {"rotate": {"axis": [1, 0, 0], "angle": 90}},
                          {"translate": [0.3, 2, 0.2]}]})"));
    // The same quad: after the transform its corners are (x, 2, z) with x in [-0.2, 0.8],
    // z in [-0.1, 0.5], facing down; given as two triangles that share no vertex (six
    // vertices, not four), so they are two triangle lights sampled by area.
    const auto meshScene = testing::sceneFromText(sceneWith(
        R"({"type": "mesh", "material": "lamp", "emission": {"radiance": 5},
            "positions": [[-0.2, 2, -0.1], [0.8, 2, -0.1], [0.8, 2, 0.5],
                          [0.8, 2, 0.5], [-0.2, 2, 0.5], [-0.2, 2, -0.1]],
            "faces": [[0, 1, 2], [3, 4, 5]]})"));
    auto lightCount = [](const render::SceneDesc& scene) {
        const render::Geometry geometry(scene);
        return render::LightSet(scene, geometry, render::LightSelection::Bvh).size();
    };
    ASSERT_EQ(lightCount(rectScene), 1u);
    ASSERT_EQ(lightCount(meshScene), 2u);
    render::RenderOptions options;
    options.spp = 128;
    const auto rect = render::renderScene(rectScene, options);
    options.seed = 99;
    const auto mesh = render::renderScene(meshScene, options);
    for (int c = 0; c < 3; ++c) {
        const auto a = testing::imageMean(*rect.film, c), b = testing::imageMean(*mesh.film, c);
        EXPECT_LT(std::abs(a.mean - b.mean), 3.29 * std::hypot(a.standardError, b.standardError))
            << "rectangle " << a.mean << " mesh " << b.mean;
        EXPECT_GT(a.mean, 0.01);
    }
}

// A mesh of four vertices and two triangles is one rectangle light when the triangles make a
// rectangle: the fan of a face (the Cornell box's lamp), also under a mirroring transform
// (which reverses the winding), the other diagonal, the triangles in another order, a pbrt-v4
// bilinear patch's corner order. It stays two triangle lights otherwise: a parallelogram, a
// quad whose fourth corner is off the rectangle, triangles facing opposite sides, two
// triangles sharing only a corner.
TEST(RectangleLight, AMeshFaceIsOneLightExactlyWhenItIsARectangle) {
    auto lightsOf = [](const std::string& positions, const std::string& faces,
                       const std::string& transform = "[]") {
        const auto scene = testing::sceneFromText(
            R"({"materials": {"m": {"type": "lambert", "reflectance": 0}},
                "shapes": [{"type": "mesh", "material": "m", "emission": {"radiance": 1},
                            "positions": )" +
            positions + R"(, "faces": )" + faces + R"(, "transform": )" + transform + "}]}");
        const render::Geometry geometry(scene);
        return render::LightSet(scene, geometry, render::LightSelection::Bvh).size();
    };
    const std::string square = "[[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0]]";
    EXPECT_EQ(lightsOf(square, "[[0, 1, 2, 3]]"), 1u);
    EXPECT_EQ(
        lightsOf(square, "[[0, 1, 2, 3]]",
                 R"([{"rotate": {"axis": [1, 2, 3], "angle": 40}}, {"translate": [5, 0, 1]}])"),
        1u);
    EXPECT_EQ(lightsOf(square, "[[0, 1, 2], [2, 3, 0]]"), 1u);
    EXPECT_EQ(lightsOf(square, "[[0, 1, 3], [1, 2, 3]]"), 1u);
    EXPECT_EQ(lightsOf(square, "[[1, 2, 3], [0, 1, 3]]"), 1u);
    EXPECT_EQ(lightsOf(square, "[[3, 2, 1, 0]]"), 1u);
    // pbrt-v4's p00, p10, p01, p11 as the importer writes them (the face 0, 1, 3, 2).
    EXPECT_EQ(lightsOf("[[0, 0, 0], [2, 0, 0], [0, 1, 0], [2, 1, 0]]", "[[0, 1, 3, 2]]"), 1u);
    EXPECT_EQ(lightsOf(square, "[[0, 1, 2], [0, 3, 2]]"), 2u);  // opposite sides
    EXPECT_EQ(lightsOf("[[0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0], [4, 0, 0]]",
                       "[[0, 1, 2], [1, 4, 2]]"),
              2u);  // five vertices
    EXPECT_EQ(lightsOf(square, "[[0, 1, 2, 3]]", R"([{"scale": [-1, 1, 1]}])"), 1u);
    EXPECT_EQ(lightsOf("[[0, 0, 0], [2, 0, 0], [2.5, 1, 0], [0.5, 1, 0]]", "[[0, 1, 2, 3]]"), 2u);
    EXPECT_EQ(lightsOf("[[0, 0, 0], [2, 0, 0], [2, 1, 0.01], [0, 1, 0]]", "[[0, 1, 2, 3]]"), 2u);
    EXPECT_EQ(lightsOf("[[0, 0, 0], [2, 0, 0], [2.01, 1, 0], [0, 1, 0]]", "[[0, 1, 2, 3]]"), 2u);

    // The corners in boundary order from vertex 0 towards its lower neighbour, whichever way
    // the triangles run; none for a degenerate triangle or triangles sharing one corner.
    auto corners = [](std::vector<std::array<std::uint32_t, 3>> triangles) {
        render::MeshDesc m;
        m.positions.assign(4, Vec3f(0.0f));
        m.triangles = std::move(triangles);
        return render::RectangleLight::quadCorners(m);
    };
    using Q = render::RectangleLight::QuadCorners;
    EXPECT_EQ(corners({{0, 1, 2}, {0, 2, 3}}), (Q{0, 1, 2, 3}));
    EXPECT_EQ(corners({{0, 2, 1}, {0, 3, 2}}), (Q{0, 1, 2, 3}));
    EXPECT_EQ(corners({{2, 3, 0}, {0, 1, 2}}), (Q{0, 1, 2, 3}));
    EXPECT_EQ(corners({{0, 1, 3}, {0, 3, 2}}), (Q{0, 1, 3, 2}));
    EXPECT_EQ(corners({{0, 1, 2}, {2, 3, 2}}), std::nullopt);
    EXPECT_EQ(corners({{0, 1, 2}, {0, 2, 1}}), std::nullopt);
    EXPECT_EQ(corners({{0, 1, 2}, {0, 3, 2}}), std::nullopt);

    const render::SceneDesc box = render::loadScene(testing::sourceFile("scenes/cornell-box.json"));
    const render::Geometry geometry(box);
    EXPECT_EQ(render::LightSet(box, geometry, render::LightSelection::Bvh).size(), 1u);
}

}  // namespace
}  // namespace lamina
