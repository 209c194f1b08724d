// The Mitsuba 3 importer (docs/interchange.md, "Mitsuba 3"): the document reader (defaults,
// $name substitution, include, ref/id, scene version 0.x names), every element and plugin it
// translates, compared with the exact lamina JSON it must produce, and the errors and warnings
// with their file and line.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "lamina/core/frame.h"
#include "lamina/geometry/geometry.h"
#include "lamina/interchange/scene_import.h"
#include "lamina/lights/environment_map.h"
#include "lamina/scene/scene_readers.h"
#include "scratch_directory.h"
#include "source_files.h"

namespace lamina::render {
namespace {

class MitsubaImport : public lamina::testing::ScratchDirectoryTest {
  protected:
    // A scene file: `<scene version="3.0.0">` on line 1, `body` from line 2.
    std::filesystem::path scene(const std::string& body, const std::string& version = "3.0.0") {
        return write("scene.xml", "<scene version=\"" + version + "\">\n" + body + "\n</scene>\n");
    }
    ImportedScene import(const std::string& body, const std::string& version = "3.0.0") {
        return importScene(scene(body, version), dir_);
    }
    Json translated(const std::string& body) { return import(body).scene; }
    std::string error(const std::string& body) {
        const auto file = scene(body);
        return lamina::testing::errorOf([&] { importScene(file, dir_); });
    }
    std::string where(int line) const {
        return (dir_ / "scene.xml").string() + ":" + std::to_string(line);
    }
    // Warnings that name `text`.
    static std::vector<std::string> warningsWith(const ImportedScene& s, const std::string& text) {
        std::vector<std::string> out;
        for (const auto& w : s.warnings)
            if (w.find(text) != std::string::npos) out.push_back(w);
        return out;
    }
    static constexpr const char* kLight = "<shape type=\"sphere\"><emitter type=\"area\"/></shape>";
};

// ---- the document --------------------------------------------------------------------------

TEST_F(MitsubaImport, DefaultsAndSubstitution) {
    const Json s = translated(R"(<default name="r" value="0.25"/>
<default name="r" value="0.9"/>
<default name="kind" value="sphere"/>
<shape type="$kind"><float name="radius" value="$r"/></shape>)");
    // The first definition of a default wins (a later one, like a command-line value, does not
    // replace it).
    EXPECT_EQ(s["shapes"][0]["type"], "sphere");
    EXPECT_EQ(s["shapes"][0]["radius"], 0.25);
}

TEST_F(MitsubaImport, UndefinedSubstitutionNamesTheLine) {
    EXPECT_EQ(error("\n<shape type=\"sphere\"><float name=\"radius\" value=\"$radius\"/></shape>"),
              where(3) +
                  ": $radius is not defined (declare it with <default name=\"radius\" "
                  "value=\"...\"/> before it is used)");
}

// mitsuba3 parser.cpp substitute_parameters: the longest names first, "\$" escapes, and a
// default declared after its use (in Mitsuba's documentation scenes, by an include at the end
// of the file) does not reach back: Mitsuba refuses such a file without -D too.
TEST_F(MitsubaImport, SubstitutionAsMitsubaDoesIt) {
    const Json s = translated(R"(<default name="res" value="8"/>
<default name="resx" value="16"/>
<sensor type="perspective"><film type="hdrfilm">
  <integer name="width" value="$resx"/><integer name="height" value="$res"/></film></sensor>
<shape type="sphere" id="a\$b"/>)");
    EXPECT_EQ(s["film"]["resolution"], Json::parse("[16, 8]"));
    EXPECT_EQ(s["shapes"][0]["name"], "a$b");
    EXPECT_EQ(error("<shape type=\"sphere\"><float name=\"radius\" value=\"$r\"/></shape>\n"
                    "<default name=\"r\" value=\"1\"/>"),
              where(2) +
                  ": $r is not defined (declare it with <default name=\"r\" value=\"...\"/> "
                  "before it is used)");
}

TEST_F(MitsubaImport, IncludeSplicesTheFileAndListsIt) {
    write("part.xml", "<scene version=\"3.0.0\">\n<bsdf type=\"diffuse\" id=\"grey\"/>\n</scene>");
    const ImportedScene s = import(R"(<include filename="part.xml"/>
<shape type="sphere"><ref id="grey"/><emitter type="area"/></shape>)");
    EXPECT_EQ(s.scene["materials"]["grey"],
              Json::parse(R"({"type": "lambert", "reflectance": 0.5})"));
    EXPECT_EQ(s.scene["shapes"][0]["material"], "grey");
    ASSERT_EQ(s.inputFiles.size(), 2u);
    EXPECT_EQ(s.inputFiles[1], dir_ / "part.xml");
}

TEST_F(MitsubaImport, IncludingItselfIsRefused) {
    write("loop.xml", "<scene version=\"3.0.0\">\n<include filename=\"loop.xml\"/>\n</scene>");
    EXPECT_NE(error("<include filename=\"loop.xml\"/>").find("includes nested deeper than 16"),
              std::string::npos);
}

TEST_F(MitsubaImport, MissingIncludeNamesTheLine) {
    EXPECT_EQ(error("\n<include filename=\"absent.xml\"/>"),
              where(3) + ": cannot open " + (dir_ / "absent.xml").string());
}

TEST_F(MitsubaImport, RefToAnUnknownIdNamesTheLine) {
    EXPECT_EQ(error("<shape type=\"sphere\">\n  <ref id=\"nothing\"/>\n</shape>"),
              where(3) + ": no object has id \"nothing\" (<ref> refers to it)");
}

TEST_F(MitsubaImport, DuplicateIdNamesBothPlaces) {
    EXPECT_EQ(error("<bsdf type=\"diffuse\" id=\"a\"/>\n<bsdf type=\"diffuse\" id=\"a\"/>"),
              where(3) + ": id \"a\" is used already at " + where(2));
}

TEST_F(MitsubaImport, MalformedXmlNamesTheLine) {
    EXPECT_EQ(error("<shape type=\"sphere\">\n\n</shap>"),
              where(4) + ": malformed XML: Start-end tags mismatch");
}

TEST_F(MitsubaImport, SceneNeedsAVersion) {
    const auto file = write("v.xml", "<scene>\n</scene>");
    EXPECT_EQ(lamina::testing::errorOf([&] { importScene(file, dir_); }),
              file.string() + ":1: <scene> needs a version attribute (e.g. version=\"3.0.0\")");
}

TEST_F(MitsubaImport, NewerVersionIsRefused) {
    for (const char* version : {"4.0.0", "99999999999999999999"}) {
        const auto file = write("v.xml", std::string("<scene version=\"") + version + "\"/>");
        EXPECT_EQ(lamina::testing::errorOf([&] { importScene(file, dir_); }),
                  file.string() + ":1: scene version " + version + " is newer than Mitsuba 3");
    }
}

TEST_F(MitsubaImport, Version06NamesAreUpgraded) {
    // Mitsuba 0.6 spells parameters in camelCase: toWorld, intIOR, maxDepth, sampleCount.
    const Json s =
        import(R"(<integrator type="path"><integer name="maxDepth" value="3"/></integrator>
<shape type="sphere"><bsdf type="dielectric"><float name="intIOR" value="1.33"/>
<float name="extIOR" value="1"/></bsdf>
<transform name="toWorld"><translate x="1"/></transform></shape>)",
               "0.6.0")
            .scene;
    EXPECT_EQ(s["integrator"]["max_depth"], 2);
    EXPECT_EQ(s["shapes"][0]["material"], Json::parse(R"({"type": "dielectric", "ior": 1.33})"));
    EXPECT_EQ(s["shapes"][0]["transform"], Json::parse(R"([{"translate": [1, 0, 0]}])"));
}

TEST_F(MitsubaImport, UnknownElementNamesTheLine) {
    EXPECT_EQ(error("\n\n<light type=\"point\"/>"),
              where(4) + ": unknown element <light> in <scene>");
}

TEST_F(MitsubaImport, HugeFileIsRefusedBeforeReading) {
    const auto file = dir_ / "huge.xml";
    {
        std::ofstream out(file, std::ios::binary);
        out << "<scene version=\"3.0.0\">";
    }
    std::filesystem::resize_file(file, (std::uintmax_t(64) << 20) + 1);
    EXPECT_EQ(lamina::testing::errorOf([&] { importScene(file, dir_); }),
              file.string() + ": " + file.string() + " is larger than 64 MiB");
}

// ---- parameters and their types --------------------------------------------------------------

TEST_F(MitsubaImport, WrongParameterTypeNamesTheLine) {
    EXPECT_EQ(error("<shape type=\"sphere\">\n<string name=\"radius\" value=\"big\"/></shape>"),
              where(3) +
                  ": <shape type=\"sphere\">: parameter \"radius\" must be <float> or "
                  "<integer>, got <string>");
    EXPECT_EQ(error("<shape type=\"sphere\">\n<float name=\"radius\" value=\"big\"/></shape>"),
              where(3) + ": parameter \"radius\": expected a number, got \"big\"");
}

TEST_F(MitsubaImport, UnknownParameterIsRefused) {
    EXPECT_EQ(error("<shape type=\"sphere\">\n<float name=\"radios\" value=\"1\"/></shape>"),
              where(3) + ": <shape type=\"sphere\">: parameter \"radios\" is not supported");
}

TEST_F(MitsubaImport, UnknownAttributeIsRefused) {
    EXPECT_EQ(error("\n<shape type=\"sphere\" radius=\"2\"/>"),
              where(3) + ": <shape>: attribute \"radius\" is not supported");
    EXPECT_EQ(
        error("<shape type=\"sphere\">\n<float name=\"radius\" value=\"1\" unit=\"m\"/></shape>"),
        where(3) + ": <float>: attribute \"unit\" is not supported");
}

TEST_F(MitsubaImport, Transforms) {
    const Json s = translated(R"(<shape type="rectangle"><transform name="to_world">
<translate x="1" z="2"/>
<rotate value="0 0 1" angle="30"/>
<scale x="2" y="3"/>
<scale value="0.5"/>
<matrix value="1 0 0 4  0 1 0 5  0 0 1 6  0 0 0 1"/>
</transform>)" + std::string(kLight).substr(std::string("<shape type=\"sphere\">").size()));
    EXPECT_EQ(s["shapes"][0]["transform"], Json::parse(R"([
      {"translate": [1, 0, 2]},
      {"rotate": {"axis": [0, 0, 1], "angle": 30}},
      {"scale": [2, 3, 1]},
      {"scale": [0.5, 0.5, 0.5]},
      {"matrix": [1, 0, 0, 4, 0, 1, 0, 5, 0, 0, 1, 6, 0, 0, 0, 1]}])"));
}

