// OBJ materials (docs/scene-format.md, "OBJ materials"): an `obj` shape without `material`
// splits its faces by usemtl into meshes with the materials their MTL entries map to; the
// mapping of each MTL key, the warnings (file and line) for what is ignored, the errors for
// a missing library and bad values, and a shape material overriding the MTL.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/bsdf/dielectric.h"
#include "lamina/bsdf/diffuse.h"
#include "lamina/bsdf/standard.h"
#include "lamina/core/json_reader.h"
#include "lamina/scene/scene_description.h"
#include "scene_shapes.h"
#include "scratch_directory.h"

namespace lamina {
namespace {

using ::testing::HasSubstr;

class ObjMaterials : public testing::ScratchDirectoryTest {
  protected:
    // An OBJ of one unit quad per material name ("" : faces before any usemtl), side by
    // side along x, with `mtllib` naming `library` unless it is empty.
    std::filesystem::path writeObj(const std::vector<std::string>& groups,
                                   const std::string& library = "quads.mtl") {
        std::string obj = library.empty() ? "" : "mtllib " + library + "\n";
        for (std::size_t g = 0; g < groups.size(); ++g) {
            const double x = 2.5 * double(g);
            for (const auto& [dx, dy] :
                 {std::pair{-1, -1}, std::pair{1, -1}, std::pair{1, 1}, std::pair{-1, 1}})
                obj += "v " + std::to_string(x + dx) + " " + std::to_string(dy) + " 0\n";
        }
        for (std::size_t g = 0; g < groups.size(); ++g) {
            if (!groups[g].empty()) obj += "usemtl " + groups[g] + "\n";
            const std::size_t v = 4 * g + 1;
            obj += "f " + std::to_string(v) + " " + std::to_string(v + 1) + " " +
                   std::to_string(v + 2) + " " + std::to_string(v + 3) + "\n";
        }
        return write("quads.obj", obj);
    }

    render::SceneDesc load(const std::string& shape) {
        const std::string json = R"({"materials": {"m": {"type": "lambert", "reflectance": 0.3}},
            "shapes": [)" + shape +
                                 R"(],
            "lights": [{"type": "environment", "radiance": 1}]})";
        return render::parseScene(json, JsonSource{"scene.json", dir_});
    }
    render::SceneDesc loadObj() { return load(R"({"type": "obj", "file": "quads.obj"})"); }

    const MaterialDesc& materialOf(const render::SceneDesc& s, std::size_t mesh) {
        return s.materials.at(
            std::size_t(testing::shapesOf<render::MeshDesc>(s.shapes).at(mesh).material));
    }
    std::string mtl() const { return (dir_ / "quads.mtl").lexically_normal().string(); }
};

TEST_F(ObjMaterials, EachUsemtlGroupIsAMeshWithItsMaterial) {
    write("quads.mtl", "newmtl red\nKd 0.8 0.1 0.1\n\nnewmtl green\nKd 0.1 0.8 0.1\n");
    writeObj({"red", "green"});
    const render::SceneDesc s = loadObj();
    const auto meshes = testing::shapesOf<render::MeshDesc>(s.shapes);
    ASSERT_EQ(meshes.size(), 2u);
    EXPECT_EQ(meshes[0].name, "shapes[0]:red");
    EXPECT_EQ(meshes[1].name, "shapes[0]:green");
    EXPECT_EQ(meshes[0].triangles.size(), 2u);
    EXPECT_EQ(s.materialNames.at(std::size_t(meshes[0].material)), mtl() + ":red");
    EXPECT_EQ(s.materialNames.at(std::size_t(meshes[1].material)), mtl() + ":green");
    EXPECT_EQ(materialOf(s, 0).type, "lambert");
    EXPECT_EQ(materialOf(s, 0).model.as<DiffuseMaterial>().reflectance.rgb,
              RgbInput(0.8, 0.1, 0.1));
    EXPECT_EQ(materialOf(s, 1).model.as<DiffuseMaterial>().reflectance.rgb,
              RgbInput(0.1, 0.8, 0.1));
    EXPECT_TRUE(s.importWarnings.empty()) << s.importWarnings.front();
    // The library is one of the scene's input files (provenance).
    EXPECT_THAT(s.inputFiles, ::testing::Contains(std::filesystem::path(mtl())));
}

