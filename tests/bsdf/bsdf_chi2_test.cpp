// Chi-square goodness of fit of every BSDF's sample() against its pdf(), for wo at 0, 30,
// 60 and 85 degrees and, for transmissive BSDFs, from below as well (total internal
// reflection for eta > 1 seen from inside). Family-wise significance 0.01 over the suite.
#include <gtest/gtest.h>

#include "bsdf_cases.h"
#include "chi2_helpers.h"

namespace lamina {
namespace {

struct Chi2Param {
    testing::BsdfCase bsdfCase;
    double thetaDeg;
    bool fromBelow;
};

std::vector<Chi2Param> params() {
    std::vector<Chi2Param> p;
    for (const auto& c : testing::bsdfCases())
        for (double theta : {0.0, 30.0, 60.0, 85.0}) {
            p.push_back({c, theta, false});
            if (c.transmissive) p.push_back({c, theta, true});
        }
    return p;
}

void PrintTo(const Chi2Param& p, std::ostream* os) {
    *os << p.bsdfCase.name << " at " << p.thetaDeg << (p.fromBelow ? " deg from below" : " deg");
}

const int kSuiteSize = static_cast<int>(params().size());

class BsdfChi2 : public ::testing::TestWithParam<Chi2Param> {};

TEST_P(BsdfChi2, SampleMatchesPdf) {
    const Chi2Param& param = GetParam();
    const Bxdf<testing::Spec>& bxdf = *param.bsdfCase.bxdf;
    Vec3d wo = testing::directionAt(param.thetaDeg);
    if (param.fromBelow) wo.z = -wo.z;
    ChiSquareConfig config;
    config.significance = testing::kSignificance;
    config.testCount = kSuiteSize;
    config.sampleCount = 400000;
    const ChiSquareResult r = runChiSquareTest(
        config,
        [&](Pcg32& rng) -> std::optional<Vec3d> {
            const double uc = rng.nextDouble();
            const Vec2d u(rng.nextDouble(), rng.nextDouble());
            const auto s = bxdf.sample(wo, uc, u, TransportMode::Radiance);
            if (!s || s->isSpecular()) return std::nullopt;
            return s->wi;
        },
        [&](const Vec3d& wi) { return bxdf.pdf(wo, wi); });
    EXPECT_TRUE(testing::passes(r));
}

std::string paramName(const ::testing::TestParamInfo<Chi2Param>& info) {
    return info.param.bsdfCase.name + "_theta" + std::to_string(int(info.param.thetaDeg)) +
           (info.param.fromBelow ? "_below" : "");
}

INSTANTIATE_TEST_SUITE_P(AllBsdfs, BsdfChi2, ::testing::ValuesIn(params()), paramName);

}  // namespace
}  // namespace lamina
