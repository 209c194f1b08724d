// Constructs of the Mitsuba 3 scenes people publish that the importer met in the corpus survey
// (docs/interchange.md, "A corpus survey": mitsuba-data's documentation and test scenes): the
// `<path>` element, `<ref>`s to named BSDFs and textures inside BSDFs, and the `checkerboard` and
// `bitmap` textures on the parameters lamina can texture. Each is compared with what Mitsuba 3
// does (its source named at each test); the checkerboard also by rendering it.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/interchange/scene_import.h"
#include "lamina/scene/scene_description.h"
#include "lamina/scene/scene_readers.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::errorOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

constexpr const char* kLight = "<emitter type=\"constant\"/>";

class MitsubaCorpusConstructs : public lamina::testing::ScratchDirectoryTest {
  protected:
    // `bytes` in NAME, a path in the scratch directory whose directories are made.
    std::filesystem::path writeIn(const std::string& name, const std::string& bytes) {
        std::filesystem::create_directories((dir_ / name).parent_path());
        return write(name, bytes);
    }
    // `body` from line 2 of NAME (in the scratch directory or a subdirectory of it).
    std::filesystem::path scene(const std::string& body, const std::string& name = "scene.xml") {
        return writeIn(name, "<scene version=\"3.0.0\">\n" + body + "\n</scene>\n");
    }
    ImportedScene import(const std::string& body, const std::string& name = "scene.xml") {
        return importScene(scene(body, name), dir_);
    }
    std::string error(const std::string& body) {
        const auto file = scene(body);
        return errorOf([&] { importScene(file, dir_); });
    }
    std::string where(int line, const std::string& name = "scene.xml") const {
        return (dir_ / name).string() + ":" + std::to_string(line);
    }
    // The material `m` of a file whose only BSDF (from line 2) has id "m".
    ImportedScene material(const std::string& bsdf) { return import(bsdf + kLight); }
};

// ---- <path> -------------------------------------------------------------------------------

// mitsuba3 src/core/parser.cpp (TagType::Resource): a relative <path> is taken from the file's
// directory and prepended to the FileResolver, which then finds a relative file name in the
// first directory that has it: the last <path> first, the scene's own directory after them.
TEST_F(MitsubaCorpusConstructs, PathAddsDirectoriesLookedInBeforeTheScenes) {
    writeIn("common/meshes/a.obj", "v 0 0 0\n");
    writeIn("other/meshes/a.obj", "v 0 0 0\n");
    writeIn("scenes/meshes/a.obj", "v 0 0 0\n");
    writeIn("common/meshes/only-common.obj", "v 0 0 0\n");
    writeIn("common/part.xml",
            "<scene version=\"3.0.0\">\n<bsdf type=\"diffuse\" id=\"g\"/>\n</scene>");
    const ImportedScene s = import(R"j(<path value="../other"/>
<path value="../common"/>
<include filename="part.xml"/>
<shape type="obj"><string name="filename" value="meshes/a.obj"/><ref id="g"/></shape>
<shape type="obj"><string name="filename" value="meshes/only-common.obj"/></shape>
<emitter type="constant"/>)j",
                                   "scenes/scene.xml");
    // The last <path> first: common's a.obj, not other's nor the scene directory's.
    EXPECT_EQ(s.scene["shapes"][0]["file"], "common/meshes/a.obj");
    EXPECT_EQ(s.scene["shapes"][0]["material"], "g");
    EXPECT_EQ(s.scene["shapes"][1]["file"], "common/meshes/only-common.obj");
    EXPECT_EQ(s.inputFiles.at(1), dir_ / "scenes/../common/part.xml");
}

TEST_F(MitsubaCorpusConstructs, PathErrorsNameTheLine) {
    EXPECT_EQ(error("\n<path value=\"nowhere\"/>"),
              where(3) + ": <path>: the directory \"nowhere\" is not there");
    EXPECT_EQ(error("<shape type=\"sphere\">\n<path value=\".\"/></shape>"),
              where(3) + ": <path> must be a child of <scene>");
    EXPECT_EQ(error("<path/>"), where(2) + ": <path> needs a value (a directory)");
    EXPECT_EQ(error("<path value=\".\" x=\"1\"/>"),
              where(2) + ": <path>: attribute \"x\" is not supported");
}

// ---- <ref> inside BSDFs --------------------------------------------------------------------

