// The polarised case of the stability sweep (polarised_stability.h) on the models whose
// polarisation has singular angles: smooth and rough dielectrics seen from both sides (Brewster's
// angle of each side, the critical angle of the dense one), a reflection-only glass (a conductor
// of index 1.5, k 0) and metals, in float and double. No element of any Mueller matrix is NaN or
// Inf with wo along the normal (inside and outside), at grazing incidence, or one ulp from
// Brewster's and the critical angle; and no element jumps between neighbours one ulp apart by
// more than kPolarisedJumpBound (64 sqrt(epsilon) of the precision, over the probe's largest
// [0][0]): the functions are continuous there, with at most a square-root singularity.
// Deterministic: fixed directions and random numbers.
#include <gtest/gtest.h>

#include "lamina/experiments/polarised_stability.h"

namespace lamina::experiments {
namespace {

struct Model {
    const char* json;
    bool rough;
};

class StabilityPolarised : public ::testing::TestWithParam<Model> {};

TEST_P(StabilityPolarised, NoNonFiniteElementAndNoJumpAcrossTheSingularAngles) {
    const std::string json = GetParam().json;
    const auto materialAt = [&](double alpha) {
        if (!GetParam().rough) return parseMaterialArgument(json);
        std::string j = json;
        j.insert(j.size() - 1, ",\"alpha\":" + std::to_string(alpha));
        return parseMaterialArgument(j);
    };
    const std::vector<double> indices = probedIndices(json);
    const PolarisedStabilityReport r = auditPolarisedStability(
        materialAt, GetParam().rough ? std::vector<double>{0, 0.1} : std::vector<double>{0},
        indices);
    EXPECT_EQ(r.nan, 0);
    EXPECT_EQ(r.inf, 0);
    EXPECT_LT(r.worstJumpFloat, kPolarisedJumpBound<float>);
    EXPECT_LT(r.worstJumpDouble, kPolarisedJumpBound<double>);
    EXPECT_EQ(r.discontinuities, 0);
    // The probes ran: matrices at every special angle, with the jump measured across Brewster's
    // (and, for an index, the critical) angle and the normal.
    EXPECT_GT(r.evaluations, 100);
    int jumpsMeasured = 0;
    for (const PolarisedProbe& p : r.probes) {
        jumpsMeasured += p.jumpDouble > 0;
        EXPECT_GT(p.evaluations, 0) << p.what;
    }
    EXPECT_GE(jumpsMeasured, indices.empty() ? 1 : 3) << json;
}

INSTANTIATE_TEST_SUITE_P(
    Models, StabilityPolarised,
    ::testing::Values(Model{R"({"type":"dielectric","ior":1.5})", true},
                      Model{R"({"type":"dielectric","ior":0.6666666666666666})", true},
                      Model{R"({"type":"dielectric","ior":4})", true},
                      Model{R"({"type":"conductor","eta":1.5,"k":0})", true},
                      Model{R"({"type":"conductor","material":"Au"})", true},
                      Model{R"({"type":"conductor","eta":0.5,"k":20})", true}),
    [](const auto& param) { return "model" + std::to_string(param.index); });

}  // namespace
}  // namespace lamina::experiments
