// The layered stack over a conductor base (bsdf/refracted_conductor.h) against the random walk
// where the physics says they agree, and its energy. Fixed seeds; each group of z-tests is held
// to a family-wise significance of 1% (Sidak: per comparison 1 - 0.99^(1/k)).
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/bsdf/coated.h"
#include "lamina/bsdf/layered.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/core/pcg32.h"
#include "lamina/core/special_functions.h"
#include "sampled_albedo.h"

namespace lamina {
namespace {

using S = Rgb<double>;
using testing::MeanAndError;
using testing::sampledAlbedo;

std::unique_ptr<Bxdf<S>> material(const std::string& json) {
    return buildBxdf(parseMaterialArgument(json), SpectrumContext<S>{});
}

// The two-sided z bound of a family of k comparisons at family-wise significance 1%.
double sidakZ(int k) {
    const double alpha = 1.0 - std::pow(0.99, 1.0 / double(k));
    return std::sqrt(2.0) * erfInv(1.0 - alpha);
}

// The mean of `values` and its standard error.
MeanAndError meanOf(const std::vector<double>& values) {
    double sum = 0, sum2 = 0;
    for (double v : values) {
        sum += v;
        sum2 += v * v;
    }
    const double n = double(values.size()), mean = sum / n;
    return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n)};
}

// The walk's f |cos| at wo = normal, wi at theta_i (degrees) in the x-z plane: the mean of
// `n` estimates and its standard error.
MeanAndError walkEval(const CoatedBxdf<S>& walk, const Vec3d& wi, int n, std::uint64_t seed) {
    Pcg32 rng(seed);
    std::vector<double> estimates;
    for (int e = 0; e < n; ++e)
        estimates.push_back(
            walk.estimate(Vec3d(0, 0, 1), wi, TransportMode::Radiance, rng).value[0]);
    return meanOf(estimates);
}

Vec3d inPlane(double thetaDeg) {
    const double r = thetaDeg * kPi<double> / 180.0;
    return {std::sin(r), 0, std::cos(r)};
}

// A coat of index 1 over a rough conductor is no coat: the walk (an estimate; near the mirror
// direction its connection is the base's own eval, with standard error 0) and both twins (exact)
// are the bare conductor, so they agree within the walk's standard errors (and rounding).
TEST(LayeredConductorWalk, AnIndexMatchedCoatIsTheWalkWithinItsStandardErrors) {
    const std::string base = R"({"type":"conductor","f0":0.8,"roughness":0.4})";
    const auto walkBsdf =
        material(R"({"type":"coated","ior":1,"roughness":0.3,"base":)" + base + "}");
    const auto& walk = dynamic_cast<const CoatedBxdf<S>&>(*walkBsdf);
    const std::vector<double> thetaI = {0, 10, 20, 40};
    const double z = sidakZ(2 * int(thetaI.size()));
    for (const char* coupling : {"fresnel", "albedo"}) {
        const auto twin = material(R"({"type":"layered","interface":{"roughness":0.3,"ior":1,)"
                                   R"("fresnel":"exact"},"base":)" +
                                   base + R"(,"coupling":")" + coupling + R"("})");
        for (double t : thetaI) {
            const MeanAndError w = walkEval(walk, inPlane(t), 4000, 11 + std::uint64_t(t));
            const double f = twin->eval(Vec3d(0, 0, 1), inPlane(t), TransportMode::Radiance)[0];
            EXPECT_LE(std::abs(f - w.mean), z * w.error + 1e-12 * f)
                << coupling << " theta_i " << t << ": twin " << f << ", walk " << w.mean << " +- "
                << w.error;
        }
    }
}