// mitsuba3 parser.cpp (TagType::NamedReference): a <ref> stands for the object with that id
// wherever an object may be nested; twosided, blendbsdf and mask take BSDFs, diffuse a texture.
TEST_F(MitsubaCorpusConstructs, RefsToNamedBsdfsAndTexturesInsideBsdfs) {
    const ImportedScene s =
        import(R"j(<bsdf type="diffuse" id="white"><rgb name="reflectance" value="0.8"/></bsdf>
<bsdf type="roughconductor" id="metal"/>
<texture type="checkerboard" id="checks"/>
<bsdf type="diffuse" id="checked"><ref name="reflectance" id="checks"/></bsdf>
<bsdf type="twosided" id="both"><ref id="white"/></bsdf>
<bsdf type="blendbsdf" id="blend"><float name="weight" value="0.25"/><ref id="white"/><ref name="second" id="metal"/></bsdf>
<bsdf type="mask" id="masked"><float name="opacity" value="0.5"/><ref id="both"/></bsdf>
<shape type="sphere"><ref id="masked"/></shape>
<shape type="sphere"><ref name="bsdf" id="checked"/></shape>)j" +
               std::string(kLight));
    const Json& m = s.scene["materials"];
    EXPECT_EQ(m["both"], m["white"]);
    EXPECT_EQ(m["blend"], Json::parse(R"j({"type": "mix", "weight": 0.25,
        "a": {"type": "lambert", "reflectance": 0.8},
        "b": {"type": "conductor", "f0": 1.0, "distribution": "beckmann", "alpha": 0.1}})j"));
    EXPECT_EQ(m["masked"], m["white"]);
    EXPECT_EQ(s.scene["shapes"][0]["alpha"], 0.5);
    EXPECT_EQ(m["checked"]["reflectance"], Json::parse(R"j({"texture": "checks"})j"));
    EXPECT_EQ(s.scene["textures"]["checks"],
              Json::parse(R"j({"type": "checkerboard", "a": 0.4, "b": 0.2, "scale": [2, 2]})j"));
    // The translated scene loads: lamina reads the texture the material names.
    const SceneDesc loaded =
        loadScene(scene(R"j(<bsdf type="diffuse" id="m"><ref name="reflectance" id="t"/></bsdf>
<texture type="checkerboard" id="t"/>
<shape type="sphere"><ref id="m"/></shape>)j" +
                        std::string(kLight)));
    EXPECT_EQ(loaded.textures.size(), 1u);
}

TEST_F(MitsubaCorpusConstructs, RefCyclesAndWrongTargetsAreOneLine) {
    // a -> b -> a through blendbsdf and twosided: refused at the depth bound, no hang.
    EXPECT_THAT(error("<bsdf type=\"blendbsdf\" id=\"a\"><ref id=\"b\"/><ref id=\"b\"/></bsdf>\n"
                      "<bsdf type=\"twosided\" id=\"b\"><ref id=\"a\"/></bsdf>"),
                HasSubstr("BSDFs nested deeper than 16 (does a <ref> refer to its own BSDF?)"));
    EXPECT_EQ(
        error("<bsdf type=\"diffuse\" id=\"a\">\n<ref name=\"reflectance\" id=\"b\"/></bsdf>\n"
              "<bsdf type=\"diffuse\" id=\"b\"/>"),
        where(3) +
            ": <bsdf type=\"diffuse\">: parameter \"reflectance\" refers to <bsdf "
            "type=\"diffuse\"> at " +
            where(4) + ", which is not a texture");
    EXPECT_EQ(
        error("<bsdf type=\"diffuse\" id=\"a\">\n<ref name=\"reflectance\" id=\"none\"/></bsdf>"),
        where(3) + ": no object has id \"none\" (<ref name=\"reflectance\"> refers to it)");
}

// mitsuba3's Cornell box (scenes/cbox) defines its area emitter at the top level after the
// shape that refers to it, and the sampler documentation scenes a sampler the sensor refers to.
TEST_F(MitsubaCorpusConstructs, TopLevelEmittersAndSamplersReferredToById) {
    const ImportedScene s = import(R"j(<sensor type="perspective"><ref id="smp"/></sensor>
<shape type="sphere"><ref id="glow"/></shape>
<emitter type="area" id="glow"><rgb name="radiance" value="2, 3, 4"/></emitter>
<emitter type="area" id="unused"/>
<sampler type="independent" id="smp"><integer name="sample_count" value="9"/></sampler>)j");
    EXPECT_EQ(s.scene["shapes"][0]["emission"], Json::parse(R"j({"radiance": [2, 3, 4]})j"));
    EXPECT_EQ(s.scene["shapes"].size(), 1u);
    EXPECT_FALSE(s.scene.contains("lights"));
    EXPECT_EQ(s.scene["sampler"]["spp"], 9);
    EXPECT_THAT(s.warnings, ::testing::Contains(where(5) + ": <emitter type=\"area\"> \"unused\" "
                                                           "is used by no shape: not imported"));
}

