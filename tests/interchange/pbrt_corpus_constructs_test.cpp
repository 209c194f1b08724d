// Constructs of the pbrt-v4 scenes people publish that the importer met only in the corpus
// survey (docs/interchange.md, "A corpus survey"): a scene file that is itself gzip-compressed,
// analytic shapes under rotations rounded by exporters, the integrators' regularize and pbrt-v3's
// rrthreshold, environment portals, emitting shapes of alpha 0 or 1, and pbrt-v3 files. Each
// is compared with what pbrt-v4 does (its source named at each test).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <zlib.h>

#include <algorithm>
#include <cmath>

#include "lamina/image/image_io.h"
#include "lamina/interchange/scene_import.h"
#include "lamina/scene/scene_description.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::errorOf;
using ::testing::HasSubstr;

constexpr const char* kPrelude =
    "LookAt 0 0 0  0 0 1  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
    "LightSource \"point\" \"rgb I\" [1 1 1]\n";
constexpr int kPreludeLines = 4;

class PbrtCorpusConstructs : public lamina::testing::ScratchDirectoryTest {
  protected:
    ImportedScene import(const std::string& body) {
        file_ = write("s.pbrt", kPrelude + body);
        return importScene(file_, dir_);
    }
    std::string importError(const std::string& body) {
        return errorOf([&] { import(body); });
    }
    /// "FILE:LINE" of line `n` of the body (after the prelude).
    std::string at(int n) const {
        return (dir_ / "s.pbrt").string() + ":" + std::to_string(n + kPreludeLines);
    }
    void writeGzip(const std::string& name, const std::string& text) {
        gzFile out = gzopen((dir_ / name).string().c_str(), "wb");
        ASSERT_NE(out, nullptr);
        gzwrite(out, text.data(), unsigned(text.size()));
        gzclose(out);
    }
    std::filesystem::path file_;
};

// pbrt-v4 opens the file it is started on through Tokenizer::CreateFromFile, which
// decompresses a .gz name (parser.cpp): a whole scene may be a .pbrt.gz.
TEST_F(PbrtCorpusConstructs, ASceneFileMayBeGzipCompressed) {
    const std::string text = std::string(kPrelude) + "Shape \"sphere\" \"float radius\" 2\n";
    writeGzip("whole.pbrt.gz", text);
    const ImportedScene compressed = importScene(dir_ / "whole.pbrt.gz", dir_);
    const std::filesystem::path plain = write("plain.pbrt", text);
    EXPECT_EQ(compressed.format, SceneFormat::Pbrt);
    EXPECT_EQ(compressed.scene, importScene(plain, dir_).scene);
    EXPECT_EQ(detectSceneFormat(dir_ / "whole.pbrt.gz"), SceneFormat::Pbrt);
    // A broken stream is an error naming the file, not a tokenizer error about byte 0x1f.
    write("broken.pbrt.gz", std::string("\x1f\x8b\x08\x00\x00\x00\x00\x00garbage", 15));
    EXPECT_THAT(errorOf([&] { importScene(dir_ / "broken.pbrt.gz", dir_); }),
                HasSubstr("broken.pbrt.gz"));
}

// A sphere under a rotation written with 6 digits (as exporters write matrices) and a uniform
// scale of 2 stays a sphere of radius 2 x 1.5 centred where the matrix puts its origin; a
// shear is still refused (lamina's analytic shapes stay round, and so do pbrt-v4's only under
// similarities).
TEST_F(PbrtCorpusConstructs, AnalyticShapesTakeRoundedRotations) {
    // 2 x a rotation by 30 degrees about z, cos and sin rounded to 6 digits, then a translation.
    const ImportedScene s = import(
        "Transform [ 1.732051 1.0 0 0  -1.0 1.732051 0 0  0 0 2 0  5 6 7 1 ]\n"
        "Shape \"sphere\" \"float radius\" 1.5\n");
    const Json& sphere = s.scene["shapes"][0];
    EXPECT_EQ(sphere["center"], Json::parse("[5, 6, 7]"));
    EXPECT_NEAR(sphere["radius"].get<double>(), 3.0, 3e-6);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_THAT(s.warnings[0],
                HasSubstr(at(2) + ": Shape \"sphere\": its transform is a rotation"));
    // An exact similarity keeps its scale to the last digit and says nothing.
    const ImportedScene exact = import("Scale 2 2 2\nShape \"sphere\" \"float radius\" 1.5\n");
    EXPECT_EQ(exact.scene["shapes"][0]["radius"], 3.0);
    EXPECT_TRUE(exact.warnings.empty());
}

