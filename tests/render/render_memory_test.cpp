// The memory a render needs is estimated before anything is allocated, and a resolution that
// does not fit is refused with a message naming it (65536 x 65536 used to end in
// std::bad_alloc after allocating ~184 bytes per pixel).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lamina/core/error.h"
#include "lamina/render/render_memory.h"
#include "render_helpers.h"

namespace lamina {
namespace {

using ::testing::HasSubstr;

TEST(RenderMemory, TheEstimateCountsFilmImageAndStrategyImages) {
    const auto m = render::estimateRenderMemory(100, 50, false, false);
    EXPECT_EQ(m.film, 5000u * render::Film::bytesPerPixel());
    EXPECT_GE(render::Film::bytesPerPixel(),
              184u);  // what the film allocated when this was written
    EXPECT_EQ(m.output, 5000u * 3 * sizeof(float));
    EXPECT_EQ(m.strategies, 0u);
    EXPECT_EQ(render::estimateRenderMemory(100, 50, true, false).output,
              5000u * 11 * sizeof(float));
    // 19 strategies, each a weighted and an unweighted RGB image of doubles, camera and splat.
    EXPECT_EQ(render::estimateRenderMemory(100, 50, false, true).strategies,
              5000u * (4 * 19 * 3 * sizeof(double) + sizeof(double)));
    // 65536 x 65536 does not overflow the count.
    EXPECT_GT(render::estimateRenderMemory(65536, 65536, false, false).total(),
              std::uint64_t(65536) * 65536 * 184);
}

TEST(RenderMemory, AvailableMemoryIsKnownOnLinux) {
    const auto available = render::availableMemory();
    ASSERT_TRUE(available.has_value());
    EXPECT_GT(*available, 0u);
}

TEST(RenderMemory, TooLargeIsRefusedWithTheResolution) {
    const auto m = render::estimateRenderMemory(1000, 1000, false, false);
    EXPECT_NO_THROW(render::checkRenderMemory(m, 1000, 1000, "s.json: film.resolution", m.total()));
    try {
        render::checkRenderMemory(m, 1000, 1000, "s.json: film.resolution", m.total() - 1);
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr("s.json: film.resolution: 1000x1000 needs ~"));
        EXPECT_THAT(e.what(), HasSubstr("of memory available"));
    }
}

// The whole render refuses before allocating: the largest legal resolution of the scene key.
TEST(RenderMemory, RenderSceneRefusesBeforeAllocating) {
    const auto scene = testing::sceneFromText(R"({
      "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0]},
      "film": {"resolution": [65536, 65536]},
      "materials": {"m": {"type": "lambert"}},
      "shapes": [{"type": "sphere", "material": "m", "emission": {"radiance": 1}}]})");
    try {
        (void)render::renderScene(scene, {});
        FAIL() << "rendered";
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr("<test scene>: film.resolution: 65536x65536 needs ~"));
    }
    render::RenderOptions options;
    options.resolution = std::pair{65536, 32768};
    try {
        (void)render::renderScene(scene, options);
        FAIL() << "rendered";
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr("--resolution: 65536x32768 needs ~"));
    }
}

}  // namespace
}  // namespace lamina
