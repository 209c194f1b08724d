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

/// A real BSDF whose Mueller matrices turn their output frame by 90 degrees (S1 and S2 change
/// sign) beyond Brewster's angle from outside: the kind of frame error the audit is for.
template <std::floating_point T>
class TurnedPastBrewster final : public Bxdf<SampledSpectrum<T>> {
  public:
    using S = SampledSpectrum<T>;
    using V = Vec3<T>;
    TurnedPastBrewster(std::unique_ptr<Bxdf<S>> inner, double eta)
        : inner_(std::move(inner)), cosBrewster_(T(1 / std::sqrt(1 + eta * eta))) {}
    S eval(const V& wo, const V& wi, TransportMode mode) const override {
        return inner_->eval(wo, wi, mode);
    }
    T pdf(const V& wo, const V& wi) const override { return inner_->pdf(wo, wi); }
    std::optional<BsdfSample<S>> sample(const V& wo, T uc, const Vec2<T>& u,
                                        TransportMode mode) const override {
        return inner_->sample(wo, uc, u, mode);
    }
    std::uint32_t flags() const override { return inner_->flags(); }
    MuellerMatrix<S> evalMueller(const V& wo, const V& wi, TransportMode mode) const override {
        return turned(wo, inner_->evalMueller(wo, wi, mode));
    }
    MuellerMatrix<S> sampleMueller(const V& wo, const BsdfSample<S>& s,
                                   TransportMode mode) const override {
        return turned(wo, inner_->sampleMueller(wo, s, mode));
    }

  private:
    MuellerMatrix<S> turned(const V& wo, MuellerMatrix<S> m) const {
        if (wo.z > T(0) && wo.z < cosBrewster_)
            for (int row = 1; row < 3; ++row)
                for (int c = 0; c < 4; ++c)
                    m(row, c) = -m(row, c);
        return m;
    }
    std::unique_ptr<Bxdf<S>> inner_;
    T cosBrewster_;
};

TEST(StabilityPolarisedAudit, FindsAFrameTurnedPastBrewstersAngle) {
    const MaterialDesc glass = parseMaterialArgument(R"({"type":"dielectric","ior":1.5})");
    PolarisedStabilityModel model;
    model.makeDouble =
        [&](double,
            SampledWavelengths<double>& lambda) -> std::unique_ptr<Bxdf<SampledSpectrum<double>>> {
        return std::make_unique<TurnedPastBrewster<double>>(
            buildBxdf(glass, SpectrumContext<SampledSpectrum<double>>{lambda}), 1.5);
    };
    model.makeFloat =
        [&](double,
            SampledWavelengths<float>& lambda) -> std::unique_ptr<Bxdf<SampledSpectrum<float>>> {
        return std::make_unique<TurnedPastBrewster<float>>(
            buildBxdf(glass, SpectrumContext<SampledSpectrum<float>>{lambda}), 1.5);
    };
    const PolarisedStabilityReport r = auditPolarisedStability(model, {0.0}, {1.5});
    EXPECT_EQ(r.nan + r.inf, 0);
    // Found in both precisions, at Brewster's angle from outside and nowhere else.
    EXPECT_EQ(r.discontinuities, 2);
    for (const PolarisedProbe& p : r.probes) {
        const bool there = p.what == "Brewster's angle, outside";
        EXPECT_EQ(p.jumpFloat > kPolarisedJumpBound<float>, there) << p.what;
        EXPECT_EQ(p.jumpDouble > kPolarisedJumpBound<double>, there) << p.what;
    }
}

}  // namespace
}  // namespace lamina::experiments