// mitsuba3 src/integrators/moment.cpp: the nested integrator's image, with its second moment
// as extra channels; ProjectiveCamera reads focus_distance for every perspective sensor, where
// a pinhole ignores it.
TEST_F(MitsubaCorpusConstructs, MomentIntegratorAndAPinholesFocusDistance) {
    const ImportedScene s = import(R"j(<integrator type="moment">
  <integrator type="path"><integer name="max_depth" value="8"/></integrator>
</integrator>
<sensor type="perspective"><float name="focus_distance" value="6"/></sensor>)j" +
                                   std::string(kLight));
    EXPECT_EQ(s.scene["integrator"],
              Json::parse(R"j({"type": "path", "max_depth": 7, "rr_depth": 4})j"));
    EXPECT_FALSE(s.scene["camera"].contains("focus_distance"));
    EXPECT_THAT(s.warnings,
                ::testing::Contains(where(2) + ": moment became its nested integrator: "
                                               "lamina writes no second-moment channels"));
    EXPECT_EQ(error("<integrator type=\"moment\"/>"),
              where(2) +
                  ": <integrator type=\"moment\">: moment with 0 integrators is not supported "
                  "(lamina takes one)");
}

// ---- checkerboard --------------------------------------------------------------------------

// mitsuba3 src/textures/checkerboard.cpp: uv' = to_uv(uv); eval gives color0 (0.4) where
// frac(u') > 1/2 and frac(v') > 1/2 agree, color1 (0.2) elsewhere: cells of 1/2, so lamina's
// scale is twice to_uv's; a shift by 1/2 or a mirrored axis swaps the colours.
TEST_F(MitsubaCorpusConstructs, CheckerboardCellsAndColours) {
    const auto texture = [&](const std::string& inside) {
        const ImportedScene s = material(
            "<bsdf type=\"diffuse\" id=\"m\"><texture type=\"checkerboard\" name=\"reflectance\">" +
            inside + "</texture></bsdf><shape type=\"sphere\"><ref id=\"m\"/></shape>");
        const std::string name = s.scene["materials"]["m"]["reflectance"]["texture"];
        EXPECT_EQ(name, "checkerboard (line 2)");
        return s.scene["textures"][name];
    };
    EXPECT_EQ(texture(R"j(<transform name="to_uv"><scale x="5" y="3"/></transform>)j"),
              Json::parse(R"j({"type": "checkerboard", "a": 0.4, "b": 0.2, "scale": [10, 6]})j"));
    EXPECT_EQ(
        texture(R"j(<rgb name="color0" value="0.1, 0.2, 0.3"/><float name="color1" value="0.9"/>
<transform name="to_uv"><scale x="4"/><translate x="0.5"/></transform>)j"),
        Json::parse(R"j({"type": "checkerboard", "a": 0.9, "b": [0.1, 0.2, 0.3],
                              "scale": [8, 2]})j"));
    EXPECT_EQ(
        texture(
            R"j(<transform name="to_uv"><scale x="-2" y="1"/><translate x="0.5" y="1.5"/></transform>)j"),
        Json::parse(R"j({"type": "checkerboard", "a": 0.2, "b": 0.4, "scale": [4, 2]})j"));
    EXPECT_EQ(error("<bsdf type=\"diffuse\" id=\"m\"><texture type=\"checkerboard\" "
                    "name=\"reflectance\">\n<transform name=\"to_uv\"><translate x=\"0.3\"/>"
                    "</transform></texture></bsdf>"),
              where(2) +
                  ": <texture type=\"checkerboard\">: a to_uv translation that is not a multiple "
                  "of 1/2 is not supported on a checkerboard (lamina's has no offset)");
    EXPECT_EQ(error("<bsdf type=\"diffuse\" id=\"m\"><texture type=\"checkerboard\" "
                    "name=\"reflectance\">\n<transform name=\"to_uv\"><rotate z=\"1\" "
                    "angle=\"30\"/></transform></texture></bsdf>"),
              where(2) +
                  ": <texture type=\"checkerboard\">: a to_uv that rotates or shears uv is not "
                  "supported (lamina's textures scale and offset u and v)");
}

