// Mitsuba 3's `bsplinecurve` and `linearcurve` shapes (mitsuba3 src/shapes/bsplinecurve.cpp,
// linearcurve.cpp) and `hair` BSDF (src/bsdfs/hair.cpp) in the importer: the control points
// after the change of basis against values computed by hand, the radii left as the file gives
// them by to_world (Mitsuba's rule) as widths per control point, the warnings and refusals, the
// hair parameters as lamina's; and in the geometry, the imported curves hide what the closed
// form says (a straight tube seen along a normal hides length x 2 r of the window) and what the
// same curve written by hand as lamina Bezier curves hides.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/geometry/geometry.h"
#include "lamina/interchange/mitsuba_curve_file.h"
#include "lamina/interchange/scene_import.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::errorOf;
using ::testing::HasSubstr;

class MitsubaCurves : public lamina::testing::ScratchDirectoryTest {
  protected:
    std::filesystem::path scene(const std::string& body) {
        return write("scene.xml", "<scene version=\"3.0.0\">\n" + body +
                                      "\n<emitter type=\"constant\"/>\n</scene>\n");
    }
    ImportedScene import(const std::string& body) { return importScene(scene(body), dir_); }
    std::string error(const std::string& body) {
        const auto file = scene(body);
        return errorOf([&] { importScene(file, dir_); });
    }
    std::string where(int line) const {
        return (dir_ / "scene.xml").string() + ":" + std::to_string(line);
    }
    static std::vector<std::string> warningsWith(const ImportedScene& s, const std::string& text) {
        std::vector<std::string> out;
        for (const auto& w : s.warnings)
            if (w.find(text) != std::string::npos) out.push_back(w);
        return out;
    }
    static std::string curve(const std::string& type, const std::string& inside = "") {
        return "<shape type=\"" + type + "\"><string name=\"filename\" value=\"c.txt\"/>" + inside +
               "</shape>";
    }
};