// A smooth coat over a dark rough conductor (F0 = 0.05), seen at normal incidence: the light the
// coat reflects back down (F ~ 0.04) returns from the base with 5% of it, and the base's lobe
// (alpha 0.04) sends almost nothing beyond the critical angle, so the passes after the first add
// about 0.2% to the walk's answer, and the first pass is what the albedo coupling computes for
// a smooth coat (the exact transmittances (1 - F(theta_o)) (1 - F(theta_i))). The walk must
// then lie above the twin (within its error bar) and by at most 1% of its value: eval at five
// theta_i, and the directional albedo. With the fresnel coupling, 1 - F(wi.h) in place of the
// two transmittances, the twin is 4% brighter and fails this (checked).
TEST(LayeredConductorWalk, ASmoothCoatOverADarkConductorIsItsSinglePassPlusAtMostOnePercent) {
    const std::string base = R"({"type":"conductor","f0":0.05,"roughness":0.2})";
    const auto walkBsdf = material(R"({"type":"coated","ior":1.5,"base":)" + base + "}");
    const auto& walk = dynamic_cast<const CoatedBxdf<S>&>(*walkBsdf);
    const auto twin = material(R"({"type":"layered","interface":{"roughness":0,"ior":1.5,)"
                               R"("fresnel":"exact"},"base":)" +
                               base + R"(,"coupling":"albedo"})");
    const std::vector<double> thetaI = {0, 4, 8, 12, 16};
    const double z = sidakZ(int(thetaI.size()) + 1);
    for (double t : thetaI) {
        const MeanAndError w = walkEval(walk, inPlane(t), 40000, 101 + std::uint64_t(t));
        const double f = twin->eval(Vec3d(0, 0, 1), inPlane(t), TransportMode::Radiance)[0];
        EXPECT_GT(w.mean - f, -z * w.error)
            << "theta_i " << t << ": twin " << f << ", walk " << w.mean << " +- " << w.error;
        EXPECT_LT(w.mean - f, 0.01 * w.mean + z * w.error)
            << "theta_i " << t << ": twin " << f << ", walk " << w.mean << " +- " << w.error;
    }
    const MeanAndError a = sampledAlbedo(*twin, Vec3d(0, 0, 1), 400000, 0, 3);
    const MeanAndError b = sampledAlbedo(walk, Vec3d(0, 0, 1), 400000, 0, 4);
    const double e = z * std::hypot(a.error, b.error);
    EXPECT_GT(b.mean - a.mean, -e) << "albedo: twin " << a.mean << " +- " << a.error << ", walk "
                                   << b.mean << " +- " << b.error;
    EXPECT_LT(b.mean - a.mean, 0.01 * b.mean + e) << "albedo: twin " << a.mean << " +- " << a.error
                                                  << ", walk " << b.mean << " +- " << b.error;
}

// A white conductor (F0 = 1) under a rough coat: with the albedo coupling the stack reflects at
// most what it receives (E(mu_o) + (1 - E(mu_o)) x the base's albedo <= 1) at every angle, and a
// white base through a smooth coat loses only what the single pass drops, so it keeps most.
TEST(LayeredConductorWalk, AWhiteConductorUnderTheAlbedoCouplingConservesEnergy) {
    const int n = 200000;
    const double z = sidakZ(2 * 4);
    for (const char* interface : {R"("roughness":0.5)", R"("roughness":0)"}) {
        const auto b = material(std::string(R"({"type":"layered","interface":{)") + interface +
                                R"(,"ior":1.5,"fresnel":"exact"},"base":{"type":"conductor",)"
                                R"("f0":1,"roughness":0.3},"coupling":"albedo"})");
        for (double theta : {0.0, 30.0, 60.0, 85.0}) {
            const double r = theta * kPi<double> / 180.0;
            const MeanAndError a = sampledAlbedo(*b, Vec3d(std::sin(r), 0, std::cos(r)), n, 0, 7);
            EXPECT_LT(a.mean - z * a.error, 1.0) << interface << " at " << theta;
            EXPECT_GT(a.mean, 0.5) << interface << " at " << theta;
        }
    }
}

}  // namespace
}  // namespace lamina