TEST_F(MitsubaImport, LookAtCameraMatrix) {
    // lookat origin (1, 2, 3) towards +x with up +y: the camera's +z is world +x, its +y world
    // +y, its +x (the image's left) up x dir = -z.
    const Json s = translated(R"(<sensor type="perspective"><transform name="to_world">
<lookat origin="1, 2, 3" target="5, 2, 3" up="0, 1, 0"/></transform></sensor>)" +
                              std::string(kLight));
    EXPECT_EQ(s["camera"]["matrix"],
              Json::parse("[0, 0, 1, 1,  0, 1, 0, 2,  -1, 0, 0, 3,  0, 0, 0, 1]"));
    EXPECT_FALSE(s["camera"].contains("handedness"));
}

TEST_F(MitsubaImport, LookAtWithoutUpTakesMitsubasBasis) {
    // Mitsuba picks up = the first vector of coordinate_system(dir): for dir = +z, (1, 0, 0);
    // the camera's +x (up x dir) is then (0, -1, 0).
    const Json s = translated(R"(<sensor type="perspective"><transform name="to_world">
<lookat origin="0, 0, 0" target="0, 0, 2"/></transform></sensor>)" +
                              std::string(kLight));
    EXPECT_EQ(s["camera"]["matrix"],
              Json::parse("[0, 1, 0, 0,  -1, 0, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1]"));
}

TEST_F(MitsubaImport, MirroredCameraIsLeftHanded) {
    const Json s = translated(R"(<sensor type="perspective"><transform name="to_world">
<scale x="-1"/></transform></sensor>)" +
                              std::string(kLight));
    EXPECT_EQ(s["camera"]["handedness"], "left");
}

TEST_F(MitsubaImport, OrthographicSensorSpansItsScaledFrame) {
    // x in [-1, 1] and y in [-1 / aspect, 1 / aspect] of to_world's frame, scaled by it.
    const Json s = translated(R"(<sensor type="orthographic"><transform name="to_world">
<scale x="3" y="3"/><lookat origin="0, 0, -5" target="0, 0, 0" up="0, 1, 0"/></transform>
<film type="hdrfilm"><integer name="width" value="40"/><integer name="height" value="20"/>
</film></sensor>)" + std::string(kLight));
    EXPECT_EQ(s["camera"]["type"], "orthographic");
    EXPECT_EQ(s["camera"]["screen_window"], Json::parse("[-3, 3, -1.5, 1.5]"));
    EXPECT_FALSE(s["camera"].contains("fov"));
    EXPECT_NE(error(R"(<sensor type="orthographic"><float name="fov" value="30"/>
</sensor>)" + std::string(kLight))
                  .find("fov"),
              std::string::npos);
}

// ---- sensor, film, sampler, integrator ---------------------------------------------------------