void expectPoints(const Json& strand, const std::vector<std::array<double, 3>>& expected) {
    ASSERT_EQ(strand.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(strand[i][std::size_t(c)].get<double>(), expected[i][std::size_t(c)], 1e-12)
                << "control point " << i << ", coordinate " << c;
}

void expectWidths(const Json& widths, const std::vector<double>& expected) {
    ASSERT_EQ(widths.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
        EXPECT_NEAR(widths[i].get<double>(), expected[i], 1e-12) << "width " << i;
}

// Five B-spline control points P0..P4 with radii: two segments. By hand, with the uniform
// cubic B-spline's Bezier points (P0 + 4 P1 + P2) / 6, (2 P1 + P2) / 3, (P1 + 2 P2) / 3,
// (P1 + 4 P2 + P3) / 6 (and the same of the radii), then to_world = scale 2, translate (1, 2, 3)
// on the positions only.
constexpr const char* kFiveBspline = "0 0 0 0.1\n6 0 0 0.1\n6 6 0 0.4\n0 6 0 0.1\n0 12 6 0.7\n";
const std::vector<std::array<double, 3>> kFiveBezier = {{5, 1, 0}, {6, 2, 0}, {6, 4, 0}, {5, 5, 0},
                                                        {4, 6, 0}, {2, 6, 0}, {1, 7, 1}};
const std::vector<double> kFiveWidths = {0.3, 0.4, 0.6, 0.6, 0.6, 0.4, 0.5};

TEST_F(MitsubaCurves, BsplineSegmentsBecomeTheirBezierControlPointsInWorldSpace) {
    write("c.txt",
          std::string("\n") + kFiveBspline + "\n  \t\n-1 0 0 1\n-0.3 0 0 1\n0.3 0 0 1\n1 0 0 1\n");
    const ImportedScene s = import(curve(
        "bsplinecurve",
        "<transform name=\"to_world\"><scale value=\"2\"/><translate x=\"1\" y=\"2\" z=\"3\"/>"
        "</transform>"));
    const Json& shape = s.scene["shapes"][0];
    EXPECT_EQ(shape["type"], "curves");
    EXPECT_EQ(shape["curve"], "cylinder");
    EXPECT_FALSE(shape.contains("transform"));  // world space: lamina would scale the widths
    EXPECT_FALSE(shape.contains("width"));
    ASSERT_EQ(shape["strands"].size(), 2u);
    std::vector<std::array<double, 3>> placed;
    for (const auto& p : kFiveBezier)
        placed.push_back({2 * p[0] + 1, 2 * p[1] + 2, 2 * p[2] + 3});
    expectPoints(shape["strands"][0], placed);
    expectWidths(shape["widths"][0], kFiveWidths);  // not doubled by the scale
    // The second curve: one segment, x = (-1 - 1.2 + 0.3) / 6, (-0.6 + 0.3) / 3, (-0.3 + 0.6) / 3,
    // (-0.3 + 1.2 + 1) / 6.
    expectPoints(shape["strands"][1], {{2 * -1.9 / 6 + 1, 2, 3},
                                       {2 * -0.1 + 1, 2, 3},
                                       {2 * 0.1 + 1, 2, 3},
                                       {2 * 1.9 / 6 + 1, 2, 3}});
    expectWidths(shape["widths"][1], {2, 2, 2, 2});
    EXPECT_EQ(s.inputFiles.back(), dir_ / "c.txt");
    EXPECT_TRUE(warningsWith(s, "curve").empty());  // the same surface: nothing to say
}

TEST_F(MitsubaCurves, LinearSegmentsAreBezierSegmentsWithPointsAtThirds) {
    write("c.txt", "0 0 0 0.3\n3 0 0 0.6\n3 3 0 0.3\n");
    const ImportedScene s = import(curve("linearcurve"));
    const Json& shape = s.scene["shapes"][0];
    expectPoints(shape["strands"][0],
                 {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {3, 2, 0}, {3, 3, 0}});
    expectWidths(shape["widths"][0], {0.6, 0.8, 1.0, 1.2, 1.0, 0.8, 0.6});
    EXPECT_EQ(warningsWith(s, where(2) + ": linearcurve became straight Bezier tubes: "
                                         "Mitsuba's spherical joints and end caps are not drawn")
                  .size(),
              1u);
}

TEST_F(MitsubaCurves, BadCurveFilesAreRefusedNamingTheirLine) {
    const std::string file = (dir_ / "c.txt").string();
    write("c.txt", "0 0 0 1\n1 0 0 1\n2 0 0 1\n\n");
    EXPECT_EQ(error(curve("bsplinecurve")),
              file + ":4: a curve of 3 control points; each curve takes at least 4");
    EXPECT_EQ(error(curve("linearcurve")), "(accepted)");  // a polyline takes 2
    write("c.txt", "0 0 0 1\n1 0 0\n");
    EXPECT_EQ(error(curve("linearcurve")),
              file +
                  ":2: expected a control point \"x y z radius\" (four numbers) or a blank "
                  "line between curves");
    write("c.txt", "0 0 0 1\n1 0 0 1 # a comment\n");
    EXPECT_THAT(error(curve("linearcurve")), HasSubstr(file + ":2: expected a control point"));
    write("c.txt", "0 0 0 1\n1 0 0 -1\n");
    EXPECT_EQ(error(curve("linearcurve")), file + ":2: a negative radius");
    write("c.txt", "0 0 nan 1\n1 0 0 1\n");
    EXPECT_THAT(error(curve("linearcurve")), HasSubstr(file + ":1: a coordinate or radius"));
    write("c.txt", std::string(2000, ' ') + "\n");
    EXPECT_THAT(error(curve("linearcurve")), HasSubstr(file + ":1: a line longer than 1024"));
    write("c.txt", "\n\n");
    EXPECT_EQ(error(curve("linearcurve")), file + ": no control points (an empty curve file)");
    EXPECT_EQ(error("<shape type=\"bsplinecurve\"/>"),
              where(2) +
                  ": <shape type=\"bsplinecurve\">: needs a filename (the curve file: "
                  "\"x y z radius\" lines)");
    write("c.txt", "0 0 0 1\n1 0 0 1\n");
    EXPECT_EQ(error(curve("linearcurve", "<emitter type=\"area\"/>")),
              where(2) +
                  ": <emitter type=\"area\">: an emitting curve is not supported (lamina's "
                  "curves do not emit)");
}

TEST_F(MitsubaCurves, ATexturedMaterialOnCurvesIsWarnedOf) {
    write("c.txt", "0 0 0 1\n1 0 0 1\n");
    const ImportedScene s = import(R"(<bsdf type="diffuse" id="m">
<texture name="reflectance" type="checkerboard"/></bsdf>
)" + curve("linearcurve", "<ref id=\"m\"/>"));
    EXPECT_EQ(warningsWith(s, "a texture on the curves lands elsewhere").size(), 1u);
    const ImportedScene plain = import(curve("linearcurve"));
    EXPECT_TRUE(warningsWith(plain, "texture").empty());
}