// A quadric under a shear or an uneven scale (disney-cloud's boundary sphere, Scale 1 0.5 1.2
// and the like) becomes an object of the quadric in its own space and an instance placing it
// by the transform: exact, as lamina's instances take any invertible transform. The shape's
// material and media go with it into the object. Not where an instance cannot stand: an
// emitting one (instances cannot emit) and one inside ObjectBegin (instances do not nest).
TEST_F(PbrtCorpusConstructs, UnevenlyScaledQuadricsArePlacedByInstances) {
    const ImportedScene s = import(
        "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
        "AttributeBegin\nMediumInterface \"fog\" \"\"\nMaterial \"interface\"\n"
        "Translate 1 2 3\nScale 1 0.5 1.2\nShape \"sphere\" \"float radius\" 2\nAttributeEnd\n"
        "Transform [ 1 0.01 0 0  0 1 0 0  0 0 1 0  0 0 0 1 ]\n"
        "Shape \"disk\" \"float innerradius\" 0.5\n");
    const Json& shapes = s.scene["shapes"];
    ASSERT_EQ(shapes.size(), 2u);
    EXPECT_TRUE(s.warnings.empty());
    EXPECT_EQ(shapes[0]["type"], "instance");
    EXPECT_EQ(shapes[0]["transform"], Json::parse(R"([{"matrix": [1, 0, 0, 1,  0, 0.5, 0, 2,
                                                                  0, 0, 1.2, 3,  0, 0, 0, 1]}])"));
    const Json& ellipsoid = s.scene["objects"][shapes[0]["object"].get<std::string>()];
    ASSERT_EQ(ellipsoid.size(), 1u);
    EXPECT_EQ(ellipsoid[0]["type"], "sphere");
    EXPECT_EQ(ellipsoid[0]["radius"], 2.0);
    EXPECT_EQ(ellipsoid[0]["center"], Json::parse("[0, 0, 0]"));
    EXPECT_EQ(ellipsoid[0]["interior"], "fog");
    EXPECT_FALSE(ellipsoid[0].contains("transform"));
    const Json& annulus = s.scene["objects"][shapes[1]["object"].get<std::string>()];
    EXPECT_EQ(annulus[0]["inner_radius"], 0.5);
    EXPECT_NE(shapes[0]["object"], shapes[1]["object"]);
    // Both load as lamina scenes.
    const std::filesystem::path json = write("ellipsoid.json", s.scene.dump());
    EXPECT_NO_THROW(loadScene(json));

    EXPECT_EQ(importError("AttributeBegin\nAreaLightSource \"diffuse\"\nScale 2 1 1\n"
                          "Shape \"sphere\"\nAttributeEnd\n"),
              at(4) +
                  ": Shape \"sphere\" under a shear or an uneven scale is not supported when it "
                  "emits (lamina places it as an instance, and instances cannot emit)");
    EXPECT_THAT(importError("ObjectBegin \"o\"\nScale 2 1 1\nShape \"sphere\"\nObjectEnd\n"
                            "ObjectInstance \"o\"\n"),
                HasSubstr(at(3) + ": Shape \"sphere\" under a shear or an uneven scale is not "
                                  "supported inside ObjectBegin"));
}

// pbrt-v4's regularize (PathIntegrator and VolPathIntegrator::Create) changes the estimator,
// not the scene: lamina renders the unregularised image and says so. rrthreshold is pbrt-v3's
// (pbrt-v4's --upgrade removes it, FormattingParserTarget::Integrator); roulette changes only
// the noise.
TEST_F(PbrtCorpusConstructs, RegularizeAndRrthresholdAreWarnedAbout) {
    file_ = write("s.pbrt",
                  "Integrator \"volpath\" \"integer maxdepth\" 8 \"bool regularize\" true\n"
                  "    \"float rrthreshold\" 0\n" +
                      std::string(kPrelude) + "Shape \"sphere\"\n");
    const ImportedScene s = importScene(file_, dir_);
    EXPECT_EQ(s.scene["integrator"], Json::parse(R"({"type": "path", "max_depth": 8})"));
    const std::string file = file_.string();
    EXPECT_THAT(s.warnings, ::testing::Contains(HasSubstr(file + ":1: regularize ignored")));
    EXPECT_THAT(s.warnings, ::testing::Contains(HasSubstr(file + ":2: rrthreshold ignored")));
    EXPECT_NO_THROW(loadScene(file_));
}

// pbrt-v4's Attribute directive (BasicSceneBuilder::Attribute, scene.cpp) gives default
// parameters to the shapes, lights, materials, media or textures that follow it in its
// attribute block: a directive's own parameter wins, then the newest default
// (ParameterDictionary's lookup order, paramdict.cpp), and a default a directive does not read
// is not an error (mayBeUnused). So a file with defaults is the file with them written out.
TEST_F(PbrtCorpusConstructs, AttributeDefaultsAreTheParametersWrittenOut) {
    const ImportedScene withDefaults = import(
        "AttributeBegin\n"
        "  Attribute \"shape\" \"float radius\" 5\n"
        "  Attribute \"shape\" \"float radius\" 2\n"
        "  Attribute \"material\" \"rgb reflectance\" [0.2 0.3 0.4]\n"
        "  Attribute \"light\" \"float scale\" 3\n"
        "  Material \"diffuse\"\n"
        "  Shape \"sphere\"\n"
        "  Shape \"sphere\" \"float radius\" 3\n"
        "  Shape \"trianglemesh\" \"point3 P\" [0 0 0  1 0 0  0 1 0] \"integer indices\" [0 1 2]\n"
        "  LightSource \"point\" \"rgb I\" [1 1 1] \"point3 from\" [0 5 0]\n"
        "AttributeEnd\n"
        "Shape \"sphere\"\n");
    const ImportedScene written = import(
        "AttributeBegin\n"
        "  Material \"diffuse\" \"rgb reflectance\" [0.2 0.3 0.4]\n"
        "  Shape \"sphere\" \"float radius\" 2\n"
        "  Shape \"sphere\" \"float radius\" 3\n"
        "  Shape \"trianglemesh\" \"point3 P\" [0 0 0  1 0 0  0 1 0] \"integer indices\" [0 1 2]\n"
        "  LightSource \"point\" \"rgb I\" [1 1 1] \"point3 from\" [0 5 0] \"float scale\" 3\n"
        "AttributeEnd\n"
        "Shape \"sphere\"\n");
    EXPECT_EQ(withDefaults.scene, written.scene);
    ASSERT_EQ(withDefaults.scene["shapes"].size(), 4u);
    EXPECT_EQ(withDefaults.scene["shapes"][0]["radius"], 2.0);
    EXPECT_EQ(withDefaults.scene["shapes"][3]["radius"], 1.0);  // after AttributeEnd
    EXPECT_EQ(importError("Attribute \"camera\" \"float fov\" 30\n"),
              at(1) +
                  ": Attribute \"camera\": expected the target \"shape\", \"light\", "
                  "\"material\", \"medium\" or \"texture\"");
    // A default the directive reads is checked like its own parameter, at the Attribute line.
    EXPECT_THAT(
        importError("Attribute \"shape\" \"string radius\" \"big\"\nShape \"sphere\"\n"),
        HasSubstr(at(1) + ": Shape \"sphere\": parameter \"string radius\" has the wrong type"));
}

