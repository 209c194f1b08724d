// `lamina render --samples/--crop` and `lamina merge` end to end: four shards merged on the
// command line give the single render's R, G, B and Variance.Y (relative 1e-6), polarised
// shards its Stokes and spectral film layers too; conflicting
// shards and malformed ranges end with one error line and the documented exit status.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>

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

// A polarised render with a spectral film (two gold mirrors: every Stokes component is
// non-zero), split by samples and crops: the merge holds the single render's image, Stokes
// layers and spectral layers (relative 1e-6), and both files carry the spectral layout's
// channel names and attributes, which OpenImageIO's oiiotool lists.
TEST_F(CliTest, PolarisedShardsWithASpectralFilmMergeToTheSingleRender) {
    const std::string kGold = testing::sourceFile("scenes/polarisation/gold-mirrors.json");
    const std::string opts = " --resolution 16x16 -q --mode polarised --spectral-film 4 ";
    const std::string full = (dir_ / "full.exr").string();
    const CommandRun one = runLamina("render " + kGold + opts + "--spp 4 -o " + full);
    ASSERT_EQ(one.exitCode, 0) << one.output;
    std::string shards;
    const char* const parts[] = {"--samples 0:2 --crop 0,16,0,9", "--samples 0:2 --crop 0,16,9,16",
                                 "--samples 2:2"};
    for (int i = 0; i < 3; ++i) {
        const std::string shard = (dir_ / ("shard" + std::to_string(i) + ".exr")).string();
        const CommandRun r = runLamina("render " + kGold + opts + parts[i] + " -o " + shard);
        ASSERT_EQ(r.exitCode, 0) << r.output;
        shards += " " + shard;
    }
    const std::string merged = (dir_ / "merged.exr").string();
    const CommandRun m = runLamina("merge" + shards + " -o " + merged);
    ASSERT_EQ(m.exitCode, 0) << m.output;
    const Channels a = readChannels(full), b = readChannels(merged);
    // 470 nm in 4 bins of 117.5 nm: centres 418.75, 536.25, 653.75 and 771.25 nm.
    std::vector<std::string> names = {"R", "G", "B"};
    for (const char* s : {"S0", "S1", "S2", "S3"}) {
        for (const char* c : {".R", ".G", ".B"})
            names.push_back(std::string(s) + c);
        for (const char* nm : {".418,750000nm", ".536,250000nm", ".653,750000nm", ".771,250000nm"})
            names.push_back(std::string(s) + nm);
    }
    std::map<char, double> largestOf;  // per Stokes component, over its channels
    for (const std::string& name : names) {
        ASSERT_TRUE(a.values.contains(name)) << name;
        ASSERT_TRUE(b.values.contains(name)) << name;
        const auto& x = a.values.at(name);
        const auto& y = b.values.at(name);
        ASSERT_EQ(x.size(), y.size());
        double largest = 0;
        for (const float v : x)
            largest = std::max(largest, double(std::abs(v)));
        if (name[0] == 'S') largestOf[name[1]] = std::max(largestOf[name[1]], largest);
        for (std::size_t i = 0; i < x.size(); ++i)
            ASSERT_LE(std::abs(x[i] - y[i]), 1e-6 * std::abs(x[i]) + 1e-9 * largest)
                << name << " pixel " << i;
    }
    for (const char k : {'0', '1', '2', '3'})
        EXPECT_GT(largestOf[k], 0) << "S" << k << ": the comparison needs light in it";
    for (const Channels* c : {&a, &b}) {
        EXPECT_EQ(c->metadata.at("spectralLayoutVersion"), "1.0");
        EXPECT_EQ(c->metadata.at("emissiveUnits"), "W.m^-2.sr^-1");
        EXPECT_EQ(c->metadata.at("polarisationHandedness"), "right");
        EXPECT_EQ(c->metadata.at("lamina:spectral_film"), "4");
    }
    if (std::system("command -v oiiotool > /dev/null 2>&1") == 0) {
        FILE* pipe = ::popen(("oiiotool --info -v " + merged + " 2>&1").c_str(), "r");
        std::string info;
        std::array<char, 4096> buf{};
        while (pipe && std::fgets(buf.data(), int(buf.size()), pipe))
            info += buf.data();
        ASSERT_EQ(pipe ? ::pclose(pipe) : -1, 0) << info;
        for (const char* want : {"S0.418,750000nm", "S3.771,250000nm", "spectralLayoutVersion",
                                 "polarisationHandedness"})
            EXPECT_NE(info.find(want), std::string::npos) << want << " in\n" << info;
    }
    // The rgb mode has no spectrum to bin: one line, exit 1.
    const CommandRun rgb = runLamina("render " + kCornell + kSmall + "--spectral-film 4 -o " +
                                     (dir_ / "rgb.exr").string());
    EXPECT_EQ(rgb.exitCode, 1);
    EXPECT_EQ(rgb.output,
              "lamina: error: --spectral-film: the rgb mode carries no spectrum; use --mode "
              "spectral or polarised\n");
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
