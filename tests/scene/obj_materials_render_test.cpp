// An OBJ with two usemtl groups and an MTL library renders each group with its own material:
// a red and a green Lambertian quad under a white environment of radiance 1, whose radiance
// is their Kd (the furnace of a Lambertian surface that sees only the sky), and a shape
// material in place of the MTL turns both grey.
#include <gtest/gtest.h>

#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina {
namespace {

class ObjMaterialsRender : public testing::ScratchDirectoryTest {
  protected:
    // The mean colour over a 5 x 5 block of pixels and its largest standard error.
    struct Block {
        Rgb<double> mean{0.0};
        double standardError = 0;
    };
    static Block block(const render::Film& film, int cx, int cy) {
        Block b;
        double var = 0;
        for (int y = cy - 2; y <= cy + 2; ++y)
            for (int x = cx - 2; x <= cx + 2; ++x) {
                for (int c = 0; c < 3; ++c)
                    b.mean[c] += film.pixel(x, y)[c] / 25.0;
                var += film.varianceOfMean(x, y);
            }
        b.standardError = std::sqrt(var) / 25.0;
        return b;
    }
};

TEST_F(ObjMaterialsRender, EachGroupRendersWithItsMaterial) {
    write("quads.mtl", "newmtl red\nKd 0.8 0.1 0.1\nnewmtl green\nKd 0.1 0.8 0.1\n");
    write("quads.obj",
          "mtllib quads.mtl\n"
          "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
          "v 1.5 -1 0\nv 3.5 -1 0\nv 3.5 1 0\nv 1.5 1 0\n"
          "usemtl red\nf 1 2 3 4\nusemtl green\nf 5 6 7 8\n");
    auto render = [&](const std::string& material) {
        const std::string json = R"({
          "camera": {"position": [1.25, 0, 6], "look_at": [1.25, 0, 0], "fov": 40},
          "film": {"resolution": [32, 16]},
          "shapes": [{"type": "obj", "file": "quads.obj")" +
                                 material + R"(}],
          "lights": [{"type": "environment", "radiance": 1}]})";
        render::RenderOptions o;
        o.spp = 64;
        return render::renderScene(render::parseScene(json, JsonSource{"scene.json", dir_}), o);
    };
    // The quads' centres (x = 0 and 2.5) fall on pixel columns 11 and 21 of row 8.
    const auto mtl = render("");
    const Block red = block(*mtl.film, 11, 8), green = block(*mtl.film, 21, 8);
    const Rgb<double> kdRed(0.8, 0.1, 0.1), kdGreen(0.1, 0.8, 0.1);
    for (int c = 0; c < 3; ++c) {
        // 5 standard errors and 1% (the sky's own estimate): significance ~1e-6 per value.
        EXPECT_NEAR(red.mean[c], kdRed[c], 5 * red.standardError + 0.01) << "channel " << c;
        EXPECT_NEAR(green.mean[c], kdGreen[c], 5 * green.standardError + 0.01) << "channel " << c;
    }
    const auto grey = render(R"(, "material": {"type": "lambert", "reflectance": 0.5})");
    for (const auto& [x, y] : {std::pair{11, 8}, std::pair{21, 8}}) {
        const Block b = block(*grey.film, x, y);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(b.mean[c], 0.5, 5 * b.standardError + 0.01);
    }
}

}  // namespace
}  // namespace lamina