// An alpha is Texture::eval_1, whose checkerboard gives color0 where eval gives color1
// (checkerboard.cpp's eval_1: m0 = mask.x != mask.y); lamina's textured roughness is
// sqrt(alpha) (conductor_reader.cpp: alpha = roughness^2).
TEST_F(MitsubaCorpusConstructs, CheckerboardAlphaBecomesTheRoughnessOfItsSquareRoots) {
    const ImportedScene s = material(R"j(<bsdf type="roughdielectric" id="m">
<texture name="alpha" type="checkerboard">
  <transform name="to_uv"><scale x="5" y="5"/></transform>
  <float name="color0" value="0.0"/><float name="color1" value="0.16"/>
</texture></bsdf>
<shape type="sphere"><ref id="m"/></shape>)j");
    const Json& m = s.scene["materials"]["m"];
    EXPECT_EQ(m["roughness"],
              Json::parse(R"j({"texture": "checkerboard (line 3) as roughness"})j"));
    EXPECT_EQ(m["distribution"], "beckmann");
    EXPECT_FALSE(m.contains("alpha"));
    EXPECT_EQ(s.scene["textures"]["checkerboard (line 3) as roughness"],
              Json::parse(R"j({"type": "checkerboard", "a": 0.4, "b": 0.0, "scale": [10, 10]})j"));
    const SceneDesc loaded = loadScene(scene(R"j(<bsdf type="roughconductor" id="m">
<texture name="alpha_u" type="checkerboard" id="t"/><ref name="alpha_v" id="t"/></bsdf>
<shape type="sphere"><ref id="m"/></shape>)j" +
                                             std::string(kLight)));
    ASSERT_EQ(loaded.materialTextures.size(), 1u);
    EXPECT_GE(loaded.materialTextures[0].roughness, 0);
    EXPECT_EQ(error("<bsdf type=\"roughconductor\" id=\"m\">\n<texture name=\"alpha_u\" "
                    "type=\"checkerboard\"/><texture name=\"alpha_v\" type=\"checkerboard\"/>"
                    "</bsdf>"),
              where(2) +
                  ": <bsdf type=\"roughconductor\">: a textured alpha_u / alpha_v is supported "
                  "only as one texture given to both (lamina's textured roughness is isotropic)");
    EXPECT_EQ(
        error("<bsdf type=\"roughconductor\" id=\"m\"><texture name=\"alpha\" "
              "type=\"checkerboard\">\n<float name=\"color0\" value=\"2\"/></texture></bsdf>"),
        where(2) +
            ": <texture type=\"checkerboard\">: parameter \"color0\": an alpha must be in "
            "[0, 1] for lamina");
}

// Rendered: a lambert square under a uniform environment of radiance 1 reflects radiance equal
// to its reflectance, so each pixel of an orthographic view is color0 or color1 where Mitsuba's
// formula puts them (mitsuba3 rectangle.cpp: uv = ((x + 1) / 2, (y + 1) / 2) on [-1, 1]^2).
// An orthographic 48 x 48 view of the 2 x 2 rectangle at the origin (Mitsuba's), 64 samples a
// pixel, in a uniform sky, the rectangle's BSDF `bsdf`.
std::string checkerScene(const std::string& bsdf) {
    return R"j(<sensor type="orthographic">
  <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
  <film type="hdrfilm"><integer name="width" value="48"/><integer name="height" value="48"/>
    <rfilter type="box"/></film>
  <sampler type="independent"><integer name="sample_count" value="64"/></sampler>
</sensor>
<integrator type="path"><integer name="max_depth" value="2"/></integrator>
<shape type="rectangle">)j" +
           bsdf + R"j(</shape>
<emitter type="constant"/>)j";
}

