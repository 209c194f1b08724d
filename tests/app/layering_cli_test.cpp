// `lamina layering` end to end on small inputs: the report's files exist and their numbers make
// sense (albedos in [0, 1], an index-matched coat within 1% of its twins, no NaN anywhere).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "cli_helpers.h"

namespace lamina {
namespace {

const char* kTinyTestObject = R"({
  "camera": {"position": [0, 1, -3], "look_at": [0, 0.5, 0], "fov": 35},
  "film": {"resolution": [12, 12]},
  "sampler": {"spp": 2},
  "materials": {"sample": {"type": "lambert"}, "floor": {"type": "lambert", "reflectance": 0.4}},
  "shapes": [
    {"type": "sphere", "center": [0, 0.5, 0], "radius": 0.5, "material": "sample"},
    {"type": "rectangle", "material": "floor", "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"scale": 3}]}
  ],
  "lights": [{"type": "environment", "radiance": 1}]
})";

class LayeringCli : public CliTest {
  protected:
    void SetUp() override {
        CliTest::SetUp();
        withoutDrawing();
    }
};

TEST_F(LayeringCli, WritesAReportWhoseNumbersMakeSense) {
    const std::string scene = write("object.json", kTinyTestObject);
    const fs::path out = dir_ / "layering";
    const CommandRun r = runLamina(
        std::string("layering '{\"type\":\"coated\",\"ior\":1,\"base\":{\"type\":\"lambert\","
                    "\"reflectance\":0.6}}' coated-gold "
                    "'{\"type\":\"coated\",\"roughness\":0.2,\"base\":{\"type\":\"conductor\","
                    "\"f0\":0.9}}' --estimates 16 --albedo-samples 65536 ") +
        "--scene " + scene + " --spp 2 -o " + out.string() + " 2>/dev/null");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* f :
         {"summary.md", "material1_albedo.csv", "material1_albedo.figure.json",
          "material1_lobes.csv", "material1_lobe_0.figure.json", "material1_lobe_75.figure.json",
          "material1_fresnel_error.figure.json", "material1_fresnel_error.f32",
          "material1_albedo_error.figure.json", "material1_walk_rgb.png",
          "material1_walk_spectral.png", "material1_albedo_spectral.png",
          "material1_fresnel_rgb_ciede2000.figure.json", "coated-gold_albedo.csv",
          "coated-gold_lobes.csv"})
        EXPECT_TRUE(fs::exists(out / f)) << f;
    // Columns: theta_o, walk, walk_se, fresnel, fresnel_se, albedo, albedo_se.
    const auto rows = readCsv(out / "material1_albedo.csv");
    ASSERT_EQ(rows.size(), 18u);
    for (const auto& row : rows) {
        ASSERT_EQ(row.size(), 7u);
        for (std::size_t c = 1; c < row.size(); c += 2) {
            EXPECT_GE(row[c], 0.0);
            EXPECT_LE(row[c], 1.0);
            // An index-matched coat is the bare base: 0.6 (the walk exactly, each twin within
            // four of its standard errors).
            EXPECT_NEAR(row[c], 0.6, 4 * row[c + 1] + 1e-12) << "column " << c << " at " << row[0];
        }
    }
    // Coated gold has its two twins (a rough conductor base); a smooth conductor base has none.
    const auto gold = readCsv(out / "coated-gold_albedo.csv");
    ASSERT_EQ(gold.size(), 18u);
    for (const auto& row : gold) {
        ASSERT_EQ(row.size(), 7u);
        for (std::size_t c = 1; c < row.size(); c += 2) {
            EXPECT_GT(row[c], 0.0) << "column " << c;
            EXPECT_LT(row[c], 1.0) << "column " << c;
            EXPECT_GT(row[c + 1], 0.0);  // every albedo carries a standard error
        }
    }
    for (const auto& row : readCsv(out / "material3_albedo.csv")) {
        ASSERT_EQ(row.size(), 3u);  // no twin
        EXPECT_GT(row[1], 0.0);
        EXPECT_LT(row[1], 1.0);
        EXPECT_GT(row[2], 0.0);
    }
    std::ifstream summary(out / "summary.md");
    const std::string text((std::istreambuf_iterator<char>(summary)), {});
    EXPECT_NE(text.find("| fresnel coupling | albedo | 18 | 18 / 0 / 0 |"), std::string::npos)
        << text;
    EXPECT_NE(text.find("no analytic twin"), std::string::npos);
    EXPECT_NE(text.find("one pass through the coat"), std::string::npos);
    EXPECT_NE(text.find("mean CIEDE2000"), std::string::npos);
    // No NaN or infinity printed as a number.
    EXPECT_FALSE(std::regex_search(text, std::regex("[^a-z](nan|inf)[^a-z]"))) << text;
}

TEST_F(LayeringCli, RefusesAMaterialThatIsNotCoated) {
    const CommandRun r = runLamina("layering '{\"type\":\"lambert\"}' -o " + (dir_ / "x").string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.output.find("lamina: error: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("expected \"coated\""), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "x" / "summary.md"));
    const CommandRun unknown = runLamina("layering glossy-unicorn -o " + (dir_ / "y").string());
    EXPECT_EQ(unknown.exitCode, 1);
    EXPECT_NE(unknown.output.find("clear-paint"), std::string::npos) << unknown.output;
}

}  // namespace
}  // namespace lamina
