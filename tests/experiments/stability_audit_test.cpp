// The stability audit finds what is wrong: a model that is fine everywhere reports nothing,
// and a deliberately broken one (NaN at grazing views, a weight that is not eval / pdf, a
// reflectance above one) is caught in exactly the cells where it is broken.
#include <gtest/gtest.h>

#include "lamina/bsdf/material_builder.h"
#include "lamina/experiments/stability_audit.h"

namespace lamina {
namespace {

using namespace lamina::experiments;

/// Wraps a real BSDF and breaks it on purpose.
template <SpectrumType S>
class BrokenBxdf final : public Bxdf<S> {
  public:
    using Float = typename S::Float;
    enum class Fault { NanAtGrazing, WrongWeight, EnergyGain };
    BrokenBxdf(std::unique_ptr<Bxdf<S>> inner, Fault fault)
        : inner_(std::move(inner)), fault_(fault) {}

    S eval(const Vec3<Float>& wo, const Vec3<Float>& wi, TransportMode mode) const override {
        if (fault_ == Fault::NanAtGrazing && std::abs(wo.z) < Float(0.05))
            return S(std::numeric_limits<Float>::quiet_NaN());
        const S v = inner_->eval(wo, wi, mode);
        return fault_ == Fault::EnergyGain ? v * Float(1.2) : v;
    }
    Float pdf(const Vec3<Float>& wo, const Vec3<Float>& wi) const override {
        return inner_->pdf(wo, wi);
    }
    std::optional<BsdfSample<S>> sample(const Vec3<Float>& wo, Float uc, const Vec2<Float>& u,
                                        TransportMode mode) const override {
        auto s = inner_->sample(wo, uc, u, mode);
        if (!s) return s;
        if (fault_ == Fault::WrongWeight) s->weight *= Float(0.9);
        if (fault_ == Fault::EnergyGain) s->weight *= Float(1.2);
        return s;
    }
    std::uint32_t flags() const override { return inner_->flags(); }

  private:
    std::unique_ptr<Bxdf<S>> inner_;
    Fault fault_;
};

template <typename S>
using Broken = BrokenBxdf<S>;

StabilityModel model(const char* json, std::optional<Broken<Rgb<double>>::Fault> fault) {
    const MaterialDesc desc = parseMaterialArgument(json);
    StabilityModel m;
    m.makeDouble = [=](double) -> std::unique_ptr<Bxdf<Rgb<double>>> {
        auto b = buildBxdf(desc, SpectrumContext<Rgb<double>>{});
        if (!fault) return b;
        return std::make_unique<Broken<Rgb<double>>>(std::move(b), *fault);
    };
    m.makeFloat = [=](double) -> std::unique_ptr<Bxdf<Rgb<float>>> {
        auto b = buildBxdf(desc, SpectrumContext<Rgb<float>>{});
        if (!fault) return b;
        return std::make_unique<Broken<Rgb<float>>>(std::move(b),
                                                    static_cast<Broken<Rgb<float>>::Fault>(*fault));
    };
    return m;
}

const std::vector<double> kCosines = {1, 0.5, 0.01, 1e-6, 0};

TEST(StabilityAudit, AHealthyModelHasNoIssues) {
    const StabilityReport r = auditStability(
        model(R"({"type":"lambert","reflectance":1})", std::nullopt), {0.0}, kCosines, 32, 2048);
    const StabilityCell t = r.total();
    EXPECT_EQ(t.issues(), 0);
    EXPECT_LT(t.worstFloatError, 1e-5);
    EXPECT_GT(t.evaluations, 0);
}

TEST(StabilityAudit, FindsTheInjectedNanOnlyAtGrazingViews) {
    const StabilityReport r = auditStability(
        model(R"({"type":"lambert","reflectance":1})", Broken<Rgb<double>>::Fault::NanAtGrazing),
        {0.0}, kCosines, 32, 256);
    for (std::size_t c = 0; c < kCosines.size(); ++c) {
        if (kCosines[c] < 0.05)
            EXPECT_GT(r.at(0, c).nan, 0) << "cos " << kCosines[c];
        else
            EXPECT_EQ(r.at(0, c).nan, 0) << "cos " << kCosines[c];
    }
}

TEST(StabilityAudit, FindsAWeightThatIsNotEvalOverPdfAndAnEnergyGain) {
    const StabilityReport wrong = auditStability(
        model(R"({"type":"lambert","reflectance":1})", Broken<Rgb<double>>::Fault::WrongWeight),
        {0.0}, {0.5}, 16, 256);
    EXPECT_GT(wrong.total().weightMismatch, 200);
    const StabilityReport gain = auditStability(
        model(R"({"type":"lambert","reflectance":1})", Broken<Rgb<double>>::Fault::EnergyGain),
        {0.0}, {0.5}, 16, 2048);
    EXPECT_EQ(gain.total().energyGain, 1);
}

}  // namespace
}  // namespace lamina