TEST_F(MitsubaImport, FieldOfViewAxes) {
    auto fov = [&](const std::string& params) {
        return translated("<sensor type=\"perspective\">" + params +
                          "<film type=\"hdrfilm\"><integer name=\"width\" value=\"400\"/>"
                          "<integer name=\"height\" value=\"200\"/></film></sensor>" +
                          kLight)["camera"]["fov"]
            .get<double>();
    };
    // Horizontal 90 degrees on a 2:1 film: tan(v / 2) = tan(45) / 2.
    const double v90 = 2 * std::atan(0.5) * 180 / 3.14159265358979323846;
    EXPECT_NEAR(fov("<float name=\"fov\" value=\"90\"/>"), v90, 1e-9);
    EXPECT_NEAR(
        fov("<float name=\"fov\" value=\"90\"/><string name=\"fov_axis\" value=\"larger\"/>"), v90,
        1e-9);
    EXPECT_NEAR(fov("<float name=\"fov\" value=\"40\"/><string name=\"fov_axis\" value=\"y\"/>"),
                40, 1e-9);
    EXPECT_NEAR(
        fov("<float name=\"fov\" value=\"40\"/><string name=\"fov_axis\" value=\"smaller\"/>"), 40,
        1e-9);
    // 50 mm: the diagonal of 36 x 24 mm, 2 atan(43.27 / 100) = 46.8 degrees, spread over the
    // film's diagonal.
    const double diagonal = std::tan(std::atan(std::sqrt(36.0 * 36 + 24 * 24) / 100));
    EXPECT_NEAR(fov(""), 2 * std::atan(diagonal / std::sqrt(5.0)) * 180 / 3.14159265358979323846,
                1e-9);
    EXPECT_NEAR(fov("<string name=\"focal_length\" value=\"50mm\"/>"), fov(""), 1e-12);
}

TEST_F(MitsubaImport, FilmFiltersAndSamplers) {
    auto film = [&](const std::string& filter, const std::string& sampler = "") {
        return translated("<sensor type=\"perspective\"><film type=\"hdrfilm\">" + filter +
                          "</film>" + sampler + "</sensor>" + kLight);
    };
    const Json defaults = film("");
    EXPECT_EQ(defaults["film"], Json::parse(R"({"resolution": [768, 576],
        "filter": {"type": "gaussian", "radius": 2, "sigma": 0.5}})"));
    EXPECT_EQ(defaults["sampler"], Json::parse(R"({"type": "independent", "spp": 4})"));
    EXPECT_EQ(film("<rfilter type=\"box\"/>")["film"]["filter"],
              Json::parse(R"({"type": "box", "radius": 0.5})"));
    EXPECT_EQ(film("<rfilter type=\"gaussian\"><float name=\"stddev\" value=\"0.25\"/></rfilter>")
                  ["film"]["filter"],
              Json::parse(R"({"type": "gaussian", "radius": 1, "sigma": 0.25})"));
    EXPECT_EQ(film("<rfilter type=\"tent\"/>")["film"]["filter"],
              Json::parse(R"({"type": "triangle", "radius": 1})"));
    EXPECT_EQ(film("",
                   "<sampler type=\"stratified\"><integer name=\"sample_count\" value=\"16\"/>"
                   "<integer name=\"seed\" value=\"3\"/></sampler>")["sampler"],
              Json::parse(R"({"type": "sobol", "spp": 16, "seed": 3})"));
    const ImportedScene lanczos = import(
        "<sensor type=\"perspective\"><film type=\"hdrfilm\">"
        "<rfilter type=\"lanczos\"/></film></sensor>" +
        std::string(kLight));
    EXPECT_EQ(lanczos.scene["film"]["filter"],
              Json::parse(R"({"type": "blackman_harris", "radius": 3})"));
    EXPECT_EQ(warningsWith(lanczos, "lanczos became").size(), 1u);
}

TEST_F(MitsubaImport, Integrators) {
    auto integrator = [&](const std::string& xml) {
        return translated(xml + kLight)["integrator"];
    };
    // Mitsuba counts the emitter vertex: max_depth 2 is direct light, lamina's max_depth 1.
    EXPECT_EQ(integrator("<integrator type=\"path\"><integer name=\"max_depth\" value=\"2\"/>"
                         "<integer name=\"rr_depth\" value=\"3\"/></integrator>"),
              Json::parse(R"({"type": "path", "max_depth": 1, "rr_depth": 2})"));
    EXPECT_EQ(
        integrator(
            "<integrator type=\"ptracer\"><integer name=\"max_depth\" value=\"8\"/></integrator>"),
        Json::parse(R"({"type": "light", "max_depth": 7, "rr_depth": 4})"));
    EXPECT_EQ(integrator("<integrator type=\"bdpt\"/>"),
              Json::parse(R"({"type": "bdpt", "max_depth": 1024, "rr_depth": 4})"));
    EXPECT_EQ(
        error("<integrator type=\"path\">\n<integer name=\"max_depth\" value=\"1\"/></integrator>"),
        where(2) +
            ": <integrator type=\"path\">: max_depth 1 is not supported (lamina renders "
            "2 to 1025 or -1)");
    EXPECT_EQ(error("<integrator type=\"aov\"/>"),
              where(2) +
                  ": <integrator type=\"aov\">: the integrator \"aov\" is not supported (path, "
                  "ptracer, bdpt, direct)");
    const ImportedScene unbounded = import("<integrator type=\"path\"/>" + std::string(kLight));
    EXPECT_EQ(
        warningsWith(unbounded, "max_depth -1 (unbounded) became lamina's max_depth 1024").size(),
        1u);
}

TEST_F(MitsubaImport, ThinLensAndOtherIntegrators) {
    const Json s = translated(R"(<sensor type="thinlens"><float name="aperture_radius" value="0.1"/>
<float name="focus_distance" value="5"/><float name="fov" value="40"/>
<string name="fov_axis" value="y"/></sensor>
<integrator type="direct"/>)" +
                              std::string(kLight));
    EXPECT_EQ(s["camera"], Json::parse(R"({"type": "thin_lens", "aperture_radius": 0.1,
        "focus_distance": 5, "fov": 40})"));
    EXPECT_EQ(s["integrator"], Json::parse(R"({"type": "path", "max_depth": 1})"));
    const ImportedScene volpath = import(
        "<integrator type=\"volpath\"><integer name=\"max_depth\" "
        "value=\"4\"/></integrator>" +
        std::string(kLight));
    EXPECT_EQ(volpath.scene["integrator"],
              Json::parse(R"({"type": "path", "max_depth": 3, "rr_depth": 4})"));
    // lamina's path renders media as volpath does: no warning about the integrator.
    EXPECT_TRUE(warningsWith(volpath, "volpath").empty());
    EXPECT_EQ(error("<integrator type=\"path\">\n<boolean name=\"hide_emitters\" value=\"true\"/>"
                    "</integrator>"),
              where(2) + ": <integrator type=\"path\">: hide_emitters is not supported");
}

// ---- shapes --------------------------------------------------------------------------------