// pbrt-v4's PortalImageInfiniteLight (lights.cpp) shows the environment image only through
// the portal: it becomes lamina's environment with the same corners as its `portal`
// (portal_environment.h), with no warning. A portal on a uniform L, which pbrt-v4 turns into an
// unnormalised RGB image, a portal of other than four corners and one that is not a rectangle
// (pbrt-v4 goes on with a wrong frame) are refused at the file's line.
TEST_F(PbrtCorpusConstructs, EnvironmentPortalsBecomeLaminasPortals) {
    write("sky.exr", "not read by the importer");
    const std::string light = "LightSource \"infinite\" \"string filename\" \"sky.exr\"";
    const ImportedScene plain = import(light + "\n");
    const ImportedScene portal =
        import(light + "\n    \"point3 portal\" [0 0 0  1 0 0  1 1 0  0 1 0]\n");
    Json expected = plain.scene["lights"];
    expected[1]["portal"] = Json::parse("[[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]");
    EXPECT_EQ(portal.scene["lights"], expected);
    EXPECT_TRUE(portal.warnings.empty());
    EXPECT_EQ(importError("LightSource \"infinite\" \"rgb L\" [1 1 1]\n"
                          "    \"point3 portal\" [0 0 0  1 0 0  1 1 0  0 1 0]\n"),
              at(2) +
                  ": infinite: a portal on a uniform \"L\" is not supported (pbrt-v4 turns L "
                  "into an unnormalised RGB image there): remove the portal");
    EXPECT_THAT(importError(light + " \"point3 portal\" [0 0 0  1 0 0  1 1 0]\n"),
                HasSubstr("expected the portal's four corners"));
    EXPECT_THAT(importError(light + "\n    \"point3 portal\" [0 0 0  1 0 0  1.5 1 0  0 1 0]\n"),
                HasSubstr(at(2) + ": LightSource \"infinite\": parameter \"point3 portal\" "
                                  "expected a rectangle"));
}

// pbrt-v4's SubsurfaceMaterial (materials.cpp) becomes a dielectric of its eta around the
// homogeneous medium of its coefficients times `scale`, which every shape using it holds; one
// warning says that lamina renders the volumetric transport pbrt-v4's BSSRDF approximates.
// sssdragon's material: the measured Skin1 (Jensen et al. 2001), scale 50, eta 1.5.
TEST_F(PbrtCorpusConstructs, SubsurfaceBecomesADielectricAroundItsMedium) {
    const ImportedScene s = import(
        "MakeNamedMaterial \"skin\" \"string type\" \"subsurface\" \"string name\" \"Skin1\"\n"
        "    \"float scale\" 50 \"float eta\" 1.5\n"
        "NamedMaterial \"skin\"\nShape \"sphere\"\n");
    EXPECT_EQ(s.scene["materials"]["skin"], Json::parse(R"({"type": "dielectric", "ior": 1.5})"));
    ASSERT_EQ(s.scene["shapes"].size(), 1u);
    EXPECT_EQ(s.scene["shapes"][0]["interior"], "subsurface of skin");
    EXPECT_FALSE(s.scene["shapes"][0].contains("exterior"));
    EXPECT_EQ(s.scene["media"]["subsurface of skin"],
              Json::parse(R"({"type": "homogeneous", "sigma_a": [0.032, 0.17, 0.48],
                              "sigma_s": [0.74, 0.88, 1.01], "scale": 50, "g": 0})"));
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_THAT(s.warnings[0], HasSubstr(at(1) + ": subsurface: rendered as the light transport "
                                                 "in its homogeneous medium"));
    // The lamina document loads: a dielectric shape holding a medium.
    EXPECT_NO_THROW(parseScene(s.scene.dump(), JsonSource{"<imported>", dir_}));

    // Coefficients given, with a roughness; pbrt-v4's defaults when nothing is given.
    const ImportedScene given = import(
        "Material \"subsurface\" \"rgb sigma_a\" [0.1 0.2 0.3] \"rgb sigma_s\" [1 2 3]\n"
        "    \"float g\" 0.4 \"float roughness\" 0.01\nShape \"sphere\"\n");
    const std::string name = given.scene["shapes"][0]["interior"];
    EXPECT_EQ(given.scene["media"][name]["sigma_a"], Json::parse("[0.1, 0.2, 0.3]"));
    EXPECT_EQ(given.scene["media"][name]["g"], 0.4);
    const Json& material =
        given.scene["materials"][given.scene["shapes"][0]["material"].get<std::string>()];
    EXPECT_EQ(material["ior"], 1.33);
    EXPECT_NEAR(material["alpha"].get<double>(), 0.1, 1e-12);
    const ImportedScene defaults = import("Material \"subsurface\"\nShape \"sphere\"\n");
    EXPECT_EQ(defaults.scene["media"][defaults.scene["shapes"][0]["interior"].get<std::string>()]
                            ["sigma_s"],
              Json::parse("[2.55, 3.21, 3.77]"));

    // What pbrt-v4 refuses, and what lamina cannot do faithfully.
    EXPECT_EQ(importError("Material \"subsurface\" \"rgb sigma_a\" [1 1 1]\nShape \"sphere\"\n"),
              at(1) + ": subsurface: give both sigma_a and sigma_s (as pbrt-v4 requires)");
    EXPECT_THAT(importError("Material \"subsurface\" \"rgb reflectance\" [0.5 0.5 0.5]\n"
                            "Shape \"sphere\"\n"),
                HasSubstr(at(1) + ": subsurface: \"reflectance\" (with \"mfp\") is not supported"));
    EXPECT_THAT(
        importError("Material \"subsurface\" \"string name\" \"Jelly\"\nShape \"sphere\"\n"),
        HasSubstr(at(1) + ": subsurface: no measured medium \"Jelly\""));
    EXPECT_THAT(importError("MakeNamedMaterial \"skin\" \"string type\" \"subsurface\"\n"
                            "MakeNamedMaterial \"half\" \"string type\" \"mix\"\n"
                            "    \"string materials\" [\"skin\" \"skin\"]\n"
                            "NamedMaterial \"half\"\nShape \"sphere\"\n"),
                HasSubstr("a subsurface material cannot be mixed"));
}

