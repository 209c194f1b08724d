// The experiment commands end to end on tiny scenes, with their numbers checked against
// something known: `render --reference --error-log` and `convergence` on a white furnace,
// whose exact image is 1 everywhere (a white Lambertian sphere in a uniform environment of
// radiance 1 reflects exactly the radiance it receives). The environment is an image of ones,
// not a constant: a constant environment is left to BSDF sampling, which on this scene is
// exact in every sample, and these tests need an estimator with variance.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>

#include "cli_helpers.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/output/image_output.h"
#include "source_files.h"

namespace lamina {
namespace {

const char* kFurnace = R"({
  "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 30},
  "film": {"resolution": [32, 32]},
  "integrator": {"max_depth": 64, "rr_depth": 64},
  "materials": {"white": {"type": "lambert", "reflectance": 1}},
  "shapes": [{"type": "sphere", "radius": 1, "material": "white"}],
  "lights": [{"type": "environment", "file": "ones-sky.exr"}]
})";

class ExperimentCli : public CliTest {
  protected:
    void SetUp() override {
        CliTest::SetUp();
        withoutDrawing();
    }
    /// The furnace scene and its environment image of ones, beside each other in dir_.
    std::string furnace() {
        render::writeFloatExr((dir_ / "ones-sky.exr").string(), 16, 8, {"R", "G", "B"},
                              std::vector<float>(16 * 8 * 3, 1.0f));
        return write("furnace.json", kFurnace);
    }
    std::string exactReference() {
        const std::string path = (dir_ / "ones.exr").string();
        render::writeFloatExr(path, 32, 32, {"R", "G", "B"}, std::vector<float>(32 * 32 * 3, 1.0f));
        return path;
    }
};

TEST_F(ExperimentCli, ErrorLogHasOneRowPerPassAndTheErrorFalls) {
    const std::string scene = furnace();
    const std::string log = (dir_ / "err.csv").string();
    const CommandRun r = runLamina("render " + scene + " -q --spp 64 --sampler independent -o " +
                                   (dir_ / "f.exr").string() + " --reference " + exactReference() +
                                   " --error-log " + log);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(log);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "seconds,spp,mse,relmse,mae");
    std::vector<std::pair<int, double>> rows;  // spp, mse
    while (std::getline(in, line)) {
        std::stringstream s(line);
        std::string field;
        std::vector<double> v;
        while (std::getline(s, field, ','))
            v.push_back(std::stod(field));
        ASSERT_EQ(v.size(), 5u) << line;
        rows.emplace_back(int(v[1]), v[2]);
    }
    // Passes of 1, 1, 2, 4, 8, 16, 32 spp: 64 spp in 7 rows.
    ASSERT_EQ(rows.size(), 7u);
    EXPECT_EQ(rows.back().first, 64);
    // MSE ~ 1/spp: from 1 to 64 spp it falls by far more than 10 (64 expected).
    EXPECT_LT(rows.back().second * 10, rows.front().second);
    // The reference must match the render's size.
    const std::string small = (dir_ / "small.exr").string();
    render::writeFloatExr(small, 8, 8, {"R", "G", "B"}, std::vector<float>(8 * 8 * 3, 1.0f));
    const CommandRun bad = runLamina("render " + scene + " -q -o " + (dir_ / "g.exr").string() +
                                     " --reference " + small + " --error-log " + log);
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_NE(bad.output.find("8x8"), std::string::npos) << bad.output;
}