/// The pixels of checkerScene's image inside the cells of a checkerboard with to_uv scale 1.5 x 1
/// and translate 0.5 (those a cell edge crosses left out) against `first` in the cells of
/// Mitsuba's color0 and `second` in the others: every pixel nearer its own value than the other
/// cells', and the mean within 1% (each pixel's 64 samples of a uniform light estimate its value
/// with a relative standard deviation below 5%: the mean of hundreds of pixels lies within 1%).
void expectCheckerCells(const Film& film, double first, double second) {
    constexpr int kSize = 48;
    const double sx = 1.5, sy = 1, tx = 0.5, ty = 0;
    int checked = 0, wrong = 0;
    double sum = 0, expectedSum = 0;
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i) {
            // Mitsuba's orthographic film: +x of to_world (here world -x) on the image's left.
            const double x = -1 + 2 * (i + 0.5) / kSize, y = 1 - 2 * (j + 0.5) / kSize;
            const double u = sx * (x + 1) / 2 + tx, v = sy * (y + 1) / 2 + ty;
            const double fu = u - std::floor(u), fv = v - std::floor(v);
            // A pixel spans 1/24 of the square: leave out those a cell edge crosses.
            const double margin = 1.0 / kSize;
            if (std::abs(fu - 0.5) < margin || std::abs(fv - 0.5) < margin || fu < margin ||
                fu > 1 - margin || fv < margin || fv > 1 - margin)
                continue;
            const double expected = (fu > 0.5) == (fv > 0.5) ? first : second;
            const double value = film.pixel(i, j)[1];
            ++checked;
            wrong += std::abs(value - expected) > std::abs(value - (first + second - expected));
            sum += value;
            expectedSum += expected;
        }
    std::printf("  %d pixels checked, %d nearer the other cells' value; mean %.4f, expected %.4f\n",
                checked, wrong, sum / checked, expectedSum / checked);
    EXPECT_GT(checked, kSize * kSize / 3);
    EXPECT_EQ(wrong, 0);
    EXPECT_NEAR(sum / checked, expectedSum / checked, 0.01 * expectedSum / checked);
}

TEST_F(MitsubaCorpusConstructs, RenderedCheckerboardPutsTheColoursWhereMitsubaDoes) {
    const auto file = scene(checkerScene(R"j(<bsdf type="twosided"><bsdf type="diffuse">
  <texture type="checkerboard" name="reflectance">
    <float name="color0" value="0.7"/><float name="color1" value="0.1"/>
    <transform name="to_uv"><scale x="1.5" y="1"/><translate x="0.5"/></transform>
  </texture></bsdf></bsdf>)j"));
    RenderOptions o;
    o.seed = 7;
    expectCheckerCells(*renderScene(loadScene(file), o).film, 0.7, 0.1);
}

// mitsuba3 src/bsdfs/mask.cpp: at a hit the ray goes on through the surface with probability
// 1 - opacity (a null BSDF), the opacity its texture's eval_1 clamped to [0, 1]; lamina's
// stochastic alpha test, with the texture as the shape's `alpha`. A checkerboard opacity of 1
// (color0) and 0 cuts square holes in a diffuse 0.7 rectangle: the sky (1) through the holes.
// eval_1 gives color0 where the cells' parities differ (the colour lookup where they agree).
TEST_F(MitsubaCorpusConstructs, TexturedMaskOpacityIsTheShapesAlpha) {
    const std::string mask = R"j(<bsdf type="mask">
  <texture type="checkerboard" name="opacity">
    <float name="color0" value="1"/><float name="color1" value="0"/>
    <transform name="to_uv"><scale x="1.5" y="1"/><translate x="0.5"/></transform>
  </texture><bsdf type="twosided"><bsdf type="diffuse"><float name="reflectance" value="0.7"/>
  </bsdf></bsdf></bsdf>)j";
    const ImportedScene s = import(checkerScene(mask));
    const Json& shape = s.scene["shapes"][0];
    ASSERT_TRUE(shape["alpha"].is_object()) << shape.dump();
    EXPECT_EQ(s.scene["textures"][shape["alpha"]["texture"].get<std::string>()]["type"],
              "checkerboard");
    RenderOptions o;
    o.seed = 8;
    expectCheckerCells(*renderScene(loadScene(scene(checkerScene(mask))), o).film, 1.0, 0.7);
    // A textured alpha is read at a triangle shape's uv: a sphere's is refused at its line.
    EXPECT_EQ(error("<shape type=\"sphere\">\n<bsdf type=\"mask\"><texture type=\"checkerboard\" "
                    "name=\"opacity\"/><bsdf type=\"diffuse\"/></bsdf></shape>" +
                    std::string(kLight)),
              where(2) +
                  ": <shape type=\"sphere\">: a textured mask opacity on a sphere is not "
                  "supported (lamina reads a texture alpha at a triangle mesh's uv; give a "
                  "number)");
}

// ---- polarizer -----------------------------------------------------------------------------