// ---- hair -----------------------------------------------------------------------------------

TEST_F(MitsubaCurves, HairTakesMitsubasDefaultsExplicitly) {
    const ImportedScene s = import("<bsdf type=\"hair\" id=\"h\"/>");
    // Mitsuba's pheomelanin default is 0.2 (lamina's 0) and its index amber / air.
    Json expected = Json::parse(R"({"type": "hair", "eumelanin": 1.3, "pheomelanin": 0.2})");
    expected["eta"] = 1.55 / 1.000277;
    EXPECT_EQ(s.scene["materials"]["h"], expected);
}

TEST_F(MitsubaCurves, HairParametersAreLaminasBetaAndAlpha) {
    const ImportedScene s = import(R"(<bsdf type="hair" id="h">
<float name="longitudinal_roughness" value="0.25"/><float name="azimuthal_roughness" value="0.6"/>
<float name="scale_tilt" value="3"/><float name="int_ior" value="1.6"/><float name="ext_ior" value="1"/>
<rgb name="sigma_a" value="0.2, 0.25, 0.7"/><float name="scale" value="2"/></bsdf>)");
    EXPECT_EQ(s.scene["materials"]["h"], Json::parse(R"({"type": "hair", "beta_m": 0.25,
        "beta_n": 0.6, "alpha": 3.0, "eta": 1.6, "sigma_a": [0.4, 0.5, 1.4]})"));
}

TEST_F(MitsubaCurves, HairRefusalsAndWarnings) {
    EXPECT_EQ(error("<bsdf type=\"hair\" id=\"h\">\n<float name=\"eumelanin\" value=\"1\"/>"
                    "<rgb name=\"sigma_a\" value=\"1\"/></bsdf>"),
              where(2) +
                  ": <bsdf type=\"hair\">: give sigma_a or eumelanin and pheomelanin, not "
                  "both (as Mitsuba)");
    EXPECT_EQ(error("<bsdf type=\"hair\" id=\"h\">"
                    "<float name=\"longitudinal_roughness\" value=\"1.5\"/></bsdf>"),
              where(2) +
                  ": <bsdf type=\"hair\">: longitudinal_roughness must be in [0, 1] (as "
                  "Mitsuba asks)");
    EXPECT_THAT(error("<bsdf type=\"hair\" id=\"h\">\n<float name=\"eta\" value=\"1.5\"/></bsdf>"),
                HasSubstr(where(3) + ": <bsdf type=\"hair\">: parameter \"eta\" is not supported"));
    EXPECT_EQ(error("<bsdf type=\"hair\" id=\"h\"><float name=\"int_ior\" value=\"1\"/></bsdf>"),
              where(2) +
                  ": <bsdf type=\"hair\">: int_ior / ext_ior must be in (1, 5] (a fibre "
                  "denser than its surroundings)");
    const ImportedScene s = import(R"(<bsdf type="hair" id="h">
<float name="azimuthal_roughness" value="0.001"/><float name="scale" value="3"/></bsdf>)");
    EXPECT_EQ(warningsWith(s, "azimuthal_roughness 0.001 became 0.01").size(), 1u);
    EXPECT_EQ(warningsWith(s, "scale ignored").size(), 1u);
    EXPECT_EQ(s.scene["materials"]["h"]["beta_n"], 0.001);
}