// pbrt-v4's DiffuseAreaLight emits nothing where AlphaMasked (lights.h: alpha <= 0 always,
// alpha >= 1 never), and its intersection skips such a surface: an emitting shape of alpha 0
// adds nothing and is left out; of alpha 1 it is the shape as it is. Between them pbrt-v4's
// test is stochastic, which lamina's emitters do not have.
TEST_F(PbrtCorpusConstructs, EmittingShapesOfAlphaZeroOrOne) {
    const std::string area = "AreaLightSource \"diffuse\" \"rgb L\" [2 2 2]\n";
    const ImportedScene zero = import("AttributeBegin\n" + area +
                                      "Shape \"sphere\" \"float alpha\" 0\nAttributeEnd\n"
                                      "Shape \"disk\"\n");
    ASSERT_EQ(zero.scene["shapes"].size(), 1u);
    EXPECT_EQ(zero.scene["shapes"][0]["type"], "disk");
    ASSERT_EQ(zero.warnings.size(), 1u);
    EXPECT_EQ(zero.warnings[0], at(3) +
                                    ": an emitting Shape \"sphere\" of alpha 0 omitted: "
                                    "pbrt-v4 neither sees it nor lets it emit");
    const ImportedScene one = import(area + "Shape \"sphere\" \"float alpha\" 1\n");
    const ImportedScene none = import(area + "Shape \"sphere\"\n");
    EXPECT_EQ(one.scene["shapes"], none.scene["shapes"]);
    EXPECT_EQ(importError(area + "Shape \"sphere\" \"float alpha\" 0.5\n"),
              at(2) + ": alpha on an emitting shape is not supported");
}

// A scene whose only material is "interface" (a medium's boundary under a point light) has
// an empty `materials` object, which loads: it was null, which the loader refused.
TEST_F(PbrtCorpusConstructs, AnInterfaceOnlySceneHasAnEmptyMaterialsObject) {
    const ImportedScene s = import(
        "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
        "AttributeBegin\nMediumInterface \"fog\" \"\"\nMaterial \"interface\"\n"
        "Shape \"sphere\"\nAttributeEnd\n");
    EXPECT_EQ(s.scene["materials"], Json::object());
    EXPECT_NO_THROW(loadScene(file_)) << errorOf([&] { loadScene(file_); });
}

// pbrt-v4 remaps a textured roughness after its lookup (alpha = sqrt(value) with
// remaproughness, TrowbridgeReitzDistribution::RoughnessToAlpha; the value itself without):
// lamina's textured roughness is sqrt(alpha), so the importer writes a `power` texture of the
// looked-up value, 1/4 or 1/2. uroughness and vroughness naming one texture are the same;
// different textures, or a texture beside a number, are anisotropic and refused. A coat's
// textured roughness is the coated material's.
// pbrt-v4-scenes' villa gives coateddiffuse "float roughness" 2: alpha sqrt(2), beyond lamina's
// microfacet models, which stop at alpha 1: clamped there with one warning.
TEST_F(PbrtCorpusConstructs, AnAlphaAboveOneBecomesOneWithAWarning) {
    const ImportedScene s = import(
        "Material \"coateddiffuse\" \"float roughness\" 2\nShape \"sphere\"\n"
        "Material \"conductor\" \"float roughness\" 0.25\nShape \"disk\"\n");
    const auto materialOf = [&](int shape) -> const Json& {
        return s.scene["materials"][s.scene["shapes"][shape]["material"].get<std::string>()];
    };
    EXPECT_EQ(materialOf(0)["alpha"], 1.0);
    EXPECT_EQ(materialOf(1)["alpha"], 0.5);
    int clamped = 0;
    for (const std::string& w : s.warnings)
        clamped += w.find("a roughness of alpha 1.414214 became lamina's largest, alpha 1") !=
                   std::string::npos;
    EXPECT_EQ(clamped, 1);
    EXPECT_NO_THROW(loadScene(file_)) << errorOf([&] { loadScene(file_); });
}

