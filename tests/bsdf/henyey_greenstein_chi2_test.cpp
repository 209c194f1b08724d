// The Henyey-Greenstein phase function (henyey_greenstein.h), which the coated material's slab
// and the path integrator's media scatter with: its sampling against its density by a
// chi-square goodness-of-fit test (family-wise significance 0.01 over the suite, Sidak
// corrected), its normalisation, and its mean cosine g.
#include <gtest/gtest.h>

#include "chi2_helpers.h"
#include "lamina/bsdf/henyey_greenstein.h"

namespace lamina {
namespace {

struct HgCase {
    double g;
    Vec3d w;  ///< the direction of propagation before scattering
};

std::vector<HgCase> cases() {
    std::vector<HgCase> c;
    const Vec3d tilted = glm::normalize(Vec3d(0.3, -0.5, 0.8));
    for (const double g : {-0.9, -0.4, 0.0, 0.0005, 0.3, 0.8, 0.95})
        for (const Vec3d& w : {Vec3d(0, 0, 1), tilted})
            c.push_back({g, w});
    return c;
}

const int kSuiteTests = int(cases().size());

class HenyeyGreensteinChi2 : public ::testing::TestWithParam<HgCase> {};

TEST_P(HenyeyGreensteinChi2, SampleMatchesDensity) {
    const HgCase& c = GetParam();
    ChiSquareConfig config;
    config.significance = testing::kSignificance;
    config.testCount = kSuiteTests;
    config.sampleCount = 400000;
    const ChiSquareResult r = runChiSquareTest(
        config,
        [&](Pcg32& rng) -> std::optional<Vec3d> {
            const double a = rng.nextDouble();
            return sampleHenyeyGreenstein(c.w, c.g, Vec2d(a, rng.nextDouble()));
        },
        [&](const Vec3d& wi) { return henyeyGreenstein(glm::dot(c.w, wi), c.g); });
    EXPECT_TRUE(testing::passes(r));
    // A phase function is a probability density over the sphere.
    EXPECT_NEAR(r.pdfIntegral, 1.0, 1e-3);
}

TEST_P(HenyeyGreensteinChi2, MeanCosineIsG) {
    // E[cos theta] = g (Henyey and Greenstein 1941): 200000 samples, standard error below
    // 1/sqrt(200000) = 0.0023; 5 standard errors.
    const HgCase& c = GetParam();
    Pcg32 rng(17);
    double sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double a = rng.nextDouble();
        sum += glm::dot(c.w, sampleHenyeyGreenstein(c.w, c.g, Vec2d(a, rng.nextDouble())));
    }
    EXPECT_NEAR(sum / n, c.g, 5.0 / std::sqrt(double(n)));
}

INSTANTIATE_TEST_SUITE_P(Asymmetries, HenyeyGreensteinChi2, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<HgCase>& p) {
                             std::string name =
                                 "g" + std::to_string(int(std::lround(p.param.g * 10000)));
                             for (char& ch : name)
                                 if (ch == '-') ch = 'm';
                             return name + (p.param.w.z == 1.0 ? "_up" : "_tilted") + "_" +
                                    std::to_string(p.index);
                         });

}  // namespace
}  // namespace lamina
