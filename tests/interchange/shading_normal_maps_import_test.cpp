// Bump and normal maps from pbrt-v4 (a material's `displacement` and `normalmap`) and Mitsuba 3
// (the `bumpmap` and `normalmap` BSDF wrappers) become lamina's `displacement` and `normal_map`
// (docs/interchange.md): the translated JSON compared exactly, a warning per approximation, the
// refusals with file and line, and the translated documents load with the maps on their
// materials. The image files are EXRs written by the test.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lamina/image/image_io.h"
#include "lamina/interchange/scene_import.h"
#include "lamina/scene/scene_description.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::errorOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

class ShadingNormalMapImport : public lamina::testing::ScratchDirectoryTest {
  protected:
    void SetUp() override {
        ScratchDirectoryTest::SetUp();
        const std::vector<float> texels(2 * 2 * 3, 0.5f);
        writeFloatExr(dir_ / "h.exr", 2, 2, {"R", "G", "B"}, texels);
        writeFloatExr(dir_ / "n.exr", 2, 2, {"R", "G", "B"}, texels);
    }
    ImportedScene import(const std::string& name, const std::string& text) {
        file_ = write(name, text);
        return importScene(file_, dir_);
    }
    /// "FILE:LINE" in the pbrt-v4 file (s.pbrt) or the Mitsuba file (scene.xml).
    std::string pbrtAt(int line) const { return at("s.pbrt", line); }
    std::string xmlAt(int line) const { return at("scene.xml", line); }
    std::string at(const std::string& name, int line) const {
        return (dir_ / name).string() + ":" + std::to_string(line);
    }
    std::filesystem::path file_;
};

constexpr const char* kPbrtPrelude =
    "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
    "LightSource \"point\" \"rgb I\" [1 1 1]\n";

TEST_F(ShadingNormalMapImport, PbrtDisplacementAndNormalMapBecomeTheMaterialsKeys) {
    const ImportedScene s = import(
        "s.pbrt", std::string(kPbrtPrelude) +
                      "Texture \"bumps\" \"float\" \"imagemap\" \"string filename\" \"h.exr\"\n"
                      "Material \"diffuse\" \"texture displacement\" \"bumps\"\n"
                      "Shape \"sphere\"\n"
                      "Material \"dielectric\" \"string normalmap\" \"n.exr\"\n"
                      "Shape \"disk\"\n"
                      "Material \"diffuse\" \"float displacement\" 0.5\n"
                      "Shape \"sphere\" \"float radius\" 2\n"
                      "Material \"diffuse\" \"string normalmap\" \"n.exr\" "
                      "\"texture displacement\" \"bumps\"\n"
                      "Shape \"sphere\" \"float radius\" 3\n");
    const Json& materials = s.scene["materials"];
    ASSERT_EQ(materials.size(), 4u) << s.scene.dump();
    std::vector<Json> byShape;
    for (const Json& shape : s.scene["shapes"])
        byShape.push_back(materials[shape["material"].get<std::string>()]);
    EXPECT_EQ(byShape[0], Json::parse(R"j({"type": "lambert", "reflectance": 0.5,
        "displacement": {"texture": "bumps (float)"
}
})j"));
    EXPECT_EQ(byShape[1], Json::parse(R"j({"type": "dielectric", "ior": 1.5,
        "normal_map": {"texture": "normal map n.exr"}})j"));
    EXPECT_EQ(byShape[2], Json::parse(R"j({"type": "lambert", "reflectance": 0.5})j"));
    EXPECT_EQ(byShape[3], Json::parse(R"j({"type": "lambert", "reflectance": 0.5,
        "normal_map": {"texture": "normal map n.exr"}})j"));
    EXPECT_EQ(s.scene["textures"]["normal map n.exr"],
              Json::parse(R"j({"type": "image", "file": "n.exr", "color_space": "linear"})j"));
    EXPECT_EQ(s.scene["textures"]["bumps (float)"],
              Json::parse(R"j({"type": "image", "file": "h.exr", "color_space": "linear",
                              "scale": [1, 1]})j"));
    EXPECT_THAT(
        s.warnings,
        ElementsAre(pbrtAt(6) + ": the bump map's slopes are differences over 0.0005 in uv "
                                "(pbrt-v4 differences over the pixel's footprint with ray "
                                "differentials: bumps finer than a pixel look sharper in lamina)",
                    pbrtAt(10) + ": a constant displacement was dropped (it turns only "
                                 "interpolated vertex normals, slightly, in pbrt-v4)",
                    pbrtAt(12) + ": displacement ignored: the material's normalmap replaces it, "
                                 "as in pbrt-v4"));
    const SceneDesc scene = loadScene(file_);
    int bumped = 0, mapped = 0;
    for (const MaterialTextures& t : scene.materialTextures) {
        bumped += t.displacement >= 0;
        mapped += t.normalMap >= 0;
    }
    EXPECT_EQ(bumped, 1);
    EXPECT_EQ(mapped, 2);
}