TEST_F(PbrtCorpusConstructs, TexturedRoughnessIsRemappedAfterItsLookup) {
    const ImportedScene s = import(
        "Texture \"r\" \"float\" \"checkerboard\" \"float tex1\" 0.04 \"float tex2\" 0.36\n"
        "Material \"conductor\" \"texture roughness\" \"r\"\nShape \"sphere\"\n"
        "Material \"dielectric\" \"texture uroughness\" \"r\" \"texture vroughness\" \"r\"\n"
        "    \"bool remaproughness\" false\nShape \"disk\"\n");
    const Json& conductor =
        s.scene["materials"][s.scene["shapes"][0]["material"].get<std::string>()];
    const Json& glass = s.scene["materials"][s.scene["shapes"][1]["material"].get<std::string>()];
    const std::string fourth = conductor["roughness"]["texture"];
    const std::string root = glass["roughness"]["texture"];
    EXPECT_EQ(s.scene["textures"][fourth]["type"], "power");
    EXPECT_EQ(s.scene["textures"][fourth]["exponent"], 0.25);
    EXPECT_EQ(s.scene["textures"][root]["exponent"], 0.5);
    EXPECT_EQ(s.scene["textures"][root]["texture"], s.scene["textures"][fourth]["texture"]);
    EXPECT_FALSE(conductor.contains("alpha"));
    EXPECT_NO_THROW(loadScene(file_)) << errorOf([&] { loadScene(file_); });
    const std::string texture =
        "Texture \"r\" \"float\" \"checkerboard\"\nTexture \"q\" \"float\" \"checkerboard\"\n";
    EXPECT_EQ(importError(texture + "Material \"conductor\" \"texture uroughness\" \"r\" "
                                    "\"texture vroughness\" \"q\"\nShape \"sphere\"\n"),
              at(3) +
                  ": an anisotropic textured roughness is not supported (lamina's textured "
                  "roughness is isotropic: give roughness, or one texture to uroughness and "
                  "vroughness)");
    EXPECT_THAT(importError(texture + "Material \"conductor\" \"texture roughness\" \"r\" "
                                      "\"float vroughness\" 0.1\nShape \"sphere\"\n"),
                HasSubstr("an anisotropic textured roughness is not supported"));
    const ImportedScene coat = import(texture +
                                      "Material \"coateddiffuse\" \"texture roughness\" \"r\"\n"
                                      "Shape \"sphere\"\n");
    const Json& coated =
        coat.scene["materials"][coat.scene["shapes"][0]["material"].get<std::string>()];
    EXPECT_EQ(coated["type"], "coated");
    EXPECT_EQ(coat.scene["textures"][coated["roughness"]["texture"].get<std::string>()]["exponent"],
              0.25);
    EXPECT_NO_THROW(loadScene(file_)) << errorOf([&] { loadScene(file_); });
    // The conductor under a coatedconductor's coat stays refused (a nested textured roughness).
    EXPECT_THAT(
        importError(texture + "Material \"coatedconductor\" \"texture conductor.roughness\" "
                              "\"r\"\nShape \"sphere\"\n"),
        HasSubstr("as a texture is not supported"));
}

// pbrt-v4's coateddiffuse takes a textured reflectance (CoatedDiffuseMaterial, materials.h):
// lamina's coated takes it through its base (MaterialKind::texturedThrough), the published
// scenes' most common refusal before.
TEST_F(PbrtCorpusConstructs, CoatedDiffuseTakesATexturedReflectance) {
    const ImportedScene s = import(
        "Texture \"checks\" \"spectrum\" \"checkerboard\" \"rgb tex1\" [0.8 0.8 0.8]\n"
        "    \"rgb tex2\" [0.2 0.2 0.2]\n"
        "Material \"coateddiffuse\" \"texture reflectance\" \"checks\" \"float roughness\" 0.1\n"
        "Shape \"sphere\"\n");
    const Json& material =
        s.scene["materials"][s.scene["shapes"][0]["material"].get<std::string>()];
    EXPECT_EQ(material["type"], "coated");
    const Json& reflectance = material["base"]["reflectance"];
    ASSERT_TRUE(reflectance.contains("texture"));
    EXPECT_EQ(s.scene["textures"][reflectance["texture"].get<std::string>()]["type"],
              "checkerboard");
    EXPECT_NO_THROW(loadScene(file_)) << errorOf([&] { loadScene(file_); });
}