TEST_F(ObjMaterials, TheMappingOfEachKey) {
    write("quads.mtl",
          "newmtl shiny\nKd 0.2 0.3 0.4\nKs 0.04 0.05 0.06\nNs 98\n"
          "newmtl glass\nillum 7\nNi 1.33\nKs 1 1 1\n"
          "newmtl dissolved\nKd 0.5 0.5 0.5\nd 0.5\n"
          "newmtl lamp\nKd 0 0 0\nKe 2 3 4\n"
          "newmtl photo\nKd 1 1 1\nmap_Kd photo.ppm\n");
    write("photo.ppm", "P3\n2 1\n255\n255 0 0 0 255 0\n");
    writeObj({"shiny", "glass", "dissolved", "lamp", "photo"});
    const render::SceneDesc s = loadObj();
    const auto meshes = testing::shapesOf<render::MeshDesc>(s.shapes);
    ASSERT_EQ(meshes.size(), 5u);

    // Ks, Ns: the specular workflow, alpha = sqrt(2 / (Ns + 2)) (Walter et al. 2007).
    const auto& shiny = materialOf(s, 0).model.as<StandardMaterial>();
    EXPECT_EQ(shiny.baseColor.rgb, RgbInput(0.2, 0.3, 0.4));
    ASSERT_TRUE(shiny.specularColor);
    EXPECT_EQ(*shiny.specularColor, RgbInput(0.04, 0.05, 0.06));
    EXPECT_NEAR(shiny.microfacet.alphaX, std::sqrt(2.0 / 100.0), 1e-12);
    EXPECT_NEAR(shiny.microfacet.alphaY, std::sqrt(2.0 / 100.0), 1e-12);

    // illum 7 with Ni: glass of that index.
    EXPECT_EQ(materialOf(s, 1).model.as<DielectricMaterial>().ior, 1.33);
    // d < 1 without Ni: glass of index 1.5, with warnings that say so.
    EXPECT_EQ(materialOf(s, 2).model.as<DielectricMaterial>().ior, 1.5);
    EXPECT_THAT(
        s.importWarnings,
        ::testing::Contains(HasSubstr(mtl() + ":9: newmtl dissolved is glass (illum 2, d 0.5) "
                                              "without an index Ni: ior 1.5")));
    EXPECT_THAT(s.importWarnings,
                ::testing::Contains(HasSubstr(mtl() + ":11: partial dissolve d 0.5")));

    // Ke: the group emits.
    ASSERT_TRUE(meshes[3].emission);
    EXPECT_EQ(meshes[3].emission->radiance, Rgb<double>(2, 3, 4));
    EXPECT_FALSE(meshes[0].emission);

    // map_Kd: an image texture, relative to the MTL file, as the reflectance.
    EXPECT_EQ(materialOf(s, 4).type, "lambert");
    const auto& tex = s.materialTextures.at(std::size_t(meshes[4].material));
    ASSERT_GE(tex.color, 0);
    EXPECT_EQ(s.textureNames.at(std::size_t(tex.color)), mtl() + ":photo:map_Kd");
    const Rgb<float> left = s.textures[std::size_t(tex.color)]->evaluate(Vec2<float>(0.25f, 0.5f));
    EXPECT_GT(left[0], 0.9f);
    EXPECT_LT(left[1], 0.1f);
}

