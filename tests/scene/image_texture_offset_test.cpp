// An image texture's offset (pbrt-v4's imagemap udelta and vdelta, UVMapping in textures.h):
// the image is looked up at scale * uv + offset, so an offset moves the lookup by offset /
// scale in uv, and no offset is the lookup without one, exactly.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "lamina/output/image_output.h"
#include "lamina/scene/texture.h"

namespace lamina {
namespace {

namespace fs = std::filesystem;

TEST(ImageTextureOffset, MovesTheLookupByOffsetOverScale) {
    const fs::path file =
        fs::temp_directory_path() / ("lamina-offset-" + std::to_string(::getpid()) + ".png");
    // 4 x 2 texels of distinct values, so that every lookup below tells positions apart.
    std::vector<float> px;
    for (int i = 0; i < 8; ++i)
        for (int c = 0; c < 3; ++c)
            px.push_back(float(i * 30 + c * 5) / 255.0f);
    render::writeRgb8(file, 4, 2, px);
    const Vec2<float> scale(2.0f, 1.0f), offset(0.25f, -0.125f);
    const render::ImageTexture plain(file, scale, false, false);
    const render::ImageTexture zero(file, scale, false, false, Vec2<float>(0.0f));
    const render::ImageTexture moved(file, scale, false, false, offset);
    for (const Vec2<float> uv :
         {Vec2<float>(0.1f, 0.2f), Vec2<float>(0.37f, 0.81f), Vec2<float>(0.9f, 0.55f)}) {
        for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(zero.evaluate(uv)[c], plain.evaluate(uv)[c]);
            // scale (uv + offset / scale) = scale uv + offset.
            const Vec2<float> shifted(uv.x + offset.x / scale.x, uv.y + offset.y / scale.y);
            EXPECT_NEAR(moved.evaluate(uv)[c], plain.evaluate(shifted)[c], 1e-5);
        }
        EXPECT_NE(moved.evaluate(uv)[0], plain.evaluate(uv)[0]);
    }
    fs::remove(file);
}

}  // namespace
}  // namespace lamina