// mitsuba3 src/bsdfs/polarizer.cpp: the absorbing axis is the surface's v turned by theta,
// (sin theta, cos theta) in (u, v), so the transmission axis is cos theta u - sin theta v; a
// rectangle's u and v are its to_world's x and y (src/shapes/rectangle.cpp). The sheets of
// mitsuba-data's polarizer documentation scenes: scaled by 0.8, turned 45 degrees about x then
// 90 about y, so u = (0, 0, -1) and v = (sqrt 1/2, sqrt 1/2, 0).
TEST_F(MitsubaCorpusConstructs, PolarizerAxesFollowTheRectanglesUAndV) {
    const std::string placed = R"(<transform name="to_world"><scale value="0.8"/>
  <rotate x="1" angle="45"/><rotate y="1" angle="90"/><translate z="1"/></transform>)";
    const ImportedScene s =
        import("<shape type=\"rectangle\">" + placed + "<bsdf type=\"polarizer\"/></shape>\n" +
               "<shape type=\"rectangle\">" + placed +
               "<bsdf type=\"polarizer\"><spectrum name=\"theta\" value=\"90\"/>"
               "<float name=\"transmittance\" value=\"0.5\"/></bsdf></shape>" +
               kLight);
    const double h = std::sqrt(0.5);
    const std::vector<std::vector<double>> axes = {{0, 0, -1}, {-h, -h, 0}};
    for (std::size_t i = 0; i < 2; ++i) {
        const Json& m = s.scene["shapes"][i]["material"];
        EXPECT_EQ(m["type"], "polariser");
        for (std::size_t k = 0; k < 3; ++k)
            EXPECT_NEAR(m["axis"][k].get<double>(), axes[i][k], 1e-12) << i << " " << k;
    }
    EXPECT_EQ(s.scene["shapes"][1]["material"]["transmittance"], 0.5);
    EXPECT_THAT(s.warnings, ::testing::Contains(HasSubstr("polarizer became lamina's polariser")));
    EXPECT_EQ(
        error("<shape type=\"sphere\"><bsdf type=\"polarizer\"/></shape>" + std::string(kLight)),
        where(2) +
            ": <bsdf type=\"polarizer\">: a polarizer is supported as a rectangle's own BSDF "
            "only (its axis follows the surface's u and v directions, which lamina's "
            "polariser takes as a world axis)");
    EXPECT_THAT(error("<shape type=\"rectangle\"><bsdf type=\"polarizer\"><boolean "
                      "name=\"polarizing\" value=\"false\"/></bsdf></shape>" +
                      std::string(kLight)),
                HasSubstr("polarizing false (a neutral density filter) is not supported"));
}

// The three documentation scenes' point, rendered in lamina's polarised mode: a lamp of radiance
// 1 seen through polarizer sheets at theta 0 and 0 passes 1/2, at 0 and 90 nothing, at 0, 45 and
// 90 1/8 (Malus's law twice). The sheets are deltas seen at normal incidence (a 0.5-degree field
// of view: 5 degrees already tilts the corners enough to move 1/8 by 0.26%), every camera ray
// reaches the lamp, and the camera and wavelength samples come before
// any scattering: each pixel is the lamp's alone (the same seed) times the closed form, to float
// rounding.
TEST_F(MitsubaCorpusConstructs, PolarizerSheetsRenderMalussLaw) {
    const auto sheets = [&](const std::vector<int>& thetas) {
        std::string body = R"(<sensor type="perspective"><float name="fov" value="0.5"/>
  <transform name="to_world"><lookat origin="0, 0, 5" target="0, 0, 0" up="0, 1, 0"/></transform>
  <film type="hdrfilm"><integer name="width" value="8"/><integer name="height" value="8"/>
    <rfilter type="box"/></film>
  <sampler type="independent"><integer name="sample_count" value="4"/></sampler>
</sensor>
<shape type="rectangle"><transform name="to_world"><translate z="-2"/></transform>
  <emitter type="area"><float name="radiance" value="1"/></emitter></shape>
)";
        for (std::size_t i = 0; i < thetas.size(); ++i)
            body += "<shape type=\"rectangle\"><transform name=\"to_world\"><translate z=\"" +
                    std::to_string(-0.5 * double(i)) +
                    "\"/></transform><bsdf type=\"polarizer\"><float name=\"theta\" value=\"" +
                    std::to_string(thetas[i]) + "\"/></bsdf></shape>\n";
        std::string name = "sheets";
        for (const int t : thetas)
            name += "-" + std::to_string(t);
        return loadScene(scene(body, name + ".xml"));
    };
    struct Case {
        std::vector<int> thetas;
        double expected;
    };
    RenderOptions o;
    o.mode = RenderModeKind::Polarised;
    const RenderResult lamp = renderScene(sheets({}), o);
    for (const Case& c : {Case{{0, 0}, 0.5}, Case{{0, 90}, 0.0}, Case{{0, 45, 90}, 0.125}}) {
        const RenderResult r = renderScene(sheets(c.thetas), o);
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i)
                for (std::size_t ch = 0; ch < 3; ++ch) {
                    const double alone = lamp.film->pixel(i, j)[ch];
                    ASSERT_GT(alone, 0.2);  // the lamp (spectral noise aside)
                    ASSERT_NEAR(r.film->pixel(i, j)[ch], c.expected * alone, 1e-4 * alone)
                        << c.thetas.size() << " sheets, pixel " << i << ", " << j;
                }
    }
}