TEST_F(ObjMaterials, IgnoredKeysWarnOncePerKeyWithFileAndLine) {
    write("quads.mtl",
          "# exported\nnewmtl a\nKa 0.1 0.1 0.1\nKd 0.5 0.5 0.5\nmap_Bump bump.png\n"
          "newmtl b\nKa 0.2 0.2 0.2\nPr 0.5\nKd 0.4 0.4 0.4\n");
    writeObj({"a", "b"});
    const render::SceneDesc s = loadObj();
    EXPECT_THAT(s.importWarnings,
                ::testing::ElementsAre(
                    mtl() + ":3: Ka is not supported: ignored (here and on any later line)",
                    mtl() + ":5: map_Bump is not supported: ignored (here and on any later line)",
                    mtl() + ":8: Pr is not supported: ignored (here and on any later line)"));
}

TEST_F(ObjMaterials, FacesWithoutAKnownMaterialGetTheDefaultLambert) {
    write("quads.mtl", "newmtl red\nKd 0.8 0.1 0.1\n");
    writeObj({"", "red", "nosuch"});
    const render::SceneDesc s = loadObj();
    const auto meshes = testing::shapesOf<render::MeshDesc>(s.shapes);
    ASSERT_EQ(meshes.size(), 2u);  // the default group holds the first and the last quad
    EXPECT_EQ(meshes[0].name, "shapes[0]:default");
    EXPECT_EQ(meshes[0].triangles.size(), 4u);
    const std::string obj = (dir_ / "quads.obj").string();
    EXPECT_EQ(s.materialNames.at(std::size_t(meshes[0].material)), obj + ":default");
    EXPECT_EQ(materialOf(s, 0).model.as<DiffuseMaterial>().reflectance.rgb, RgbInput(0.5));
    EXPECT_THAT(
        s.importWarnings,
        ::testing::ElementsAre(obj + ":17: usemtl nosuch: no such material in the MTL libraries",
                               obj + ": 4 triangles have no material (no usemtl before them, or an "
                                     "unknown one): a default lambert 0.5"));
}

TEST_F(ObjMaterials, AShapeMaterialOverridesTheMtl) {
    // With a material the MTL is not read at all: here it does not even exist.
    writeObj({"red", "green"}, "missing.mtl");
    const render::SceneDesc s = load(R"({"type": "obj", "file": "quads.obj", "material": "m"})");
    const auto meshes = testing::shapesOf<render::MeshDesc>(s.shapes);
    ASSERT_EQ(meshes.size(), 1u);
    EXPECT_EQ(meshes[0].triangles.size(), 4u);
    EXPECT_EQ(s.materialNames.at(std::size_t(meshes[0].material)), "m");
    EXPECT_TRUE(s.importWarnings.empty());
}

TEST_F(ObjMaterials, ErrorsNameTheFileAndLine) {
    writeObj({"red"}, "missing.mtl");
    EXPECT_THAT(
        testing::errorOf([&] { loadObj(); }),
        HasSubstr("shapes[0].file: " + (dir_ / "quads.obj").string() +
                  ":1: mtllib missing.mtl: " + (dir_ / "missing.mtl").string() + ": no such file"));
    writeObj({"red"}, "");
    EXPECT_THAT(testing::errorOf([&] { loadObj(); }),
                HasSubstr("names no MTL library (mtllib); give the shape a material"));
    writeObj({"red"});
    for (const auto& [text, message] : std::initializer_list<std::pair<const char*, std::string>>{
             {"newmtl red\nKd 1.5 0 0\n", ":2: Kd: expected a value in [0, 1], got 1.5"},
             {"newmtl red\nKs 0.1 0.1\n", ":2: Ks: expected r g b"},
             {"newmtl red\nNs -3\n", ":2: Ns: expected a value in [0, 10000000], got -3"},
             {"newmtl red\nKe 1 nan 1\n", ":2: Ke: expected a number, got \"nan\""},
             {"Kd 0.5 0.5 0.5\n", ":1: Kd before any newmtl"},
             {"newmtl red\nnewmtl red\n", ":2: newmtl red is defined twice (first at line 1)"}}) {
        write("quads.mtl", text);
        EXPECT_THAT(testing::errorOf([&] { loadObj(); }), HasSubstr(mtl() + message)) << text;
    }
}

}  // namespace
}  // namespace lamina