TEST_F(MitsubaImport, AnalyticShapes) {
    const Json s = translated(R"(<shape type="sphere"><point name="center" x="1" y="2" z="3"/>
<float name="radius" value="0.5"/><boolean name="flip_normals" value="true"/>
<emitter type="area"><rgb name="radiance" value="1, 2, 3"/></emitter></shape>
<shape type="disk"><boolean name="flip_normals" value="true"/></shape>
<shape type="rectangle"><boolean name="flip_normals" value="true"/></shape>
<shape type="cube"/>)");
    EXPECT_EQ(s["shapes"][0], Json::parse(R"({"type": "sphere", "center": [1, 2, 3], "radius": 0.5,
        "flip_normals": true, "material": {"type": "lambert", "reflectance": 0.5},
        "emission": {"radiance": [1, 2, 3]}})"));
    EXPECT_EQ(s["shapes"][1]["normal"], Json::parse("[0, 0, -1]"));
    // An emitter's constant spectrum is equal energy: illuminant E of that luminance.
    EXPECT_EQ(translated("<shape type=\"disk\"><emitter type=\"area\"><spectrum name=\"radiance\" "
                         "value=\"3\"/></emitter></shape>")["shapes"][0]["emission"],
              Json::parse(R"({"radiance": {"illuminant": "E", "scale": 3}})"));
    EXPECT_EQ(s["shapes"][2]["transform"],
              Json::parse(R"([{"rotate": {"axis": [1, 0, 0], "angle": 180}}])"));
    EXPECT_EQ(s["shapes"][3]["type"], "mesh");
    EXPECT_EQ(s["shapes"][3]["positions"].size(), 24u);
    EXPECT_EQ(s["shapes"][3]["faces"].size(), 6u);
    // The +x face first, counter-clockwise seen from +x.
    EXPECT_EQ(s["shapes"][3]["positions"][0], Json::parse("[1, -1, -1]"));
    EXPECT_EQ(s["shapes"][3]["positions"][1], Json::parse("[1, 1, -1]"));
    EXPECT_EQ(s["shapes"][3]["positions"][2], Json::parse("[1, 1, 1]"));
}

TEST_F(MitsubaImport, MeshFiles) {
    write("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    write("m.ply", "ply\n");
    const ImportedScene s = import(R"(<shape type="obj"><string name="filename" value="m.obj"/>
<boolean name="face_normals" value="true"/></shape>
<shape type="ply" id="part"><string name="filename" value="m.ply"/></shape>)" +
                                   std::string(kLight));
    EXPECT_EQ(s.scene["shapes"][0]["file"], "m.obj");
    EXPECT_EQ(s.scene["shapes"][1], Json::parse(R"({"type": "ply", "file": "m.ply", "name": "part",
        "material": {"type": "lambert", "reflectance": 0.5}})"));
    EXPECT_EQ(warningsWith(s, where(2) + ": face_normals became the file's own normals").size(),
              1u);
}

TEST_F(MitsubaImport, MissingMeshFileNamesTheLine) {
    EXPECT_EQ(
        error("\n<shape type=\"obj\"><string name=\"filename\" value=\"absent.obj\"/></shape>"),
        where(3) + ": <shape type=\"obj\">: parameter \"filename\": cannot open " +
            (dir_ / "absent.obj").string());
}

TEST_F(MitsubaImport, UnsupportedShapesAreRefused) {
    EXPECT_EQ(error("<shape type=\"serialized\"/>"),
              where(2) + ": <shape type=\"serialized\">: needs a filename");
    EXPECT_EQ(error("\n<shape type=\"hyperboloid\"/>"),
              where(3) +
                  ": <shape type=\"hyperboloid\">: the shape plugin \"hyperboloid\" is not "
                  "supported (obj, ply, serialized, rectangle, cube, sphere, disk, cylinder, "
                  "bsplinecurve, linearcurve, instance, shapegroup)");
}

// Mitsuba's cylinder (mitsuba3 src/shapes/cylinder.cpp): the unit cylinder placed by to_world *
// translate(p0) * to_frame(Frame3f(p1 - p0)) * scale(radius, radius, |p1 - p0|), open, facing
// outwards, uv = (phi / 2 pi, z / length) with phi from the frame's s axis. A lamina cylinder
// of that radius, z in [0, length], in that frame: the same surface and uv.
TEST_F(MitsubaImport, CylinderBecomesLaminasInItsPlacedFrame) {
    const ImportedScene imported = import(R"(<shape type="cylinder">
  <point name="p0" x="1" y="0" z="0"/><point name="p1" x="1" y="3" z="0"/>
  <float name="radius" value="0.25"/>
  <transform name="to_world"><scale value="2"/><translate x="0" y="0" z="1"/></transform>
</shape>
<shape type="cylinder"><boolean name="flip_normals" value="true"/></shape>
<shape type="cylinder"><transform name="to_world"><scale x="-1"/></transform></shape>)" +
                                          std::string(kLight));
    const Json& shapes = imported.scene["shapes"];
    ASSERT_EQ(shapes.size(), 4u);
    const Json& c = shapes[0];
    EXPECT_EQ(c["type"], "cylinder");
    EXPECT_DOUBLE_EQ(c["radius"].get<double>(), 0.5);
    EXPECT_EQ(c["z_min"], 0.0);
    EXPECT_DOUBLE_EQ(c["z_max"].get<double>(), 6.0);
    EXPECT_FALSE(c.contains("flip_normals"));
    // The frame: Duff et al.'s basis about +y (Mitsuba's Frame3f), at to_world(p0) = (2, 0, 1).
    const Frame<double> frame = Frame<double>::fromNormal(Vec3d(0, 1, 0));
    const Json& m = c["transform"][0]["matrix"];
    for (int row = 0; row < 3; ++row) {
        EXPECT_NEAR(m[std::size_t(4 * row)].get<double>(), frame.s[row], 1e-12);
        EXPECT_NEAR(m[std::size_t(4 * row + 1)].get<double>(), frame.t[row], 1e-12);
        EXPECT_NEAR(m[std::size_t(4 * row + 2)].get<double>(), frame.n[row], 1e-12);
    }
    EXPECT_EQ(m[3], 2.0);
    EXPECT_EQ(m[7], 0.0);
    EXPECT_EQ(m[11], 1.0);
    // Mitsuba's defaults: radius 1 from (0, 0, 0) to (0, 0, 1); flip_normals kept, and a
    // mirroring to_world turns the normal Mitsuba takes from dp/du x dp/dv inwards.
    EXPECT_EQ(shapes[1]["radius"], 1.0);
    EXPECT_EQ(shapes[1]["z_max"], 1.0);
    EXPECT_EQ(shapes[1]["flip_normals"], true);
    EXPECT_EQ(shapes[2]["flip_normals"], true);
    // The lamina scene hits it where Mitsuba's surface is: towards the axis at mid-height, at
    // the radius, with v = 1/2 and u the angle from the frame's s axis (here its t: 90
    // degrees) over 2 pi.
    const SceneDesc scene = parseScene(imported.scene.dump(), JsonSource{"<imported>", dir_});
    const Geometry g(scene);
    const Vec3f t(frame.t);
    const auto hit = g.intersect(Vec3f(2, 3, 1) + 2.0f * t, -t);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(glm::length(hit->p - (Vec3f(2, 3, 1) + 0.5f * t)), 0.0f, 1e-5f);
    EXPECT_NEAR(hit->uv.x, 0.25f, 1e-5f);
    EXPECT_NEAR(hit->uv.y, 0.5f, 1e-5f);
    EXPECT_NEAR(glm::dot(hit->ng, t), 1.0f, 1e-5f);
}

