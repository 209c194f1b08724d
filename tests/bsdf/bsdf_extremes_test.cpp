// Numerical stability on extreme inputs: every material over roughness
// alpha in {0, 1e-7, 1e-5, 1e-3, 0.01, 0.1, 0.5, 1}, conductor k in {0, 0.1, 3, 10, 20},
// dielectric and thin_dielectric eta in {1, 1+1e-6, 1.0001, 1.33, 1.5, 2.42, 4} and their
// reciprocals, diffuse_transmission with one or both albedos at 0, 1e-7 or 1, and
// directions with cos theta in {0, +-1e-8, 1e-6, 1e-4, 0.01, 0.5, 1}, at the horizon, below
// it, equal and opposite: eval, pdf and sample never return NaN, Inf or a negative value, and
// the float result is within 1e-3 relative of the double one wherever the double value is
// above 1e-6 of the configuration's peak. (alpha < 1e-3 is treated as smooth in both
// precisions: kSmoothAlpha; anisotropic pairs with one alpha below it and the other above,
// such as alpha_x 0 and alpha_y 1, are rough with the small one raised to kSmoothAlpha.)
//
// Where the function itself is ill-conditioned at float precision, no float code can meet
// 1e-3: rough refraction within ~1e-5 of the critical angle (the Fresnel factor has a
// square-root singularity there) changes by ~1% when a direction moves by one float ulp.
// Such points are found by perturbing each direction component by two float ulps (relative)
// in double; the comparison
// skips them, and the test requires them to be rare (at most 5% of the compared pairs;
// the worst case, rough glass of index 2.42 seen from inside, has 8 of 252; hair, whose fibre
// offset is undefined along the fibre, is allowed 10%).
#include <gtest/gtest.h>

#include <cstdio>

#include "lamina/bsdf/material_builder.h"