// ---- bitmap --------------------------------------------------------------------------------

// mitsuba3 src/textures/bitmap.cpp: filename, raw (false: 8-bit sRGB decoded), filter_type,
// wrap_mode (repeat), to_uv; looked up at to_uv(uv), pixel centres at (i + 1/2) / width as in
// lamina's image texture, whose scale and offset take a to_uv that scales and translates.
TEST_F(MitsubaCorpusConstructs, BitmapOnAColourParameter) {
    write("wood.png", "not read by the importer");
    const ImportedScene s = material(R"j(<bsdf type="roughplastic" id="m">
<texture type="bitmap" name="diffuse_reflectance">
  <string name="filename" value="wood.png"/><boolean name="raw" value="false"/>
  <transform name="to_uv"><scale x="2" y="3"/><translate x="0.5" y="0.25"/></transform>
</texture></bsdf>
<shape type="obj"><string name="filename" value="wood.png"/><ref id="m"/></shape>)j");
    EXPECT_EQ(
        s.scene["materials"]["m"]["base"],
        Json::parse(
            R"j({"type": "lambert", "reflectance": {"texture": "bitmap wood.png (line 3)"}})j"));
    EXPECT_EQ(s.scene["textures"]["bitmap wood.png (line 3)"],
              Json::parse(R"j({"type": "image", "file": "wood.png", "color_space": "srgb",
                              "scale": [2, 3], "offset": [0.5, 0.25]})j"));
    std::vector<std::string> bitmapWarnings;
    for (const std::string& w : s.warnings)
        if (w.find("bitmap") != std::string::npos) bitmapWarnings.push_back(w);
    EXPECT_THAT(bitmapWarnings,
                ElementsAre(HasSubstr(where(3) + ": bitmap became an image texture: Mitsuba "
                                                 "reads v = 0 at the image's top row")));
}

// A bitmap as a microfacet alpha (Texture::eval_1, bilinear): lamina's textured roughness is
// sqrt(alpha), so the importer takes the square root after the lookup (a `power` texture of 1/2),
// where Mitsuba takes alpha = the lookup.
TEST_F(MitsubaCorpusConstructs, BitmapAlphaIsTheSquareRootOfTheLookup) {
    write("rough.png", "not read by the importer");
    const ImportedScene s = material(R"j(<bsdf type="roughconductor" id="m">
<texture type="bitmap" name="alpha">
  <string name="filename" value="rough.png"/><boolean name="raw" value="true"/>
</texture></bsdf>
<shape type="obj"><string name="filename" value="rough.png"/><ref id="m"/></shape>)j");
    const std::string root = s.scene["materials"]["m"]["roughness"]["texture"];
    EXPECT_EQ(root, "bitmap rough.png (line 3) as roughness");
    EXPECT_EQ(s.scene["textures"][root],
              Json::parse(R"j({"type": "power", "texture": "bitmap rough.png (line 3)",
                              "exponent": 0.5})j"));
    EXPECT_EQ(s.scene["textures"]["bitmap rough.png (line 3)"]["color_space"], "linear");
    int channel = 0;
    for (const std::string& w : s.warnings)
        channel += w.find("reads its first channel where Mitsuba reads the luminance") !=
                   std::string::npos;
    EXPECT_EQ(channel, 1);
}

// roughplastic's textured alpha is its coat's: lamina's coated takes a textured roughness.
TEST_F(MitsubaCorpusConstructs, RoughPlasticsTexturedAlphaIsTheCoatsRoughness) {
    const ImportedScene s = material(R"j(<bsdf type="roughplastic" id="m">
<texture type="checkerboard" name="alpha"><float name="color0" value="0.04"/>
  <float name="color1" value="0.25"/></texture></bsdf>
<shape type="sphere"><ref id="m"/></shape>)j");
    const Json& m = s.scene["materials"]["m"];
    EXPECT_EQ(m["type"], "coated");
    const std::string root = m["roughness"]["texture"];
    EXPECT_EQ(s.scene["textures"][root]["type"], "checkerboard");
    // alpha = roughness^2: the checkerboard of the square roots.
    EXPECT_NEAR(
        s.scene["textures"][root]["a"].get<double>() + s.scene["textures"][root]["b"].get<double>(),
        0.2 + 0.5, 1e-12);
    EXPECT_FALSE(m.contains("alpha"));
}