TEST_F(MitsubaImport, CylinderErrorsNameTheLine) {
    EXPECT_EQ(error("\n<shape type=\"cylinder\"><float name=\"radius\" value=\"-1\"/></shape>"),
              where(3) + ": <shape type=\"cylinder\">: radius must be > 0");
    EXPECT_EQ(
        error("<shape type=\"cylinder\"><point name=\"p1\" x=\"0\" y=\"0\" z=\"0\"/></shape>"),
        where(2) +
            ": <shape type=\"cylinder\">: p0 and p1 coincide: the cylinder has no "
            "length");
    EXPECT_EQ(error("<shape type=\"cylinder\"><transform name=\"to_world\"><scale x=\"2\"/>"
                    "</transform></shape>"),
              where(2) +
                  ": <shape type=\"cylinder\">: to_world must keep the cylinder round (a "
                  "rotation, a translation and a scale the same across its axis): lamina "
                  "refuses a shear or an uneven scale across it");
}

TEST_F(MitsubaImport, ShapeGroupsAndInstances) {
    const Json s = translated(R"(<shape type="shapegroup" id="g">
  <shape type="sphere"><float name="radius" value="2"/></shape>
</shape>
<shape type="instance"><ref id="g"/><transform name="to_world"><translate y="1"/></transform></shape>
<shape type="instance"><ref id="g"/></shape>)" +
                              std::string(kLight));
    EXPECT_EQ(s["objects"], Json::parse(R"({"g": [{"type": "sphere", "center": [0, 0, 0],
        "radius": 2, "material": {"type": "lambert", "reflectance": 0.5}}]})"));
    EXPECT_EQ(s["shapes"][0], Json::parse(R"({"type": "instance", "object": "g",
        "transform": [{"translate": [0, 1, 0]}]})"));
    EXPECT_EQ(s["shapes"][1], Json::parse(R"({"type": "instance", "object": "g"})"));
    EXPECT_EQ(error("<shape type=\"instance\"><shape type=\"shapegroup\"/></shape>"),
              where(2) +
                  ": <shape type=\"instance\">: an instance needs one <ref> to a shapegroup "
                  "with an id");
    EXPECT_EQ(error("<shape type=\"shapegroup\" id=\"g\">\n<shape type=\"sphere\">"
                    "<emitter type=\"area\"/></shape></shape>"),
              where(3) +
                  ": <emitter type=\"area\">: an emitting shape inside a shapegroup is not "
                  "supported");
}

// ---- emitters ------------------------------------------------------------------------------

TEST_F(MitsubaImport, Emitters) {
    const ImportedScene s = import(R"(<emitter type="point"><point name="position" value="1 2 3"/>
<rgb name="intensity" value="5"/></emitter>
<emitter type="point"><transform name="to_world"><translate x="4"/></transform></emitter>
<emitter type="spot"><transform name="to_world"><lookat origin="0, 5, 0" target="0, 0, 0" up="0, 0, 1"/></transform>
<float name="cutoff_angle" value="30"/><rgb name="intensity" value="2, 2, 1"/></emitter>
<emitter type="directional"><vector name="direction" value="0, -1, 0"/><float name="irradiance" value="3"/></emitter>
<emitter type="directional"><transform name="to_world"><rotate x="1" angle="90"/></transform></emitter>
<emitter type="constant"><rgb name="radiance" value="0.1, 0.2, 0.3"/></emitter>)");
    EXPECT_EQ(s.scene["lights"][0],
              Json::parse(R"({"type": "point", "position": [1, 2, 3], "intensity": 5})"));
    EXPECT_EQ(s.scene["lights"][1],
              Json::parse(R"({"type": "point", "position": [4, 0, 0], "intensity": 1})"));
    const Json& spot = s.scene["lights"][2];
    EXPECT_EQ(spot["position"], Json::parse("[0, 5, 0]"));
    EXPECT_NEAR(spot["look_at"][1].get<double>(), 4, 1e-12);
    EXPECT_EQ(spot["cone_angle"], 30);
    EXPECT_EQ(spot["falloff_start"], 22.5);
    EXPECT_EQ(spot["intensity"], Json::parse("[2, 2, 1]"));
    EXPECT_EQ(s.scene["lights"][3],
              Json::parse(R"({"type": "directional", "direction": [0, -1, 0], "irradiance": 3})"));
    // +z rotated 90 degrees about +x is -y.
    EXPECT_NEAR(s.scene["lights"][4]["direction"][1].get<double>(), -1, 1e-12);
    EXPECT_EQ(s.scene["lights"][5],
              Json::parse(R"({"type": "environment", "radiance": [0.1, 0.2, 0.3]})"));
    EXPECT_EQ(warningsWith(s, "smoothstep in cos theta").size(), 1u);
}

