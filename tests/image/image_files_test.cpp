// Image files without OpenImageIO in the process: an EXR written by lamina (OpenEXR) reads back
// bit for bit with its data window and every metadata type; a PNG written by lamina's own
// writer reads back, through the OpenImageIO module, as exactly the 8-bit values; writing and
// reading EXR and writing PNG never load the module; and a module that cannot be loaded is
// one InputError naming the file, the module's path and the loader's reason.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>

#include "lamina/output/image_output.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using testing::errorOf;
namespace fs = std::filesystem;
using ::testing::HasSubstr;

class ImageFiles : public testing::ScratchDirectoryTest {};

/// Whether this process has mapped OpenImageIO or lamina's module.
bool openImageIoMapped() {
    std::ifstream maps("/proc/self/maps");
    std::stringstream text;
    text << maps.rdbuf();
    return text.str().find("libOpenImageIO") != std::string::npos ||
           text.str().find("lamina_oiio_images") != std::string::npos;
}

TEST_F(ImageFiles, ExrRoundTripsBitForBitWithItsDataWindowAndMetadata) {
    // A 5 x 4 crop at (3, 2) of a 16 x 10 image, five channels of awkward floats: negative
    // zero, the smallest subnormal, the largest float, infinity, and random bit patterns.
    const PixelBounds window{3, 8, 2, 6};
    const std::vector<std::string> names = {"R", "G", "B", "Albedo.R", "Z"};
    std::vector<float> data(std::size_t(window.width()) * window.height() * names.size());
    std::mt19937 rng(1);
    for (float& v : data) {
        const float r = std::uniform_real_distribution<float>(-1e6f, 1e6f)(rng);
        v = r;
    }
    data[0] = -0.0f;
    data[1] = std::numeric_limits<float>::denorm_min();
    data[2] = std::numeric_limits<float>::max();
    data[3] = std::numeric_limits<float>::infinity();
    ImageMetadata meta;
    meta.strings["scene"] = "a scene with \"quotes\"";
    meta.floats["seconds"] = 0.1f;
    meta.ints["spp"] = -7;
    meta.matrices["camera_to_world"] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16.5f};
    const fs::path file = dir_ / "crop.exr";
    writeFloatExr(file, window, 16, 10, names, data, meta);

    const FloatImage back = readFloatImage(file);
    EXPECT_EQ(back.x, 3);
    EXPECT_EQ(back.y, 2);
    EXPECT_EQ(back.width, 5);
    EXPECT_EQ(back.height, 4);
    EXPECT_EQ(back.fullWidth, 16);
    EXPECT_EQ(back.fullHeight, 10);
    // R, G, B first, then the layers: the order OpenImageIO gave.
    EXPECT_EQ(back.channels, (std::vector<std::string>{"R", "G", "B", "Z", "Albedo.R"}));
    ASSERT_EQ(back.samples.size(), data.size());
    for (std::size_t p = 0; p < data.size() / names.size(); ++p)
        for (std::size_t c = 0; c < names.size(); ++c) {
            const float written = data[p * names.size() + c];
            const float read = back.samples[p * names.size() + std::size_t(back.channel(names[c]))];
            EXPECT_EQ(std::memcmp(&written, &read, sizeof(float)), 0)
                << "pixel " << p << " channel " << names[c] << ": " << written << " " << read;
        }
    EXPECT_EQ(back.metadata.strings, meta.strings);
    EXPECT_EQ(back.metadata.floats, meta.floats);
    EXPECT_EQ(back.metadata.ints, meta.ints);
    EXPECT_EQ(back.metadata.matrices, meta.matrices);
    EXPECT_EQ(back.attributes.at("compression"), "zip");
    // The standard attributes under OpenImageIO's names, as its reader gave them before.
    EXPECT_EQ(back.attributes.at("PixelAspectRatio"), "1");
    EXPECT_EQ(back.attributes.at("screenWindowCenter"), "0, 0");
    EXPECT_EQ(back.attributes.count("DateTime"), 1u);
    EXPECT_EQ(back.attributes.at("lamina:spp"), "-7");
    EXPECT_EQ(back.attributes.at("lamina:seconds"), "0.1");
}

