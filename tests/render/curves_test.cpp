// The `curves` shape in the geometry (curve_geometry.h, Embree's round and flat Bezier curves):
// a ray meets a straight tube where the closed form says, with the normal out of the axis and
// the tangent along it; a ray from inside meets the far wall (the hair material's tubes let
// light through that way); a flat ribbon faces the ray with a tube's shading normal; widths
// taper, or follow the widths given per control point; instances carry the tangent. The reader
// refuses what is not a strand, naming the path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lamina/geometry/geometry.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using ::testing::HasSubstr;

SceneDesc sceneWith(const std::string& shape, const std::string& objects = "") {
    return testing::sceneFromText(R"({
      "materials": {"m": {"type": "hair"}},
      "lights": [{"type": "point", "position": [0, 0, 100], "intensity": 1}],)" +
                                  objects + R"("shapes": [{"material": "m", )" + shape + "}]}");
}

// A straight strand along x from -2 to 2 (control points evenly spaced: a straight segment).
constexpr const char* kStraight = R"("type": "curves", "width": 0.5,
    "strands": [[[-2, 0, 0], [-0.6667, 0, 0], [0.6667, 0, 0], [2, 0, 0]]])";

void expectNear(const Vec3f& a, const Vec3f& b, float tolerance) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(CurveHits, ARoundTubeIsHitAtItsRadiusWithItsTangent) {
    const SceneDesc scene = sceneWith(kStraight);
    ASSERT_TRUE(std::holds_alternative<CurvesDesc>(scene.shapes[0]));
    const Geometry g(scene);
    // From above, off the axis by 0.15 in y: the tube of radius 0.25 at z = sqrt(r^2 - y^2).
    const auto hit = g.intersect(Vec3f(0.3f, 0.15f, 5), Vec3f(0, 0, -1));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 5 - 0.2f, 1e-3f);
    expectNear(hit->p, Vec3f(0.3f, 0.15f, 0.2f), 1e-3f);
    expectNear(hit->ng, Vec3f(0, 0.6f, 0.8f), 1e-3f);
    EXPECT_EQ(hit->ng, hit->ns);
    expectNear(hit->tangent, Vec3f(1, 0, 0), 1e-5f);
    EXPECT_NEAR(hit->uv.x, 0.575f, 1e-3f);  // x = 0.3 of [-2, 2]
    // Beside the tube: a miss.
    EXPECT_FALSE(g.intersect(Vec3f(0.3f, 0.3f, 5), Vec3f(0, 0, -1)));
    EXPECT_FALSE(g.occluded(Vec3f(0.3f, 0.3f, 5), Vec3f(0, 0, -1), 10));
    EXPECT_TRUE(g.occluded(Vec3f(0.3f, 0.15f, 5), Vec3f(0, 0, -1), 10));
}

TEST(CurveHits, ARayFromInsideMeetsTheFarWallFacingOutwards) {
    const SceneDesc scene = sceneWith(kStraight);  // the geometry keeps a reference
    const Geometry g(scene);
    const auto hit = g.intersect(Vec3f(0, 0, 0.2f), Vec3f(0, 0, -1));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 0.45f, 1e-3f);
    expectNear(hit->ng, Vec3f(0, 0, -1), 1e-3f);  // outward: the ray meets it from inside
}

TEST(CurveHits, AFlatRibbonFacesTheRayWithATubesShadingNormal) {
    const SceneDesc scene = sceneWith(std::string(kStraight) + R"(, "curve": "flat")");
    const Geometry g(scene);
    const auto hit = g.intersect(Vec3f(0.3f, 0.15f, 5), Vec3f(0, 0, -1));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 5.0f, 1e-3f);  // the ribbon through the axis
    expectNear(hit->ng, Vec3f(0, 0, 1), 1e-5f);
    expectNear(hit->ns, Vec3f(0, 0.6f, 0.8f), 2e-3f);
    expectNear(hit->tangent, Vec3f(1, 0, 0), 1e-5f);
}

TEST(CurveHits, WidthsTaperFromRootToTip) {
    const SceneDesc scene = sceneWith(R"("type": "curves", "width0": 0.8, "width1": 0.2,
        "strands": [[[-2, 0, 0], [-0.6667, 0, 0], [0.6667, 0, 0], [2, 0, 0]]])");
    const Geometry g(scene);
    const auto root = g.intersect(Vec3f(-1.5f, 0, 5), Vec3f(0, 0, -1));
    const auto tip = g.intersect(Vec3f(1.5f, 0, 5), Vec3f(0, 0, -1));
    ASSERT_TRUE(root && tip);
    EXPECT_NEAR(root->p.z, 0.5f * (0.8f - 0.6f * 0.5f / 4), 2e-3f);  // radius at x = -1.5
    EXPECT_NEAR(tip->p.z, 0.5f * (0.8f - 0.6f * 3.5f / 4), 2e-3f);
}