// Mitsuba 3's homogeneous medium (albedo 0.75 and sigma_t 1 by default, scale, a nested hg
// or isotropic phase function) becomes a lamina medium with sigma_s = albedo sigma_t and
// sigma_a = sigma_t - sigma_s; a shape's interior and exterior media (nested or refs) its
// "interior" and "exterior", the null BSDF lamina's "interface", the sensor's medium the
// camera's. A null shape between no media is left out.
TEST_F(MitsubaImport, HomogeneousMediaAndTheirBoundaries) {
    const ImportedScene s = import(R"(<medium type="homogeneous" id="fog"/>
<medium type="homogeneous" id="ink">
  <rgb name="albedo" value="0.5, 0.25, 0"/><float name="sigma_t" value="2"/>
  <float name="scale" value="3"/><phase type="hg"><float name="g" value="0.5"/></phase>
</medium>
<medium type="homogeneous" id="spare"/>
<bsdf type="null" id="boundary"/>
<sensor type="perspective"><ref id="fog"/></sensor>
<shape type="sphere"><ref id="boundary"/><ref name="interior" id="ink"/>
  <ref name="exterior" id="fog"/></shape>
<shape type="sphere"><bsdf type="dielectric"/>
  <medium type="homogeneous" name="interior"><phase type="isotropic"/></medium></shape>
<shape type="sphere"><bsdf type="null"/></shape>
<emitter type="point"><ref id="fog"/></emitter>)");
    const Json& media = s.scene["media"];
    EXPECT_EQ(media["fog"], Json::parse(R"({"type": "homogeneous", "sigma_s": 0.75,
        "sigma_a": 0.25, "scale": 1.0, "g": 0.0})"));
    EXPECT_EQ(media["ink"], Json::parse(R"({"type": "homogeneous", "sigma_s": [1.0, 0.5, 0.0],
        "sigma_a": [1.0, 1.5, 2.0], "scale": 3.0, "g": 0.5})"));
    EXPECT_EQ(media["medium_3"], media["fog"]);
    EXPECT_FALSE(media.contains("spare"));
    EXPECT_EQ(s.scene["camera"]["medium"], "fog");
    ASSERT_EQ(s.scene["shapes"].size(), 2u);
    EXPECT_EQ(s.scene["shapes"][0]["material"], "interface");
    EXPECT_EQ(s.scene["shapes"][0]["interior"], "ink");
    EXPECT_EQ(s.scene["shapes"][0]["exterior"], "fog");
    EXPECT_EQ(s.scene["shapes"][1]["interior"], "medium_3");
    EXPECT_FALSE(s.scene["shapes"][1].contains("exterior"));
    EXPECT_EQ(warningsWith(s, "upsamples").size(), 1u);  // ink's colours
    EXPECT_EQ(warningsWith(s, "spare").size(), 1u);
    EXPECT_EQ(warningsWith(s, "no medium omitted").size(), 1u);
    EXPECT_EQ(warningsWith(s, "the emitter's medium").size(), 1u);
    const auto file = scene(R"(<medium type="homogeneous" id="fog"/>
<sensor type="perspective"><ref id="fog"/></sensor>
<shape type="sphere"><bsdf type="null"/><ref name="interior" id="fog"/></shape>)" +
                            std::string(kLight));
    EXPECT_NO_THROW(loadScene(file)) << lamina::testing::errorOf([&] { loadScene(file); });
    // Mitsuba's path integrator ignores media; lamina's path tracer renders them.
    const ImportedScene path = import(R"(<integrator type="path"/>
<medium type="homogeneous" id="fog"/><sensor type="perspective"><ref id="fog"/></sensor>)" +
                                      std::string(kLight));
    EXPECT_EQ(warningsWith(path, "as if there were none").size(), 1u);
}

TEST_F(MitsubaImport, MediaErrorsNameTheLine) {
    EXPECT_EQ(error("<shape type=\"sphere\"><medium type=\"spectra\" name=\"interior\"/>"
                    "</shape>"),
              where(2) +
                  ": <medium type=\"spectra\">: the medium \"spectra\" is "
                  "not supported (homogeneous, heterogeneous)");
    EXPECT_EQ(error("<shape type=\"sphere\"><medium type=\"homogeneous\" name=\"inside\"/>"
                    "</shape>"),
              where(2) +
                  ": <shape type=\"sphere\">: a medium of a shape is named \"interior\" "
                  "or \"exterior\"");
    EXPECT_EQ(error("<shape type=\"sphere\"><medium type=\"homogeneous\" name=\"interior\">"
                    "<float name=\"albedo\" value=\"1.5\"/></medium></shape>"),
              where(2) + ": <medium type=\"homogeneous\">: parameter \"albedo\" must be <= 1");
    EXPECT_EQ(error("<shape type=\"sphere\"><medium type=\"homogeneous\" name=\"interior\">"
                    "<phase type=\"rayleigh\"/></medium></shape>"),
              where(2) +
                  ": <phase type=\"rayleigh\">: the phase function \"rayleigh\" is not "
                  "supported (isotropic, hg)");
    EXPECT_EQ(error("<shape type=\"sphere\"><bsdf type=\"twosided\"><bsdf type=\"null\"/>"
                    "</bsdf></shape>"),
              where(2) +
                  ": <bsdf type=\"null\">: a null BSDF is only supported as a shape's own "
                  "BSDF (an index-matched boundary), not inside another BSDF");
}

TEST_F(MitsubaImport, EnvironmentMap) {
    write("sky.exr", "not read by the importer");
    const ImportedScene s =
        import(R"(<emitter type="envmap"><string name="filename" value="sky.exr"/>
<float name="scale" value="2"/>
<transform name="to_world"><rotate y="1" angle="90"/></transform></emitter>)");
    EXPECT_EQ(s.scene["lights"][0], Json::parse(R"({"type": "environment", "file": "sky.exr",
        "scale": 2, "transform": [{"scale": [-1, 1, 1]},
                                  {"rotate": {"axis": [0, 1, 0], "angle": 90}}]})"));
    EXPECT_TRUE(warningsWith(s, "envmap").empty());
    EXPECT_EQ(error("<emitter type=\"envmap\"><string name=\"filename\" value=\"sky.exr\"/>\n"
                    "<transform name=\"to_world\"><scale value=\"2\"/></transform></emitter>"),
              where(2) +
                  ": <emitter type=\"envmap\">: to_world of an envmap must be a rotation "
                  "(lamina refuses a scale or shear)");
    // A rotation written with 6 digits, as exporters write one: its nearest rotation, warned.
    const ImportedScene rounded =
        import(R"(<emitter type="envmap"><string name="filename" value="sky.exr"/>
<transform name="to_world"><matrix value="0.866025 0 0.5 0  0 1 0 0  -0.5 0 0.866025 0  0 0 0 1"/>
</transform></emitter>)");
    EXPECT_EQ(warningsWith(rounded, "is a rotation to within").size(), 1u);
    EXPECT_TRUE(rounded.scene["lights"][0]["transform"][1].contains("matrix"));
}

// The translated transform makes lamina look every direction up in the pixel Mitsuba 3 does
// (mitsuba3 envmap.cpp: d = to_world^-1 w, u = atan2(d.x, -d.z) / 2 pi, v = acos(d.y) / pi):
// a map whose pixels are their own index, seen along the centre of every pixel by Mitsuba's
// mapping under an oblique rotation, must return that pixel's index.
TEST_F(MitsubaImport, EnvironmentMapLooksUpThePixelsMitsubaDoes) {
    write("sky.exr", "not read by the importer");
    const ImportedScene s =
        import(R"(<emitter type="envmap"><string name="filename" value="sky.exr"/>
<transform name="to_world"><rotate x="1" y="2" z="0.5" angle="70"/></transform></emitter>)");
    const JsonSource source{"translated", dir_};
    const glm::dmat4 toWorld = readTransform(JsonReader(s.scene["lights"][0], "", source));
    const glm::dmat3 mitsubaToWorld(readTransform(JsonReader(Json::parse(R"({"transform": [
            {"rotate": {"axis": [1, 2, 0.5], "angle": 70}}]})"),
                                                             "", source)));
    const int width = 16, height = 8;
    std::vector<Rgb<float>> pixels;
    for (int i = 0; i < width * height; ++i)
        pixels.emplace_back(float(i), 0.0f, 0.0f);
    const EnvironmentMap map(width, height, pixels,
                             {EnvironmentMapping::Equirectangular, 0, Mat3<double>(toWorld)});
    for (int row = 0; row < height; ++row)
        for (int col = 0; col < width; ++col) {
            const double phi = 2 * kPi<double> * (col + 0.5) / width,
                         theta = kPi<double> * (row + 0.5) / height;
            // atan2(d.x, -d.z) = phi and acos(d.y) = theta.
            const glm::dvec3 local(std::sin(theta) * std::sin(phi), std::cos(theta),
                                   -std::sin(theta) * std::cos(phi));
            const Vec3<float> w(mitsubaToWorld * local);
            EXPECT_EQ(map.lookup(w)[0], float(row * width + col))
                << "row " << row << " col " << col;
        }
}