namespace lamina {
namespace {

struct Config {
    std::string name, json;
};

void PrintTo(const Config& c, std::ostream* os) {
    *os << c.json;
}

std::string number(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::vector<Config> configs() {
    std::vector<Config> out;
    const double alphas[] = {0, 1e-7, 1e-5, 1e-3, 0.01, 0.1, 0.5, 1};
    for (double a : alphas) {
        for (double k : {0.0, 0.1, 3.0, 10.0, 20.0})
            for (const char* ndf : {"ggx", "beckmann"})
                out.push_back(
                    {std::string("conductor_") + ndf + "_a" + number(a) + "_k" + number(k),
                     R"({"type":"conductor","distribution":")" + std::string(ndf) +
                         R"(","alpha":)" + number(a) + R"(,"eta":0.4,"k":)" + number(k) + "}"});
        for (double eta : {1.0, 1 + 1e-6, 1.0001, 1.33, 1.5, 2.42, 4.0})
            for (int inverse = 0; inverse < (eta == 1.0 ? 1 : 2); ++inverse) {  // 1/1 = 1
                const double e = inverse ? 1 / eta : eta;
                out.push_back({"dielectric_a" + number(a) + "_eta" + number(e),
                               R"({"type":"dielectric","alpha":)" + number(a) + R"(,"ior":)" +
                                   number(e) + "}"});
            }
        out.push_back({"standard_a" + number(a),
                       R"({"type":"standard","alpha":)" + number(a) + R"(,"base_color":1})"});
        out.push_back(
            {"standard_metal_a" + number(a), R"({"type":"standard","metalness":1,"alpha":)" +
                                                 number(a) + R"(,"base_color":[1,0.8,0.3]})"});
        out.push_back(
            {"standard_glass_a" + number(a), R"({"type":"standard","transmission":0.7,"alpha":)" +
                                                 number(a) + R"(,"base_color":1})"});
    }
    // Anisotropic extremes: smooth along one tangent axis and rough along the other (a legal
    // alpha_x / alpha_y pair; the smooth axis takes the narrowest rough lobe, kSmoothAlpha).
    const std::pair<double, double> anisotropic[] = {{0, 1},      {1, 0},       {0, 0.5},
                                                     {1e-7, 0.3}, {5e-4, 0.01}, {1e-3, 1}};
    for (const auto& [ax, ay] : anisotropic) {
        const std::string alphaKeys = R"("alpha_x":)" + number(ax) + R"(,"alpha_y":)" + number(ay);
        const std::string tag = "_ax" + number(ax) + "_ay" + number(ay);
        for (const char* ndf : {"ggx", "beckmann"})
            out.push_back({std::string("conductor_") + ndf + tag,
                           R"({"type":"conductor","distribution":")" + std::string(ndf) + R"(",)" +
                               alphaKeys + R"(,"eta":0.4,"k":3})"});
        out.push_back(
            {"dielectric" + tag, R"({"type":"dielectric",)" + alphaKeys + R"(,"ior":1.5})"});
        out.push_back(
            {"standard" + tag, R"({"type":"standard",)" + alphaKeys + R"(,"base_color":1})"});
    }
    // Hair: roughness from 0 (taken as 0.01) to 1, clear to nearly black fibres, steep tilts.
    for (double b : {0.0, 1e-3, 0.05, 0.3, 1.0})
        for (double e : {0.0, 8.0})
            out.push_back({"hair_b" + number(b) + "_eumelanin" + number(e),
                           R"({"type":"hair","beta_m":)" + number(b) + R"(,"beta_n":)" + number(b) +
                               R"(,"eumelanin":)" + number(e) + R"(,"alpha":)" + number(b * 30) +
                               "}"});
    for (double eta : {1.0, 1 + 1e-6, 1.0001, 1.33, 1.5, 2.42, 4.0})
        for (int inverse = 0; inverse < (eta == 1.0 ? 1 : 2); ++inverse) {
            const double e = inverse ? 1 / eta : eta;
            out.push_back({"thin_dielectric_eta" + number(e),
                           R"({"type":"thin_dielectric","ior":)" + number(e) + "}"});
        }
    for (const auto& [r, t] :
         std::initializer_list<std::pair<double, double>>{{0, 1}, {1, 0}, {0.5, 0.5}, {1e-7, 1e-7}})
        out.push_back({"diffuse_transmission_r" + number(r) + "_t" + number(t),
                       R"({"type":"diffuse_transmission","reflectance":)" + number(r) +
                           R"(,"transmittance":)" + number(t) + "}"});
    for (const char* d : {"lambert", "oren_nayar", "burley", "frostbite"})
        for (double r : {0.0, 1e-5, 0.5, 1.0})
            out.push_back({std::string(d) + "_r" + number(r),
                           R"({"type":")" + std::string(d) + R"(","reflectance":1)" +
                               (std::string(d) == "lambert" ? "" : R"(,"roughness":)" + number(r)) +
                               "}"});
    return out;
}

// The directions are rounded to float first and then used by both precisions, so the
// comparison measures the arithmetic of each variant, not the rounding of its inputs.
std::vector<Vec3<double>> directions() {
    std::vector<Vec3<double>> out;
    for (double c : {0.0, 1e-8, -1e-8, 1e-6, 1e-4, 0.01, 0.5, 1.0, -0.5, -1.0, -1e-4})
        for (double phi : {0.0, 2.0}) {
            const double s = std::sqrt(std::max(0.0, 1 - c * c));
            out.emplace_back(Vec3<float>(Vec3<double>(s * std::cos(phi), s * std::sin(phi), c)));
        }
    return out;
}

template <typename S>
bool bad(const S& s) {
    return !s.isFinite() || s.hasNegative();
}

class BsdfExtremes : public ::testing::TestWithParam<Config> {};

TEST_P(BsdfExtremes, FiniteNonNegativeAndFloatMatchesDouble) {
    const MaterialDesc desc = parseMaterialArgument(GetParam().json);
    const auto d = buildBxdf(desc, SpectrumContext<Rgb<double>>{});
    const auto f = buildBxdf(desc, SpectrumContext<Rgb<float>>{});
    const auto dirs = directions();
    struct Pair {
        Vec3<double> wo, wi;
        Rgb<double> value;
        double pdf;
    };
    std::vector<Pair> pairs;
    double peak = 0, peakPdf = 0;
    for (const auto& wo : dirs)
        for (const auto& wi : dirs)
            for (auto mode : {TransportMode::Radiance, TransportMode::Importance}) {
                const Rgb<double> v = d->eval(wo, wi, mode);
                const double p = d->pdf(wo, wi);
                const Rgb<float> vf = f->eval(Vec3<float>(wo), Vec3<float>(wi), mode);
                const float pf = f->pdf(Vec3<float>(wo), Vec3<float>(wi));
                ASSERT_FALSE(bad(v)) << "eval(double) wo.z " << wo.z << " wi.z " << wi.z;
                ASSERT_FALSE(bad(vf)) << "eval(float) wo.z " << wo.z << " wi.z " << wi.z;
                ASSERT_TRUE(std::isfinite(p) && p >= 0) << "pdf " << p;
                ASSERT_TRUE(std::isfinite(pf) && pf >= 0) << "pdf(float) " << pf;
                if (mode == TransportMode::Radiance) pairs.push_back({wo, wi, v, p});
                peak = std::max(peak, v.maxValue());
                peakPdf = std::max(peakPdf, p);
            }
    // Equal and opposite directions are among the pairs (wo == wi, wo == -wi).
    auto illConditioned = [&](const Pair& p) {
        // Two float ulps per component, relative (the rounding float inputs carry).
        const double h = 2.4e-7;
        const Vec3<double> shifts[] = {{h, 0, 0}, {0, h, 0}, {0, 0, h}, {-h, 0, 0}, {0, 0, -h}};
        for (const auto& dv : shifts)
            for (int which = 0; which < 2; ++which) {
                const Vec3<double> o = which ? p.wo : glm::normalize(p.wo * (1.0 + dv));
                const Vec3<double> i = which ? glm::normalize(p.wi * (1.0 + dv)) : p.wi;
                const Rgb<double> v = d->eval(o, i, TransportMode::Radiance);
                for (int c = 0; c < 3; ++c)
                    if (std::abs(v[c] - p.value[c]) > 2.5e-4 * p.value[c]) return true;
                if (std::abs(d->pdf(o, i) - p.pdf) > 2.5e-4 * p.pdf) return true;
            }
        return false;
    };
    int compared = 0, skipped = 0;
    for (const Pair& p : pairs) {
        if (p.value.maxValue() > 1e-6 * peak || p.pdf > 1e-6 * peakPdf) {
            ++compared;
            if (illConditioned(p)) {
                ++skipped;
                continue;
            }
        }
        const Rgb<float> vf =
            f->eval(Vec3<float>(p.wo), Vec3<float>(p.wi), TransportMode::Radiance);
        for (int c = 0; c < 3; ++c) {
            if (p.value[c] > 1e-6 * peak) {
                EXPECT_NEAR(double(vf[c]), p.value[c], 1e-3 * p.value[c])
                    << "eval wo " << p.wo.x << "," << p.wo.z << " wi " << p.wi.x << "," << p.wi.z;
            }
        }
        if (p.pdf > 1e-6 * peakPdf) {
            EXPECT_NEAR(double(f->pdf(Vec3<float>(p.wo), Vec3<float>(p.wi))), p.pdf, 1e-3 * p.pdf)
                << "pdf wo " << p.wo.x << "," << p.wo.z << " wi " << p.wi.x << "," << p.wi.z;
        }
    }
    // Hair takes the fibre offset h from wo's direction across the fibre, which is undefined
    // along it: directions near the fibre axis (the tests' horizon directions in x) are
    // ill-conditioned by the model itself, 17 of 297 pairs at most (beta 0.3, alpha 9).
    const bool hair = GetParam().json.find(R"("type":"hair")") != std::string::npos;
    EXPECT_LE(skipped, std::max(1, compared / (hair ? 10 : 20)))
        << skipped << " of " << compared << " pairs are ill-conditioned";
    // Sampling at every direction, including the random numbers' edges (pbrt-v4 #313).
    for (const auto& wo : dirs)
        for (double uc : {0.0, 0.5, 1 - 1e-16})
            for (double u0 : {0.0, 0.3, 1 - 1e-16})
                for (double u1 : {0.0, 0.7, 1 - 1e-16}) {
                    const auto s = d->sample(wo, uc, {u0, u1}, TransportMode::Radiance);
                    if (s) {
                        ASSERT_FALSE(bad(s->weight)) << "sample weight at wo.z " << wo.z;
                        ASSERT_TRUE(std::isfinite(s->pdf) && s->pdf > 0) << "sample pdf " << s->pdf;
                        ASSERT_NEAR(glm::length(s->wi), 1.0, 1e-6);
                    }
                    const auto sf = f->sample(Vec3<float>(wo), float(uc), {float(u0), float(u1)},
                                              TransportMode::Radiance);
                    if (sf) {
                        ASSERT_FALSE(bad(sf->weight)) << "sample weight (float) at wo.z " << wo.z;
                        ASSERT_TRUE(std::isfinite(sf->pdf) && sf->pdf > 0);
                    }
                }
}

INSTANTIATE_TEST_SUITE_P(AllMaterials, BsdfExtremes, ::testing::ValuesIn(configs()),
                         [](const auto& paramInfo) {
                             std::string n = paramInfo.param.name;
                             for (char& c : n)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return n;
                         });

}  // namespace
}  // namespace lamina