TEST_F(ExperimentCli, ConvergenceSlopeOfAnUnbiasedEstimatorIsMinusOne) {
    const std::string scene = furnace();
    const CommandRun r = runLamina("convergence " + scene + " --integrators path,bdpt --time 3 " +
                                   "--sampler independent --reference " + exactReference() +
                                   " -o " + (dir_ / "conv").string() + " 2>/dev/null");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* f :
         {"convergence.csv", "convergence.py", "convergence.figure.json", "summary.md"})
        EXPECT_TRUE(fs::exists(dir_ / "conv" / f)) << f;
    // The matplotlib script beside the CSV draws it (with Debian's python3-matplotlib).
    if (std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") == 0) {
        const fs::path figure = dir_ / "conv" / "figure.png";
        const std::string command = "/usr/bin/python3 " +
                                    (dir_ / "conv" / "convergence.py").string() + " " +
                                    figure.string() + " >/dev/null 2>&1";
        EXPECT_EQ(std::system(command.c_str()), 0) << command;
        EXPECT_TRUE(fs::exists(figure) && fs::file_size(figure) > 1000) << figure;
    } else {
        std::cerr << "skipped: /usr/bin/python3 has no matplotlib (python3-matplotlib), the "
                     "generated convergence.py is not run\n";
    }
    // | path | rgb | samples/s | spp | relMSE | MSE | slope (time) | slope (spp) | ...
    // The slope against samples is the estimator's own and must be -1; the one against
    // seconds is bent by the load of the machine the test runs on (under ctest -j2, beside
    // other renders), so it only has to be near -1.
    const std::regex row(R"(\| (path|bdpt) \| rgb \| [^|]+ \| [^|]+ \| [^|]+ \| [^|]+ \| )"
                         R"(([-0-9.]+) \| ([-0-9.]+) \|)");
    int found = 0;
    for (std::sregex_iterator it(r.output.begin(), r.output.end(), row), end; it != end; ++it) {
        const double perSecond = std::stod((*it)[2]), perSample = std::stod((*it)[3]);
        EXPECT_GE(perSample, -1.2) << (*it)[1];
        EXPECT_LE(perSample, -0.8) << (*it)[1];
        EXPECT_GE(perSecond, -1.6) << (*it)[1];
        EXPECT_LE(perSecond, -0.6) << (*it)[1];
        ++found;
    }
    EXPECT_EQ(found, 2) << r.output;
}

// The exact curve of `lamina fresnel` is the conductor Fresnel the BSDF uses in spectral mode:
// a smooth gold mirror's reflection weight at each wavelength and angle.
TEST_F(ExperimentCli, FresnelExactCurveIsTheBsdfsConductorFresnel) {
    const CommandRun r = runLamina("fresnel Au bk7 -o " + dir_.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("Hoffman F82"), std::string::npos);
    for (const char* f :
         {"Au.csv", "Au.figure.json", "Au_swatches.figure.json", "bk7_spectral.csv", "summary.md"})
        EXPECT_TRUE(fs::exists(dir_ / f)) << f;
    const auto rows = readCsv(dir_ / "Au_spectral.csv");  // degrees, 380, 400, ..., 780 nm
    ASSERT_EQ(rows.size(), 91u);
    const MaterialDesc gold =
        parseMaterialArgument(R"({"type":"conductor","material":"Au","alpha":0})");
    for (int degrees : {0, 30, 60, 80, 89})
        for (int column : {2, 6, 10, 14, 18}) {  // 400, 480, 560, 640, 720 nm
            const double nm = 380 + 20 * (column - 1);
            auto lambda = SampledWavelengths<double>::fixed(std::array<double, 4>{nm, nm, nm, nm});
            const auto bsdf = buildBxdf(gold, SpectrumContext<SampledSpectrum<double>>{lambda});
            const double t = degrees * kPi<double> / 180;
            const auto s = bsdf->sample({std::sin(t), 0.0, std::cos(t)}, 0.5, {0.5, 0.5},
                                        TransportMode::Radiance);
            ASSERT_TRUE(s.has_value());
            EXPECT_NEAR(rows[std::size_t(degrees)][std::size_t(column)], s->weight[0], 1e-6)
                << degrees << " degrees, " << nm << " nm";
        }
    EXPECT_EQ(runLamina("fresnel unobtainium -o " + dir_.string()).exitCode, 1);
}

TEST_F(ExperimentCli, StabilityReportsAHealthyModelCleanAndRendersStressScenes) {
    const std::string stress = testing::sourceFile("scenes/stress/ior-4.json");
    const CommandRun r =
        runLamina(R"(stability '{"type":"lambert","reflectance":1}' --samples 256 )"
                  R"(--spp 4 --scenes )" +
                  stress + " -o " + dir_.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find(R"(| `{"type":"lambert","reflectance":1}` | 0 | 0 | 0 | 0 | 0 |)"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("| ior-4.json | 0 |"), std::string::npos) << r.output;
    // The material in the name; the parameter values on the axes.
    EXPECT_TRUE(fs::exists(dir_ / "model1_lambert_float_error.figure.json"));
    std::ifstream spec(dir_ / "model1_lambert_issues.figure.json");
    const std::string figure((std::istreambuf_iterator<char>(spec)), {});
    EXPECT_NE(figure.find("cos(theta_o)"), std::string::npos);
    EXPECT_NE(figure.find("log10(1 + issues per cell)"), std::string::npos);
}

}  // namespace
}  // namespace lamina