TEST_F(MitsubaImport, UnsupportedEmitterIsRefused) {
    EXPECT_EQ(error("<emitter type=\"projector\"/>"),
              where(2) +
                  ": <emitter type=\"projector\">: the emitter plugin \"projector\" is not "
                  "supported (area, point, spot, directional, constant, envmap)");
}

// ---- BSDFs ---------------------------------------------------------------------------------

class MitsubaBsdf : public MitsubaImport {
  protected:
    Json material(const std::string& bsdf) {
        const std::string withId = "<bsdf id=\"m\" " + bsdf.substr(6);
        return translated(withId + kLight)["materials"]["m"];
    }
};

TEST_F(MitsubaBsdf, Diffuse) {
    EXPECT_EQ(material("<bsdf type=\"diffuse\"/>"),
              Json::parse(R"({"type": "lambert", "reflectance": 0.5})"));
    EXPECT_EQ(material("<bsdf type=\"diffuse\"><srgb name=\"reflectance\" value=\"0.5\"/></bsdf>")
                  ["reflectance"]
                      .get<double>(),
              std::pow((0.5 + 0.055) / 1.055, 2.4));
}

TEST_F(MitsubaBsdf, ConductorPresets) {
    const ImportedScene au =
        import("<bsdf type=\"conductor\" id=\"m\"><string name=\"material\" value=\"Au\"/></bsdf>" +
               std::string(kLight));
    EXPECT_EQ(au.scene["materials"]["m"],
              Json::parse(R"({"type": "conductor", "material": "Au"})"));
    EXPECT_EQ(
        warningsWith(au, "material \"Au\" became lamina's \"Au\" (lamina's measured table").size(),
        1u);
    EXPECT_EQ(
        material("<bsdf type=\"conductor\"><string name=\"material\" value=\"Ni_palik\"/></bsdf>")
            ["material"],
        "Ni");
    // `none`, Mitsuba's default: eta 0, k 1, reflectance 1 at every angle.
    EXPECT_EQ(material("<bsdf type=\"conductor\"/>"),
              Json::parse(R"({"type": "conductor", "f0": 1})"));
    EXPECT_EQ(
        error(
            "<bsdf type=\"conductor\" id=\"m\">\n<string name=\"material\" value=\"Hg\"/></bsdf>"),
        where(2) +
            ": <bsdf type=\"conductor\">: material \"Hg\" has no lamina counterpart "
            "(lamina has Ag, Al, Au, Be, Cr, Cu, Ni_palik as Ni, W; give eta and k "
            "instead)");
}

TEST_F(MitsubaBsdf, ConductorOptics) {
    EXPECT_EQ(material("<bsdf type=\"roughconductor\"><rgb name=\"eta\" value=\"0.2, 0.9, 1.1\"/>"
                       "<rgb name=\"k\" value=\"3.9, 2.4, 2.2\"/></bsdf>"),
              Json::parse(R"({"type": "conductor", "eta": [0.2, 0.9, 1.1], "k": [3.9, 2.4, 2.2],
                  "distribution": "beckmann", "alpha": 0.1})"));
    EXPECT_EQ(
        material("<bsdf type=\"roughconductor\"><string name=\"distribution\" value=\"ggx\"/>"
                 "<float name=\"alpha_u\" value=\"0.1\"/><float name=\"alpha_v\" value=\"0.3\"/>"
                 "</bsdf>"),
        Json::parse(R"({"type": "conductor", "f0": 1, "distribution": "ggx",
                  "alpha_x": 0.1, "alpha_y": 0.3})"));
    EXPECT_EQ(
        material("<bsdf type=\"conductor\"><spectrum name=\"eta\" value=\"400:1.5, 700:0.2\"/>"
                 "<spectrum name=\"k\" value=\"400:2, 700:4\"/></bsdf>"),
        Json::parse(R"({"type": "conductor", "eta": [[400, 1.5], [700, 0.2]],
                  "k": [[400, 2], [700, 4]]})"));
    EXPECT_EQ(error("<bsdf type=\"conductor\" id=\"m\"><string name=\"material\" value=\"Au\"/>\n"
                    "<rgb name=\"specular_reflectance\" value=\"0.5\"/></bsdf>"),
              where(2) +
                  ": <bsdf type=\"conductor\">: parameter \"specular_reflectance\" other "
                  "than 1 is not supported");
}

TEST_F(MitsubaBsdf, Dielectrics) {
    // bk7 in air by default: 1.5046 / 1.000277.
    EXPECT_EQ(
        material("<bsdf type=\"dielectric\"/>"),
        Json::parse(R"({"type": "dielectric", "ior": )" + Json(1.5046 / 1.000277).dump() + "}"));
    EXPECT_EQ(
        material("<bsdf type=\"roughdielectric\"><string name=\"int_ior\" value=\"water\"/>"
                 "<string name=\"ext_ior\" value=\"vacuum\"/><float name=\"alpha\" value=\"0.2\"/>"
                 "</bsdf>"),
        Json::parse(R"({"type": "dielectric", "ior": 1.333, "distribution": "beckmann",
                  "alpha": 0.2})"));
    EXPECT_EQ(material("<bsdf type=\"thindielectric\"><float name=\"int_ior\" value=\"1.5\"/>"
                       "<float name=\"ext_ior\" value=\"1\"/></bsdf>"),
              Json::parse(R"({"type": "thin_dielectric", "ior": 1.5})"));
    EXPECT_EQ(error("<bsdf type=\"dielectric\" id=\"m\">\n<string name=\"int_ior\" "
                    "value=\"glass\"/></bsdf>"),
              where(2) +
                  ": <bsdf type=\"dielectric\">: parameter \"int_ior\": unknown material "
                  "\"glass\"");
}

TEST_F(MitsubaBsdf, PlasticBecomesCoated) {
    const ImportedScene s = import(
        "<bsdf type=\"roughplastic\" id=\"m\"><rgb name=\"diffuse_reflectance\" value=\"0.1, 0.2, "
        "0.3\"/>"
        "<float name=\"int_ior\" value=\"1.5\"/><float name=\"ext_ior\" value=\"1\"/>"
        "<string name=\"distribution\" value=\"ggx\"/><float name=\"alpha\" "
        "value=\"0.05\"/></bsdf>" +
        std::string(kLight));
    EXPECT_EQ(s.scene["materials"]["m"], Json::parse(R"({"type": "coated", "ior": 1.5,
        "base": {"type": "lambert", "reflectance": [0.1, 0.2, 0.3]},
        "distribution": "ggx", "alpha": 0.05})"));
    EXPECT_EQ(warningsWith(s, "roughplastic became lamina's coated").size(), 1u);
    EXPECT_EQ(material("<bsdf type=\"plastic\"/>"),
              Json::parse(R"({"type": "coated", "ior": )" + Json(1.49 / 1.000277).dump() +
                          R"(, "base": {"type": "lambert", "reflectance": 0.5}})"));
}