TEST_F(ShadingNormalMapImport, PbrtRefusesMapsInsideAMixAndMissingFiles) {
    EXPECT_EQ(errorOf([&] {
                  import("s.pbrt", std::string(kPbrtPrelude) +
                                       "MakeNamedMaterial \"a\" \"string type\" \"diffuse\" "
                                       "\"string normalmap\" \"n.exr\"\n"
                                       "MakeNamedMaterial \"b\" \"string type\" \"diffuse\"\n"
                                       "MakeNamedMaterial \"ab\" \"string type\" \"mix\" "
                                       "\"string materials\" [\"a\" \"b\"]\n"
                                       "NamedMaterial \"ab\"\nShape \"sphere\"\n");
              }),
              pbrtAt(7) +
                  ": mix: a material with a bump or normal map cannot be mixed (lamina's "
                  "maps belong to the material a shape uses)");
    EXPECT_THAT(errorOf([&] {
                    import("s.pbrt", std::string(kPbrtPrelude) +
                                         "Material \"diffuse\" \"string normalmap\" \"no.png\"\n"
                                         "Shape \"sphere\"\n");
                }),
                HasSubstr(pbrtAt(5) + ": Material \"diffuse\": parameter \"string normalmap\""));
}

constexpr const char* kMitsubaLight = "<shape type=\"sphere\"><emitter type=\"area\"/></shape>\n";