// pbrt-v4's constant texture is its value everywhere; scale and mix take textures or constants
// for each operand (textures.h: ScaleTexture, MixTexture; tex1 0, tex2 1, amount 0.5). A float
// constant used as a scale is folded into the number; a scale by another texture is a mix of 0
// and tex at that amount (exact for amounts in [0, 1], warned about).
TEST_F(PbrtCorpusConstructs, ConstantTexturesAndConstantOperands) {
    write("h.png", "not read by the importer");
    const ImportedScene s = import(
        "Texture \"c\" \"spectrum\" \"constant\" \"rgb value\" [0.5 0.25 0.125]\n"
        "Texture \"k\" \"float\" \"constant\" \"float value\" 0.002\n"
        "Texture \"h\" \"float\" \"imagemap\" \"string filename\" \"h.png\"\n"
        "Texture \"bump\" \"float\" \"scale\" \"texture tex\" \"h\" \"texture scale\" \"k\"\n"
        "Texture \"m\" \"spectrum\" \"mix\" \"rgb tex1\" [0.1 0.2 0.3] \"texture tex2\" \"c\"\n"
        "    \"texture amount\" \"h\"\n"
        "Texture \"s\" \"spectrum\" \"scale\" \"rgb tex\" [0.5 0.5 0.5] \"texture scale\" \"h\"\n"
        "Material \"diffuse\" \"texture reflectance\" \"m\" \"texture displacement\" \"bump\"\n"
        "Shape \"sphere\"\n"
        "Material \"diffuse\" \"texture reflectance\" \"s\"\n"
        "Shape \"disk\"\n");
    const Json& textures = s.scene["textures"];
    EXPECT_EQ(textures["c"], Json::parse(R"j({"type": "mix", "a": [0.5, 0.25, 0.125],
        "b": [0.5, 0.25, 0.125], "amount": 0})j"));
    EXPECT_EQ(textures["bump (float)"],
              Json::parse(R"j({"type": "scale", "texture": "h (float)", "scale": 0.002})j"));
    EXPECT_EQ(textures["m"], Json::parse(R"j({"type": "mix", "a": [0.1, 0.2, 0.3], "b": "c",
        "amount": "h (float)"})j"));
    EXPECT_EQ(textures["s"], Json::parse(R"j({"type": "mix", "a": 0, "b": [0.5, 0.5, 0.5],
        "amount": "h (float)"})j"));
    EXPECT_THAT(s.warnings, ::testing::Contains(HasSubstr(
                                at(7) + ": texture \"scale\" by a texture became a mix of 0")));
}

// pbrt-v4's DirectionMixTexture (textures.cpp): tex1 where the geometric normal is along dir,
// tex2 across it, dir turned by the transform in effect at the Texture and normalised.
TEST_F(PbrtCorpusConstructs, DirectionMixTexturesTurnTheirDirection) {
    const ImportedScene s = import(
        "AttributeBegin\nRotate 90 0 0 1\n"
        "Texture \"d\" \"spectrum\" \"directionmix\" \"rgb tex1\" [1 0 0] \"vector3 dir\" [0 2 0]\n"
        "AttributeEnd\n"
        "Texture \"u\" \"float\" \"directionmix\"\n"
        "Material \"diffuse\" \"texture reflectance\" \"d\"\nShape \"sphere\"\n"
        "Material \"conductor\" \"texture roughness\" \"u\"\nShape \"disk\"\n");
    const Json& d = s.scene["textures"]["d"];
    EXPECT_EQ(d["type"], "direction_mix");
    EXPECT_EQ(d["a"], Json::parse("[1, 0, 0]"));
    EXPECT_EQ(d["b"], 1.0);
    ASSERT_EQ(d["direction"].size(), 3u);
    EXPECT_NEAR(d["direction"][0].get<double>(), -1.0, 1e-12);
    EXPECT_NEAR(d["direction"][1].get<double>(), 0.0, 1e-12);
    EXPECT_NEAR(d["direction"][2].get<double>(), 0.0, 1e-12);
    EXPECT_EQ(s.scene["textures"]["u (float)"],
              Json::parse(R"({"type": "direction_mix", "a": 0, "b": 1, "direction": [0, 1, 0]})"));
    EXPECT_NO_THROW(parseScene(s.scene.dump(), JsonSource{"<imported>", dir_}));
}

// pbrt-v4's UVMapping looks an image up at (uscale u + udelta, vscale v + vdelta): lamina's
// image texture with that scale and offset, a checkerboard's too.
TEST_F(PbrtCorpusConstructs, ImageMapOffsetsBecomeTheImagesOffset) {
    write("a.png", "not read by the importer");
    const ImportedScene s = import(
        "Texture \"t\" \"spectrum\" \"imagemap\" \"string filename\" \"a.png\"\n"
        "    \"float uscale\" 2 \"float udelta\" -0.5 \"float vdelta\" 0.25\n"
        "Texture \"c\" \"spectrum\" \"checkerboard\" \"float udelta\" 1\n"
        "Texture \"m\" \"spectrum\" \"mix\" \"texture tex1\" \"t\" \"texture tex2\" \"c\"\n"
        "Material \"diffuse\" \"texture reflectance\" \"m\"\nShape \"sphere\"\n");
    EXPECT_EQ(s.scene["textures"]["t"], Json::parse(R"({"type": "image", "file": "a.png",
        "color_space": "srgb", "scale": [2, 1], "offset": [-0.5, 0.25]})"));
    EXPECT_EQ(s.scene["textures"]["c"], Json::parse(R"({"type": "checkerboard", "a": 1, "b": 0,
        "scale": [1, 1], "offset": [1, 0]})"));
}