// ---- the geometry -------------------------------------------------------------------------

// The fraction of a window [-2, 2] x [-1, 1] in the plane z = 5 whose rays straight down (an
// orthographic view along -z) meet a shape: the area the shapes hide over the window's 8.
double hiddenFraction(const SceneDesc& scene) {
    const Geometry g(scene);
    constexpr int nx = 800, ny = 400;
    int hits = 0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            hits += g.intersect(Vec3f(-2 + 4 * (i + 0.5f) / nx, -1 + 2 * (j + 0.5f) / ny, 5),
                                Vec3f(0, 0, -1))
                        .has_value();
    return double(hits) / (nx * ny);
}

TEST_F(MitsubaCurves, AStraightImportedBsplineHidesLengthTimesDiameter) {
    // Collinear, evenly spaced: the B-spline runs from (P0 + 4 P1 + P2) / 6 = -0.5 to 0.5 in
    // the file, -1 to 1 once scaled by 2; the radius stays 0.25 (Mitsuba leaves radii alone).
    // Seen from above, the open tube hides 2 x 0.5 = 1 of the window's 8.
    write("c.txt", "-1.5 0 0 0.25\n-0.5 0 0 0.25\n0.5 0 0 0.25\n1.5 0 0 0.25\n");
    const SceneDesc s = loadScene(scene(
        curve("bsplinecurve", "<transform name=\"to_world\"><scale value=\"2\"/></transform>")));
    const double hidden = hiddenFraction(s);
    std::printf("  hidden %.5f of the window (closed form 0.125)\n", hidden);
    // A grid of 800 x 400 rays over the rectangle's 4 edges: within a few rays of a row.
    EXPECT_NEAR(hidden, 0.125, 0.002);
}

TEST_F(MitsubaCurves, AnImportedBsplineHidesWhatItsBezierWrittenByHandHides) {
    // The five-point B-spline above, shrunk into the window, against kFiveBezier written as a
    // lamina strand with kFiveWidths (the same placement and scale).
    std::string file;
    const double k = 0.25;
    for (const auto& [p, r] :
         std::vector<std::pair<std::array<double, 3>, double>>{{{0, 0, 0}, 0.1},
                                                               {{6, 0, 0}, 0.1},
                                                               {{6, 6, 0}, 0.4},
                                                               {{0, 6, 0}, 0.1},
                                                               {{0, 12, 6}, 0.7}})
        file += std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) +
                " " + std::to_string(r * k) + "\n";
    write("c.txt", file);
    const SceneDesc imported =
        loadScene(scene(curve("bsplinecurve",
                              "<transform name=\"to_world\"><translate x=\"-3.5\" y=\"-4\"/>"
                              "<scale value=\"0.25\"/></transform>")));
    Json strand = Json::array(), widths = Json::array();
    for (std::size_t i = 0; i < kFiveBezier.size(); ++i) {
        strand.push_back(
            {k * (kFiveBezier[i][0] - 3.5), k * (kFiveBezier[i][1] - 4), k * kFiveBezier[i][2]});
        widths.push_back(k * kFiveWidths[i]);
    }
    const Json handWritten = {{"materials", {{"m", {{"type", "lambert"}}}}},
                              {"lights", Json::array({{{"type", "environment"}, {"radiance", 1}}})},
                              {"shapes", Json::array({{{"type", "curves"},
                                                       {"material", "m"},
                                                       {"strands", Json::array({strand})},
                                                       {"widths", Json::array({widths})}}})}};
    const SceneDesc reference = testing::sceneFromText(handWritten.dump());
    const double a = hiddenFraction(imported), b = hiddenFraction(reference);
    std::printf("  imported %.5f, by hand %.5f of the window\n", a, b);
    EXPECT_GT(a, 0.01);
    // The same control points to float rounding: the same rays, to a few at the silhouette.
    EXPECT_NEAR(a, b, 1e-4);
}

}  // namespace
}  // namespace lamina::render