TEST_F(ShadingNormalMapImport, MitsubaWrappersBecomeTheMaterialsKeys) {
    const ImportedScene s = import("scene.xml", std::string(R"j(<scene version="3.0.0">
<bsdf type="bumpmap" id="bumpy">
  <texture type="bitmap"><string name="filename" value="h.exr"/><boolean name="raw" value="true"/></texture>
  <float name="scale" value="0.25"/>
  <bsdf type="diffuse"/>
</bsdf>
<shape type="sphere"><ref id="bumpy"/></shape>
<shape type="sphere">
  <bsdf type="twosided"><bsdf type="normalmap">
    <boolean name="use_shadowing_function" value="false"/>
    <texture type="bitmap" name="normalmap"><string name="filename" value="n.exr"/><boolean name="raw" value="true"/></texture>
    <bsdf type="roughconductor"/>
  </bsdf></bsdf>
</shape>
)j") + kMitsubaLight + "</scene>\n");
    EXPECT_EQ(s.scene["materials"]["bumpy"], Json::parse(R"j({"type": "lambert", "reflectance": 0.5,
                  "displacement": {"texture": "bitmap h.exr (line 3) times 0.25"}})j"));
    EXPECT_EQ(s.scene["textures"]["bitmap h.exr (line 3)"],
              Json::parse(R"j({"type": "image", "file": "h.exr", "color_space": "linear"})j"));
    EXPECT_EQ(s.scene["textures"]["bitmap h.exr (line 3) times 0.25"],
              Json::parse(R"j({"type": "scale", "texture": "bitmap h.exr (line 3)",
                              "scale": 0.25
})j"));
    const Json& conductor = s.scene["shapes"][1]["material"];
    EXPECT_EQ(conductor["normal_map"], Json::parse(R"j({"texture": "bitmap n.exr (line 11)"
    })j"));
    EXPECT_EQ(conductor["type"], "conductor");
    std::vector<std::string> mapWarnings;
    for (const std::string& w : s.warnings)
        if (w.find("bitmap") != std::string::npos || w.find("bump") != std::string::npos ||
            w.find("shadowing") != std::string::npos)
            mapWarnings.push_back(w);
    EXPECT_THAT(
        mapWarnings,
        ElementsAre(xmlAt(2) +
                        ": the shadowing function of the perturbed "
                        "normal (Conty Estevez et al. 2019) is not applied: lamina keeps Veach's "
                        "shading-normal rules, which darken the terminator differently",
                    HasSubstr(xmlAt(3) + ": bitmap became an image texture: "
                                         "Mitsuba reads v = 0 at the image's top row"),
                    HasSubstr(xmlAt(2) + ": bumpmap became the material's "
                                         "displacement: lamina's bump includes the h dn/du term"),
                    HasSubstr(xmlAt(11) + ": bitmap became an image texture")));
    const SceneDesc scene = loadScene(file_);
    int bumped = 0, mapped = 0;
    for (const MaterialTextures& t : scene.materialTextures) {
        bumped += t.displacement >= 0;
        mapped += t.normalMap >= 0;
    }
    EXPECT_EQ(bumped, 1);
    EXPECT_EQ(mapped, 1);
}

TEST_F(ShadingNormalMapImport, MitsubaRefusesWhatLaminaCannotMap) {
    const auto error = [&](const std::string& bsdf) {
        return errorOf([&] {
            import("scene.xml",
                   "<scene version=\"3.0.0\">\n" + bsdf + "\n" + kMitsubaLight + "</scene>\n");
        });
    };
    const std::string raw = R"j(<boolean name="raw" value="true"/>)j";
    EXPECT_EQ(error(R"j(<bsdf type="normalmap" id="m"><texture type="bitmap" name="normalmap">)j"
                    R"j(<string name="filename" value="n.exr"/></texture><bsdf type="diffuse"/>)j"
                    "</bsdf>"),
              xmlAt(2) +
                  ": <bsdf type=\"normalmap\">: a normalmap's bitmap decoded from sRGB is "
                  "not supported: set raw to true (its texels are vectors)");
    EXPECT_EQ(error(R"j(<bsdf type="bumpmap" id="m"><texture type="checkerboard"/>)j"
                    R"j(<bsdf type="diffuse"/></bsdf>)j"),
              xmlAt(2) +
                  ": <texture type=\"checkerboard\">: a bumpmap's or normalmap's texture "
                  "must be a bitmap (lamina reads image files)");
    EXPECT_EQ(error(R"j(<bsdf type="bumpmap" id="m"><float name="scale" value="-1"/>)j"
                    R"j(<texture type="bitmap"><string name="filename" value="h.exr"/>)j" +
                    raw + R"j(</texture><bsdf type="diffuse"/></bsdf>)j"),
              xmlAt(2) +
                  ": <bsdf type=\"bumpmap\">: scale must be in [0, 1e6] for lamina (a "
                  "negative height is not supported)");
    EXPECT_EQ(
        error(R"j(<bsdf type="blendbsdf" id="m"><bsdf type="bumpmap">)j"
              R"j(<texture type="bitmap"><string name="filename" value="h.exr"/>)j" +
              raw + R"j(</texture><bsdf type="diffuse"/></bsdf><bsdf type="diffuse"/></bsdf>)j"),
        xmlAt(2) +
            ": <bsdf type=\"blendbsdf\">: a bumpmap or normalmap inside blendbsdf is "
            "not supported (lamina's maps belong to the material a shape uses)");
}

}  // namespace
}  // namespace lamina::render
