// `lamina render --samples/--crop` and `lamina merge` end to end: four shards merged on the
// command line give the single render's R, G, B and Variance.Y (relative 1e-6); conflicting
// shards and malformed ranges end with one error line and the documented exit status.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>

#include "cli_helpers.h"
#include "lamina/output/image_output.h"
#include "source_files.h"

namespace lamina {
namespace {

const std::string kCornell = testing::sourceFile("scenes/cornell-box.json");
const std::string kSmall = " --resolution 16x16 --max-depth 3 -q ";

/// Every channel of an EXR by name, and its lamina: string attributes.
struct Channels {
    std::map<std::string, std::vector<float>> values;
    std::map<std::string, std::string> metadata;
};

Channels readChannels(const std::string& path) {
    const render::FloatImage image = render::readFloatImage(path);
    Channels out;
    const std::size_t nc = image.channels.size();
    for (std::size_t c = 0; c < nc; ++c) {
        auto& v = out.values[image.channels[c]];
        for (std::size_t i = 0; i < image.samples.size() / nc; ++i)
            v.push_back(image.samples[i * nc + c]);
    }
    out.metadata = image.attributes;
    return out;
}

TEST_F(CliTest, FourShardsMergeToTheSingleRender) {
    const std::string full = (dir_ / "full.exr").string();
    ASSERT_EQ(runLamina("render " + kCornell + kSmall + "--spp 6 --aovs -o " + full).exitCode, 0);
    std::string shards;
    const char* const parts[] = {"--samples 0:3 --crop 0,16,0,9", "--samples 0:3 --crop 0,16,9,16",
                                 "--samples 3:1", "--samples 4:2"};
    for (int i = 0; i < 4; ++i) {
        const std::string shard = (dir_ / ("shard" + std::to_string(i) + ".exr")).string();
        const CommandRun r =
            runLamina("render " + kCornell + kSmall + "--aovs " + parts[i] + " -o " + shard);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        shards += " " + shard;
    }
    const std::string merged = (dir_ / "merged.exr").string();
    const CommandRun m = runLamina("merge" + shards + " -o " + merged);
    ASSERT_EQ(m.exitCode, 0) << m.output;
    EXPECT_NE(m.output.find("4 shards, samples 0:6"), std::string::npos) << m.output;
    const Channels a = readChannels(full), b = readChannels(merged);
    for (const char* name : {"R", "G", "B", "Variance.Y", "Albedo.R", "N.Z", "Z"}) {
        ASSERT_TRUE(b.values.contains(name)) << name;
        const auto& x = a.values.at(name);
        const auto& y = b.values.at(name);
        ASSERT_EQ(x.size(), y.size());
        for (std::size_t i = 0; i < x.size(); ++i)
            ASSERT_LE(std::abs(x[i] - y[i]), 1e-6 * std::abs(x[i]) + 1e-12f)
                << name << " pixel " << i;
    }
    for (const char* name : {"Variance.R", "Variance.G", "Variance.B"})
        EXPECT_TRUE(b.values.contains(name)) << name;
    EXPECT_EQ(b.metadata.at("lamina:samples"), "0:6");
    EXPECT_EQ(b.metadata.at("lamina:spp"), "6");
    EXPECT_EQ(b.metadata.at("lamina:merged_shards"), "4");
    EXPECT_EQ(b.metadata.at("lamina:samples_missing"), "none");
    EXPECT_EQ(b.metadata.at("lamina:partial_shards"), "none");
}

TEST_F(CliTest, MergeRefusesOverlappingShardsInOneLine) {
    const std::string a = (dir_ / "a.exr").string(), b = (dir_ / "b.exr").string();
    ASSERT_EQ(runLamina("render " + kCornell + kSmall + "--samples 0:2 -o " + a).exitCode, 0);
    ASSERT_EQ(runLamina("render " + kCornell + kSmall + "--samples 1:2 -o " + b).exitCode, 0);
    const CommandRun r = runLamina("merge " + a + " " + b + " -o " + (dir_ / "m.exr").string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.output, "lamina: error: " + a + " and " + b +
                            ": both hold samples 1:1 of pixels in 0,16,0,16 and 0,16,0,16 "
                            "(X0,X1,Y0,Y1)\n");
    EXPECT_FALSE(fs::exists(dir_ / "m.exr"));
}

TEST_F(CliTest, MalformedSampleRangesAndCropsAreUsageErrors) {
    for (const char* bad : {"--samples 3", "--samples -1:2", "--samples 0:0", "--crop 0,4,0",
                            "--crop 4,2,0,4", "--samples 0:2 --spp 4"}) {
        const CommandRun r =
            runLamina("render " + kCornell + kSmall + bad + " -o " + (dir_ / "x.exr").string());
        EXPECT_EQ(r.exitCode, 2) << bad << ": " << r.output;
        EXPECT_EQ(r.output.rfind("lamina: error: ", 0), 0u) << r.output;
    }
    EXPECT_EQ(filesIn(), 0u);
}

// The plan's scripts need no Slurm: run by hand with each index (as any batch system would),
// then merge.sh, they give the single render.
TEST_F(CliTest, FarmPlanScriptsRunWithoutSlurmAndMergeToTheSingleRender) {
    const fs::path plan = dir_ / "plan";
    const CommandRun p = runLamina("farm plan " + kCornell +
                                   " --shards 3 --spp 7 --resolution 16x16 --max-depth 3 "
                                   "--threads 1 -o " +
                                   plan.string());
    ASSERT_EQ(p.exitCode, 0) << p.output;
    std::ifstream sbatch(plan / "render.sbatch");
    const std::string array((std::istreambuf_iterator<char>(sbatch)), {});
    EXPECT_NE(array.find("#SBATCH --array=0-2\n"), std::string::npos) << array;
    EXPECT_NE(array.find("#SBATCH --cpus-per-task=1\n"), std::string::npos) << array;
    std::ifstream shardScript(plan / "render-shard.sh");
    const std::string shard((std::istreambuf_iterator<char>(shardScript)), {});
    EXPECT_NE(shard.find("first=(0 3 5)\ncount=(3 2 2)\n"), std::string::npos) << shard;
    for (int i = 0; i < 3; ++i)
        ASSERT_EQ(
            std::system(
                ("bash " + (plan / "render-shard.sh").string() + " " + std::to_string(i)).c_str()),
            0);
    EXPECT_NE(
        std::system(("bash " + (plan / "render-shard.sh").string() + " 3 2>/dev/null").c_str()), 0);
    ASSERT_EQ(std::system(("bash " + (plan / "merge.sh").string() + " 2>/dev/null").c_str()), 0);
    const std::string full = (dir_ / "full.exr").string();
    ASSERT_EQ(runLamina("render " + kCornell + kSmall + "--spp 7 -o " + full).exitCode, 0);
    const Channels a = readChannels(full), b = readChannels((plan / "image.exr").string());
    for (const char* name : {"R", "G", "B"}) {
        const auto& x = a.values.at(name);
        const auto& y = b.values.at(name);
        ASSERT_EQ(x.size(), y.size());
        for (std::size_t i = 0; i < x.size(); ++i)
            ASSERT_LE(std::abs(x[i] - y[i]), 1e-6 * std::abs(x[i]) + 1e-12f) << name << i;
    }

    // `lamina convergence --merged` measures it against a reference.
    const std::string reference = (dir_ / "reference.exr").string();
    ASSERT_EQ(
        runLamina("render " + kCornell + kSmall + "--spp 32 --seed 9 -o " + reference).exitCode, 0);
    const CommandRun c =
        runLamina("convergence " + kCornell + " --merged " + (plan / "image.exr").string() +
                  " --reference " + reference + " -o " + (dir_ / "conv").string());
    ASSERT_EQ(c.exitCode, 0) << c.output;
    std::ifstream csv(dir_ / "conv" / "merged.csv");
    std::string header, row;
    std::getline(csv, header);
    std::getline(csv, row);
    EXPECT_EQ(header,
              "image,shards,spp,render_seconds,longest_shard_seconds,partial,relmse,mse,"
              "mae");
    EXPECT_EQ(row.rfind("image.exr,3,7,", 0), 0u) << row;
}

// A cluster's required directives (time limit, partition, account, anything else) go into
// both jobs: a merge job without the site's account or partition would be rejected.
TEST_F(CliTest, FarmPlanWritesTheClustersSbatchLinesIntoBothJobs) {
    const fs::path plan = dir_ / "plan";
    const CommandRun p = runLamina("farm plan " + kCornell +
                                   " --shards 2 --spp 4 --time-limit 1-02:30:00 --partition short "
                                   "--account proj42 --sbatch=--mem=4G --sbatch=--qos=low -o " +
                                   plan.string());
    ASSERT_EQ(p.exitCode, 0) << p.output;
    for (const char* job : {"render.sbatch", "merge.sbatch"}) {
        std::ifstream in(plan / job);
        const std::string text((std::istreambuf_iterator<char>(in)), {});
        EXPECT_NE(text.find("#SBATCH --time=1-02:30:00\n#SBATCH --partition=short\n"
                            "#SBATCH --account=proj42\n#SBATCH --mem=4G\n#SBATCH --qos=low\n"),
                  std::string::npos)
            << job << ":\n"
            << text;
        // sbatch stops reading directives at the first command: they all come before it.
        EXPECT_LT(text.rfind("#SBATCH"), text.find("\nexec ")) << job;
    }
}

TEST_F(CliTest, FarmPlanRefusesATimeLimitOrLineSlurmWouldNotRead) {
    for (const auto& [options, message] : std::vector<std::pair<std::string, std::string>>{
             {"--time-limit 2h",
              "--time-limit 2h: expected a Slurm time limit: MINUTES, H:M:S or D-H:M:S"},
             {"--time-limit 1:2:3:4",
              "--time-limit 1:2:3:4: expected a Slurm time limit: MINUTES, H:M:S or D-H:M:S"},
             {"--sbatch=mem=4G",
              "--sbatch mem=4G: expected one sbatch option on one line, such as --mem=4G"},
             {"--partition 'a b'", "--partition a b: expected one word"}}) {
        const CommandRun r = runLamina("farm plan " + kCornell + " --shards 2 --spp 4 " + options +
                                       " -o " + (dir_ / "plan").string());
        EXPECT_EQ(r.exitCode, 1) << options;
        EXPECT_EQ(r.output, "lamina: error: " + message + "\n");
        EXPECT_EQ(filesIn(), 0u) << options;
    }
}

TEST_F(CliTest, FarmPlanRefusesMoreShardsThanSamples) {
    const CommandRun r =
        runLamina("farm plan " + kCornell + " --shards 9 --spp 8 -o " + (dir_ / "plan").string());
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_EQ(r.output,
              "lamina: error: --shards 9: more shards than the 8 samples per pixel to split\n");
    EXPECT_EQ(filesIn(), 0u);
}

}  // namespace
}  // namespace lamina