// Exporters write vscale -1 for images stored top row first (the villa of pbrt-v4-scenes,
// villa/materials.pbrt, throughout, with udelta/vdelta): pbrt-v4's UVMapping mirrors, and so
// does lamina's negative scale (TextureMappings.ANegativeScaleMirrorsAnImage). A zero scale
// is refused at its line.
TEST_F(PbrtCorpusConstructs, AMirroredImageMapKeepsItsNegativeScale) {
    write("bark.png", "not read by the importer");
    const ImportedScene s = import(
        "Texture \"b\" \"float\" \"imagemap\" \"string filename\" [ \"bark.png\" ]\n"
        "    \"string wrap\" [ \"repeat\" ] \"string mapping\" [ \"uv\" ] \"float scale\" [ 1 ]\n"
        "    \"float uscale\" [ 2 ] \"float vscale\" [ -2 ] \"float udelta\" [ -0.5 ]\n"
        "    \"float vdelta\" [ 0.5 ]\n"
        "Texture \"k\" \"spectrum\" \"mix\" \"rgb tex1\" [ 0.01 0.01 0.01 ] \"texture amount\" "
        "\"b\"\n"
        "Material \"diffuse\" \"texture reflectance\" \"k\"\nShape \"sphere\"\n");
    EXPECT_EQ(s.scene["textures"]["b (float)"], Json::parse(R"({"type": "image",
        "file": "bark.png", "color_space": "srgb", "scale": [2, -2], "offset": [-0.5, 0.5]})"));
    EXPECT_EQ(
        importError("Texture \"m\" \"spectrum\" \"imagemap\" \"string filename\" \"bark.png\"\n"
                    "    \"float vscale\" 0\n"
                    "Material \"diffuse\" \"texture reflectance\" \"m\"\nShape \"sphere\"\n"),
        at(1) + ": a zero uscale / vscale maps the whole surface to one texel");
}

// pbrt-v4's planar, spherical and cylindrical mappings (TextureMapping2D::Create) project the
// point in the space of the transform in effect at the Texture directive (renderFromTexture);
// lamina's mapping carries that transform. The two vectors and offsets as the villa's phone
// and kroken's book covers write them.
TEST_F(PbrtCorpusConstructs, ProjectedMappingsCarryTheTexturesTransform) {
    writeRgb8(dir_ / "a.png", 1, 1, {0.5f, 0.5f, 0.5f});
    const ImportedScene s = import(
        "Texture \"p\" \"spectrum\" \"imagemap\" \"string filename\" \"a.png\"\n"
        "    \"string mapping\" [ \"planar\" ] \"vector3 v1\" [ 0.5 0 0 ]\n"
        "    \"vector3 v2\" [ 0 -0.5 -0 ] \"float udelta\" [ 0.5 ] \"float vdelta\" [ -0.5 ]\n"
        "AttributeBegin\nTranslate 1 2 3\n"
        "Texture \"c\" \"spectrum\" \"imagemap\" \"string filename\" \"a.png\"\n"
        "    \"string mapping\" \"cylindrical\"\n"
        "Texture \"s\" \"float\" \"checkerboard\" \"string mapping\" \"spherical\"\n"
        "AttributeEnd\n"
        "Texture \"m\" \"spectrum\" \"mix\" \"texture tex1\" \"p\" \"texture tex2\" \"c\"\n"
        "    \"texture amount\" \"s\"\n"
        "Material \"diffuse\" \"texture reflectance\" \"m\"\nShape \"sphere\"\n");
    const Json& t = s.scene["textures"];
    EXPECT_EQ(t["p"], Json::parse(R"({"type": "image", "file": "a.png", "color_space": "srgb",
        "mapping": {"type": "planar", "v1": [0.5, 0, 0], "v2": [0, -0.5, -0.0],
                    "offset": [0.5, -0.5]}})"));
    const Json moved = Json::parse(R"([{"matrix": [1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3,
        0, 0, 0, 1]}])");
    EXPECT_EQ(t["c"], (Json{{"type", "image"},
                            {"file", "a.png"},
                            {"color_space", "srgb"},
                            {"mapping", {{"type", "cylindrical"}, {"transform", moved}}}}));
    EXPECT_EQ(t["s (float)"], (Json{{"type", "checkerboard"},
                                    {"a", 1},
                                    {"b", 0},
                                    {"mapping", {{"type", "spherical"}, {"transform", moved}}}}));
    // The translation is a scene lamina loads: the mappings are lamina's.
    EXPECT_NO_THROW(loadScene(file_, false)) << errorOf([&] { loadScene(file_, false); });
    EXPECT_EQ(importError("Texture \"x\" \"spectrum\" \"imagemap\" \"string filename\" \"a.png\"\n"
                          "    \"string mapping\" \"cubic\"\n"
                          "Material \"diffuse\" \"texture reflectance\" \"x\"\nShape \"sphere\"\n"),
              at(1) +
                  ": texture mapping \"cubic\" is not one of pbrt-v4's (uv, spherical, "
                  "cylindrical, planar)");
}