TEST_F(MitsubaCorpusConstructs, NamedBitmapUsedTwiceWarnsOnce) {
    write("w.png", "x");
    const ImportedScene s = import(
        R"j(<texture type="bitmap" id="wood"><string name="filename" value="w.png"/></texture>
<shape type="sphere"><bsdf type="diffuse"><ref name="reflectance" id="wood"/></bsdf></shape>
<shape type="sphere"><bsdf type="diffuse"><ref name="reflectance" id="wood"/></bsdf></shape>)j" +
        std::string(kLight));
    EXPECT_EQ(s.scene["shapes"][1]["material"]["reflectance"],
              Json::parse(R"j({"texture": "wood"})j"));
    EXPECT_EQ(s.scene["textures"]["wood"],
              Json::parse(R"j({"type": "image", "file": "w.png", "color_space": "srgb"})j"));
    int bitmapWarnings = 0;
    for (const std::string& w : s.warnings)
        bitmapWarnings += w.find("bitmap became") != std::string::npos;
    EXPECT_EQ(bitmapWarnings, 1);
}

// Unnamed textures are named by their line, and by their file when it is an included one: two
// files' checkerboards on the same line stay two textures.
TEST_F(MitsubaCorpusConstructs, UnnamedTexturesOfTwoFilesKeepTheirOwnNames) {
    writeIn("part.xml",
            "<scene version=\"3.0.0\">\n<bsdf type=\"diffuse\" id=\"b\"><texture "
            "type=\"checkerboard\" name=\"reflectance\"><float name=\"color0\" "
            "value=\"0.9\"/></texture></bsdf>\n</scene>");
    const ImportedScene s = import(
        "<bsdf type=\"diffuse\" id=\"a\"><texture type=\"checkerboard\" name=\"reflectance\"/>"
        "</bsdf>\n<include filename=\"part.xml\"/>\n<shape type=\"sphere\"><ref id=\"a\"/></shape>"
        "<shape type=\"sphere\"><ref id=\"b\"/></shape>" +
        std::string(kLight));
    EXPECT_EQ(s.scene["materials"]["a"]["reflectance"]["texture"], "checkerboard (line 2)");
    EXPECT_EQ(s.scene["materials"]["b"]["reflectance"]["texture"],
              "checkerboard (part.xml line 2)");
    EXPECT_EQ(s.scene["textures"]["checkerboard (part.xml line 2)"]["a"], 0.9);
    EXPECT_EQ(s.scene["textures"]["checkerboard (line 2)"]["a"], 0.4);
}

TEST_F(MitsubaCorpusConstructs, BitmapRefusalsNameTheLine) {
    write("w.png", "x");
    EXPECT_EQ(error("<bsdf type=\"diffuse\" id=\"m\"><texture type=\"bitmap\" "
                    "name=\"reflectance\">\n<string name=\"filename\" value=\"w.png\"/>"
                    "<string name=\"wrap_mode\" value=\"clamp\"/></texture></bsdf>"),
              where(2) +
                  ": <texture type=\"bitmap\">: wrap_mode \"clamp\" is not supported (lamina's "
                  "images repeat)");
    EXPECT_EQ(error("<bsdf type=\"diffuse\" id=\"m\"><texture type=\"bitmap\" "
                    "name=\"reflectance\">\n<string name=\"filename\" value=\"w.png\"/>"
                    "<transform name=\"to_uv\"><scale y=\"-1\"/></transform></texture></bsdf>"),
              where(2) +
                  ": <texture type=\"bitmap\">: a to_uv that mirrors or collapses a bitmap is "
                  "not supported (lamina's image scale is positive)");
    EXPECT_EQ(error("<bsdf type=\"diffuse\" id=\"m\">\n<texture type=\"mesh_attribute\" "
                    "name=\"reflectance\"/></bsdf>"),
              where(3) +
                  ": <texture type=\"mesh_attribute\">: the texture plugin \"mesh_attribute\" is "
                  "not supported (bitmap, checkerboard)");
    EXPECT_EQ(error("<bsdf type=\"blendbsdf\" id=\"m\">\n<bsdf type=\"diffuse\"><texture "
                    "type=\"checkerboard\" name=\"reflectance\"/></bsdf><bsdf type=\"diffuse\"/>"
                    "</bsdf>"),
              where(2) +
                  ": <bsdf type=\"blendbsdf\">: a textured BSDF inside blendbsdf is not "
                  "supported (lamina's mix takes untextured materials)");
}

}  // namespace
}  // namespace lamina::render