TEST_F(MitsubaBsdf, TwoSidedBlendAndMask) {
    const ImportedScene one = import("<bsdf type=\"diffuse\" id=\"m\"/>" + std::string(kLight));
    EXPECT_EQ(warningsWith(one, "one-sided in Mitsuba").size(), 1u);
    const ImportedScene two = import(
        "<bsdf type=\"twosided\" id=\"m\"><bsdf type=\"diffuse\"/></bsdf>" + std::string(kLight));
    EXPECT_EQ(two.scene["materials"]["m"],
              Json::parse(R"({"type": "lambert", "reflectance": 0.5})"));
    EXPECT_TRUE(warningsWith(two, "one-sided in Mitsuba").empty());
    EXPECT_EQ(material("<bsdf type=\"blendbsdf\"><float name=\"weight\" value=\"0.25\"/>"
                       "<bsdf type=\"diffuse\"/><bsdf type=\"conductor\"/></bsdf>"),
              Json::parse(R"({"type": "mix", "weight": 0.25,
                  "a": {"type": "lambert", "reflectance": 0.5}, "b": {"type": "conductor", "f0": 1}})"));
    const Json masked =
        translated(R"(<bsdf type="mask" id="leaf"><float name="opacity" value="0.3"/>
<bsdf type="diffuse"/></bsdf>
<shape type="rectangle"><ref id="leaf"/></shape>
<shape type="disk"><bsdf type="mask"><bsdf type="conductor"/></bsdf></shape>)" +
                   std::string(kLight));
    EXPECT_EQ(masked["materials"]["leaf"],
              Json::parse(R"({"type": "lambert", "reflectance": 0.5})"));
    EXPECT_EQ(masked["shapes"][0]["material"], "leaf");
    EXPECT_EQ(masked["shapes"][0]["alpha"], 0.3);
    EXPECT_EQ(masked["shapes"][1]["alpha"], 0.5);
    EXPECT_EQ(error("<shape type=\"sphere\"><bsdf type=\"mask\"><bsdf type=\"diffuse\"/></bsdf>\n"
                    "<emitter type=\"area\"/></shape>"),
              where(2) + ": <shape type=\"sphere\">: a mask on an emitting shape is not supported");
}

TEST_F(MitsubaBsdf, UnsupportedPluginAndTextureAreRefused) {
    EXPECT_EQ(error("\n<bsdf type=\"measured_polarized\" id=\"m\"/>"),
              where(3) +
                  ": <bsdf type=\"measured_polarized\">: the BSDF plugin \"measured_polarized\" is "
                  "not supported (diffuse, conductor, roughconductor, dielectric, roughdielectric, "
                  "thindielectric, plastic, roughplastic, pplastic, principled, principledthin, "
                  "twosided, blendbsdf, mask, bumpmap, normalmap, measured, polarizer, hair)");
    // A texture where lamina takes none (mitsuba_textures.cpp's colorOrTexture is not asked there).
    EXPECT_EQ(error("<bsdf type=\"conductor\" id=\"m\">\n<texture type=\"bitmap\" "
                    "name=\"specular_reflectance\"/></bsdf>"),
              where(3) +
                  ": <bsdf type=\"conductor\">: parameter \"specular_reflectance\": a texture "
                  "is not supported here (give a colour)");
}

TEST_F(MitsubaBsdf, RefCycleIsRefused) {
    EXPECT_NE(error("<bsdf type=\"twosided\" id=\"a\"><ref id=\"a\"/></bsdf>")
                  .find("BSDFs nested deeper than 16 (does a <ref> refer to its own BSDF?)"),
              std::string::npos);
}

// ---- spectra -------------------------------------------------------------------------------

TEST_F(MitsubaBsdf, SpectraForms) {
    write("r.spd", "# nm value\n400 0.1\n\n700 0.9  # red\n");
    EXPECT_EQ(
        material("<bsdf type=\"diffuse\"><spectrum name=\"reflectance\" value=\"0.4\"/></bsdf>")
            ["reflectance"],
        0.4);
    EXPECT_EQ(material("<bsdf type=\"diffuse\"><spectrum name=\"reflectance\" "
                       "value=\"400:0.1, 550:0.5, 700:0.9\"/></bsdf>")["reflectance"],
              Json::parse(R"({"spectrum": [[400, 0.1], [550, 0.5], [700, 0.9]]})"));
    const ImportedScene file = import(
        "<bsdf type=\"diffuse\" id=\"m\"><spectrum name=\"reflectance\" "
        "filename=\"r.spd\"/></bsdf>" +
        std::string(kLight));
    EXPECT_EQ(file.scene["materials"]["m"]["reflectance"],
              Json::parse(R"({"spectrum": [[400, 0.1], [700, 0.9]]})"));
    EXPECT_EQ(file.inputFiles.back(), dir_ / "r.spd");
    EXPECT_EQ(
        error("<bsdf type=\"diffuse\" id=\"m\">\n<spectrum name=\"reflectance\" value=\"400:x\"/>"
              "</bsdf>"),
        where(3) + ": parameter \"reflectance\": expected a number, got \"x\"");
    EXPECT_EQ(
        error("<bsdf type=\"diffuse\" id=\"m\">\n<rgb name=\"reflectance\" value=\"1 2\"/></bsdf>"),
        where(3) + ": parameter \"reflectance\": expected 1 or 3 numbers, got \"1 2\"");
}

// ---- the test scenes of tests/data/interchange/mitsuba ------------------------------------------

std::string mitsubaData(const std::string& name) {
    return (testing::sourceFile("tests/data/interchange/mitsuba") / name).string();
}

TEST(MitsubaScenes, InstancesTranslateToTheHandWrittenObjects) {
    // The render comparison needs lamina's instancing; the translated document must already be
    // the hand-written one (up to the camera's rounding and the one-sided lambert notes).
    const std::filesystem::path dir = mitsubaData("");
    const ImportedScene s = importScene(mitsubaData("instances.xml"), dir);
    Json expected = lamina::readJsonFile(mitsubaData("instances.json"));
    EXPECT_EQ(s.scene["objects"], expected["objects"]);
    EXPECT_EQ(s.scene["shapes"], expected["shapes"]);
    EXPECT_EQ(s.scene["lights"], expected["lights"]);
    EXPECT_EQ(s.scene["materials"], expected["materials"]);
    EXPECT_NEAR(s.scene["camera"]["fov"].get<double>(), expected["camera"]["fov"].get<double>(),
                1e-3);
}

}  // namespace
}  // namespace lamina::render