// pbrt-v4's solid noise textures (FBmTexture, WrinkledTexture, WindyTexture, MarbleTexture) with
// their defaults, placed by the point mapping of the transform at their Texture directive; the
// villa's couch and pool as it writes them (wrinkled and windy under a Scale, the windy one
// scaled by a float constant texture, both displacements), and dots with a texture inside.
TEST_F(PbrtCorpusConstructs, NoiseTexturesBecomeLaminasWithTheirPlacement) {
    const ImportedScene s = import(
        "TransformBegin\n  Scale 3 3 3\n  Texture \"couch-disp\" \"float\" \"wrinkled\"\n"
        "  Texture \"scaled\" \"float\" \"scale\" \"texture tex\" [ \"couch-disp\" ]\n"
        "      \"float scale\" [ 0.005 ]\nTransformEnd\n"
        "TransformBegin\n  Scale 6 6 6\n  Texture \"water\" \"float\" \"windy\"\n"
        "  Texture \"sc\" \"float\" \"constant\" \"float value\" [ 0.75 ]\n"
        "  Texture \"swater\" \"float\" \"scale\" \"texture tex\" [ \"water\" ]\n"
        "      \"texture scale\" [ \"sc\" ]\nTransformEnd\n"
        "Texture \"f\" \"float\" \"fbm\" \"integer octaves\" 4 \"float roughness\" 0.25\n"
        "Texture \"stone\" \"spectrum\" \"marble\" \"float scale\" 2 \"float variation\" 0.5\n"
        "TransformBegin\n  Scale 2 2 2\n"
        "  Texture \"cube\" \"float\" \"checkerboard\" \"integer dimension\" 3\n"
        "TransformEnd\n"
        "Texture \"d\" \"spectrum\" \"dots\" \"texture inside\" \"stone\"\n"
        "    \"rgb outside\" [ 0.1 0.2 0.3 ] \"float uscale\" 4 \"float vscale\" 4\n"
        "AttributeBegin\nMaterial \"diffuse\" \"texture displacement\" \"scaled\"\n"
        "    \"texture reflectance\" \"d\"\nShape \"sphere\"\nAttributeEnd\n"
        "AttributeBegin\nMaterial \"diffuse\" \"texture displacement\" \"cube\"\n"
        "Shape \"sphere\" \"float radius\" 4\nAttributeEnd\n"
        "AttributeBegin\nMaterial \"dielectric\" \"texture displacement\" \"swater\"\n"
        "Shape \"sphere\" \"float radius\" 2\nAttributeEnd\n"
        "Material \"diffuse\" \"texture displacement\" \"f\"\n"
        "Shape \"sphere\" \"float radius\" 3\n");
    const Json& t = s.scene["textures"];
    const auto scaled = [](int k) {
        return Json::parse("[{\"matrix\": [" + std::to_string(k) + ", 0, 0, 0, 0, " +
                           std::to_string(k) + ", 0, 0, 0, 0, " + std::to_string(k) +
                           ", 0, 0, 0, 0, 1]}]");
    };
    EXPECT_EQ(t["couch-disp (float)"],
              (Json{{"type", "wrinkled"},
                    {"octaves", 8},
                    {"roughness", 0.5},
                    {"mapping", {{"type", "point"}, {"transform", scaled(3)}}}}));
    EXPECT_EQ(t["scaled (float)"], Json::parse(R"j({"type": "scale",
        "texture": "couch-disp (float)", "scale": 0.005})j"));
    EXPECT_EQ(
        t["water (float)"],
        (Json{{"type", "windy"}, {"mapping", {{"type", "point"}, {"transform", scaled(6)}}}}));
    EXPECT_EQ(t["swater (float)"]["scale"], 0.75);
    EXPECT_EQ(t["f (float)"], Json::parse(R"({"type": "fbm", "octaves": 4, "roughness": 0.25})"));
    EXPECT_EQ(t["stone"], Json::parse(R"({"type": "marble", "octaves": 8, "roughness": 0.5,
        "scale": 2, "variation": 0.5})"));
    EXPECT_EQ(t["d"], Json::parse(R"({"type": "dots", "inside": "stone",
        "outside": [0.1, 0.2, 0.3], "scale": [4, 4]})"));
    EXPECT_EQ(t["cube (float)"],
              (Json{{"type", "checkerboard"},
                    {"a", 1},
                    {"b", 0},
                    {"mapping", {{"type", "point"}, {"transform", scaled(2)}}}}));
    // The translation is a scene lamina loads: every texture and mapping is lamina's own.
    EXPECT_NO_THROW(loadScene(file_, false)) << errorOf([&] { loadScene(file_, false); });
    // One warning for the file: lamina sums every octave.
    EXPECT_EQ(std::count_if(s.warnings.begin(), s.warnings.end(),
                            [](const std::string& w) {
                                return w.find("sum every octave") != std::string::npos;
                            }),
              1);
    EXPECT_EQ(
        importError("Texture \"f\" \"float\" \"fbm\" \"integer octaves\" 40\n"
                    "Material \"diffuse\" \"texture displacement\" \"f\"\nShape \"sphere\"\n"),
        at(1) + ": fbm: octaves must be in [1, 30] (got 40)");
}

// pbrt-v3 files (Film "image", "color" textures) are refused by pbrt-v4 as well; the error
// says how pbrt-v4 converts them.
TEST_F(PbrtCorpusConstructs, PbrtV3FilesAreRefusedWithTheWayToConvertThem) {
    file_ = write("v3.pbrt", "Film \"image\" \"integer xresolution\" 64\n" + std::string(kPrelude));
    EXPECT_EQ(errorOf([&] { importScene(file_, dir_); }),
              file_.string() +
                  ":1: Film \"image\" is pbrt-v3's film: this is a pbrt-v3 file, "
                  "which pbrt-v4 refuses too; convert it with pbrt-v4's `pbrt "
                  "--upgrade FILE > NEW.pbrt`");
    EXPECT_THAT(importError("Texture \"t\" \"color\" \"imagemap\" \"string filename\" \"a.png\"\n"),
                HasSubstr("got \"color\" (pbrt-v3's name: convert the file with pbrt-v4's"));
}

}  // namespace
}  // namespace lamina::render