TEST_F(ImageFiles, PngReadsBackThroughTheModuleAsTheEightBitValues) {
    // Random values in [0, 1], and the rounding edges (1/510 rounds to 1, -1 clamps to 0).
    const int w = 7, h = 3;
    std::vector<float> rgb(std::size_t(w) * h * 3);
    std::mt19937 rng(2);
    for (float& v : rgb)
        v = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
    rgb[0] = -1.0f;
    rgb[1] = 2.0f;
    rgb[2] = std::nextafter(0.5f / 255.0f, 1.0f);
    const fs::path file = dir_ / "figure.png";
    writeRgb8(file, w, h, rgb);
    const FloatImage back = readFloatImage(file);
    ASSERT_EQ(back.width, w);
    ASSERT_EQ(back.height, h);
    ASSERT_EQ(back.channels, (std::vector<std::string>{"R", "G", "B"}));
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        const long byte = std::lround(std::clamp(rgb[i], 0.0f, 1.0f) * 255.0f);
        EXPECT_EQ(std::lround(back.samples[i] * 255.0f), byte) << i;
        EXPECT_FLOAT_EQ(back.samples[i], float(byte) / 255.0f) << i;
    }
    EXPECT_EQ(std::lround(back.samples[2] * 255.0f), 1);
    // An 8-bit PNG is display-referred: readRgbImage decodes it and says so.
    EXPECT_TRUE(readRgbImage(file).displayReferred);
}

// Each in a process of its own (gtest's "threadsafe" death tests run the test binary again for
// just that test), so that no other test has loaded the module before.
TEST_F(ImageFiles, ExrAndPngNeverLoadOpenImageIo) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const fs::path exr = dir_ / "a.exr", png = dir_ / "a.png";
    EXPECT_EXIT(
        {
            const std::vector<float> rgb(2 * 2 * 3, 0.25f);
            writeFloatExr(exr, 2, 2, {"R", "G", "B"}, rgb);
            writeRgb8(png, 2, 2, rgb);
            checkOutputPath(dir_ / "b.exr");
            checkOutputPath(dir_ / "b.png");
            const bool read = readRgbImage(exr).at(1, 1, 2) == 0.25f;
            const bool mapped = openImageIoMapped();
            if (!read || mapped)
                std::fprintf(stderr, "read %d, OpenImageIO mapped %d\n", read, mapped);
            std::exit(read && !mapped ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "");
}

TEST_F(ImageFiles, AModuleThatCannotBeLoadedIsOneInputError) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const fs::path png = dir_ / "a.png";
    writeRgb8(png, 1, 1, {0.5f, 0.5f, 0.5f});
    EXPECT_EXIT(
        {
            ::setenv("LAMINA_OIIO_MODULE", "/nonexistent/liblamina_oiio_images.so", 1);
            const std::string error = errorOf([&] { readRgbImage(png); });
            const std::string expected =
                png.string() +
                ": reading .png images needs lamina's OpenImageIO module "
                "(/nonexistent/liblamina_oiio_images.so): /nonexistent/liblamina_oiio_images.so: "
                "cannot open shared object file: No such file or directory";
            // And an EXR still reads: it needs no module.
            const bool exrReads =
                (writeFloatExr(dir_ / "b.exr", 1, 1, {"R", "G", "B"}, {1.0f, 2.0f, 3.0f}),
                 readRgbImage(dir_ / "b.exr").at(0, 0, 2) == 3.0f);
            if (error != expected || !exrReads)
                std::fprintf(stderr, "error: %s\nEXR read: %d\n", error.c_str(), exrReads);
            std::exit(error == expected && exrReads ? 0 : 1);
        },
        ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace lamina::render