TEST(CurveHits, WidthsPerControlPointRunWithTheBezierBasis) {
    // Widths at the control points 0.2, 0.6, 1.0, 1.4 (evenly spaced, as the points are): the
    // Bezier interpolation of them is 0.2 + 1.2 t, t = (x + 2) / 4 along the straight strand.
    const SceneDesc scene = sceneWith(R"("type": "curves", "widths": [[0.2, 0.6, 1.0, 1.4]],
        "strands": [[[-2, 0, 0], [-0.6667, 0, 0], [0.6667, 0, 0], [2, 0, 0]]])");
    const Geometry g(scene);
    const auto thin = g.intersect(Vec3f(-1.5f, 0, 5), Vec3f(0, 0, -1));
    const auto thick = g.intersect(Vec3f(1.5f, 0, 5), Vec3f(0, 0, -1));
    ASSERT_TRUE(thin && thick);
    EXPECT_NEAR(thin->p.z, 0.5f * (0.2f + 1.2f * 0.125f), 2e-3f);
    EXPECT_NEAR(thick->p.z, 0.5f * (0.2f + 1.2f * 0.875f), 2e-3f);
}

TEST(CurveHits, AnInstanceTurnsTheTangent) {
    const std::string objects =
        R"("objects": {"tuft": [{"material": "m", )" + std::string(kStraight) + R"(}]},)";
    const SceneDesc scene = testing::sceneFromText(R"({
      "materials": {"m": {"type": "hair"}},
      "lights": [{"type": "point", "position": [0, 0, 100], "intensity": 1}],)" +
                                                   objects + R"(
      "shapes": [{"type": "instance", "object": "tuft",
                  "transform": [{"rotate": {"axis": [0, 0, 1], "angle": 90}}]}]})");
    const Geometry g(scene);
    const auto hit = g.intersect(Vec3f(0, 1, 5), Vec3f(0, 0, -1));
    ASSERT_TRUE(hit);
    expectNear(hit->tangent, Vec3f(0, 1, 0), 1e-5f);
}

TEST(CurvesReader, RefusesWhatIsNotAStrand) {
    EXPECT_THAT(testing::errorOf([] {
                    sceneWith(R"("type": "curves", "strands": [[[0, 0, 0], [1, 0, 0], [2, 0, 0],
                        [3, 0, 0], [4, 0, 0]]])");
                }),
                HasSubstr("shapes[0].strands: expected at index 0 a strand of 3k + 1 control "
                          "points"));
    EXPECT_THAT(testing::errorOf([] { sceneWith(R"("type": "curves", "strands": [])"); }),
                HasSubstr("expected a non-empty array of strands"));
    EXPECT_THAT(testing::errorOf(
                    [] { sceneWith(std::string(kStraight) + R"(, "emission": {"radiance": 1})"); }),
                HasSubstr("curves do not emit"));
    EXPECT_THAT(testing::errorOf([] {
                    sceneWith(R"("type": "curves", "width": 0,
                        "strands": [[[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]])");
                }),
                HasSubstr("width"));
    EXPECT_THAT(testing::errorOf([] {
                    sceneWith(R"("type": "curves", "width": 0.1, "widths": [[1, 1, 1, 1]],
                        "strands": [[[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]])");
                }),
                HasSubstr("shapes[0].widths: give widths per control point or width"));
    EXPECT_THAT(testing::errorOf([] {
                    sceneWith(R"("type": "curves", "widths": [[1, 1, 1]],
                        "strands": [[[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]])");
                }),
                HasSubstr("shapes[0].widths: expected at index 0 a list of 4 widths"));
    EXPECT_THAT(testing::errorOf([] {
                    sceneWith(R"("type": "curves", "widths": [[1, 1, 1, 1], [1]],
                        "strands": [[[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]])");
                }),
                HasSubstr("shapes[0].widths: expected one list of widths per strand (1 strands)"));
    EXPECT_THAT(testing::errorOf([] {
                    sceneWith(R"("type": "curves", "widths": [[1, -1, 1, 1]],
                        "strands": [[[0, 0, 0], [1, 0, 0], [2, 0, 0], [3, 0, 0]]])");
                }),
                HasSubstr("shapes[0].widths[0][1]"));
}

}  // namespace
}  // namespace lamina::render
