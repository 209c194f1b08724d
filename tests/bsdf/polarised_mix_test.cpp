// The polarised `mix` (mix.h, docs/polarisation.md): it polarises as its two materials. Its
// Mueller matrix is the weighted sum of theirs, in the same canonical frames; a delta sample's
// matrix is that of the material that drew it, which the sample names through every enclosing
// mix (BsdfSample::component, one bit per mix), also when the light runs backwards (the
// polarised mode's light paths ask for the reversed sample's matrix). The catalogue's
// PolarisedBsdf tests hold the mixes of bsdf_cases.h to [0][0] = eval, realisability and
// reciprocity. Broken once on purpose: a mix that hands every delta sample to its material a
// fails the nested tests (the leaves' matrices differ by more than 0.01 in some element), and
// the ideal depolariser the mix was before fails the weighted sum.
#include <gtest/gtest.h>

#include <numbers>

#include "bsdf_cases.h"
#include "lamina/bsdf/mix.h"
#include "lamina/core/error.h"
#include "lamina/core/pcg32.h"

namespace lamina {
namespace {

using testing::Spec;
using Mueller = MuellerMatrix<Spec>;

// The component bits fit where the flags' upper half was: the sample is as large as before.
static_assert(sizeof(BsdfSample<Rgb<float>>) == 36 && sizeof(BsdfSample<Rgb<double>>) == 72 &&
              sizeof(BsdfSample<SampledSpectrum<float>>) == 40 &&
              sizeof(BsdfSample<SampledSpectrum<double>>) == 80);

std::unique_ptr<Bxdf<Spec>> build(const std::string& json) {
    return buildBxdf(parseMaterialArgument(json), SpectrumContext<Spec>{});
}

Vec3d randomDirection(Pcg32& rng) {
    const double z = 2.0 * rng.nextDouble() - 1.0;
    const double phi = 2.0 * std::numbers::pi * rng.nextDouble();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

/// The largest difference of an element of a and b, channel by channel, over b's [0][0].
double relativeDistance(const Mueller& a, const Mueller& b) {
    double d = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double scale = std::max(std::abs(b(0, 0)[c]), 1e-300);
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k)
                d = std::max(d, std::abs(a(r, k)[c] - b(r, k)[c]) / scale);
    }
    return d;
}

/// m with each channel divided by its [0][0]: the shape of the event, whatever its magnitude.
Mueller normalised(Mueller m) {
    for (int c = 0; c < 3; ++c) {
        const double m00 = m(0, 0)[c];
        for (int r = 0; r < 4; ++r)
            for (int k = 0; k < 4; ++k)
                m(r, k)[c] /= m00;
    }
    return m;
}

const char* const kRoughGold =
    R"({"type":"conductor","eta":[0.18,0.42,1.37],"k":[3.42,2.35,1.77],"fresnel":"exact",)"
    R"("roughness":0.4})";
const char* const kMatte = R"({"type":"lambert","reflectance":[0.7,0.5,0.3]})";

TEST(PolarisedMix, ItsMuellerMatrixIsTheWeightedSumOfItsMaterials) {
    const auto mix = build(std::string(R"({"type":"mix","weight":0.3,"a":)") + kRoughGold +
                           R"(,"b":)" + kMatte + "}");
    const auto gold = build(kRoughGold), matte = build(kMatte);
    Pcg32 rng(3);
    int polarised = 0, sampled = 0;
    for (int i = 0; i < 500; ++i) {
        const Vec3d wo = randomDirection(rng), wi = randomDirection(rng);
        for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
            const Mueller m = mix->evalMueller(wo, wi, mode);
            const Mueller expected = gold->evalMueller(wo, wi, mode) * 0.7 +
                                     depolarising(matte->eval(wo, wi, mode)) * 0.3;
            for (int c = 0; c < 3; ++c)
                for (int r = 0; r < 4; ++r)
                    for (int k = 0; k < 4; ++k)
                        ASSERT_NEAR(m(r, k)[c], expected(r, k)[c],
                                    1e-12 * std::max(1.0, expected(0, 0)[c]))
                            << "element " << r << k << " channel " << c;
            // The gold polarises unpolarised light: the test compares something.
            if (std::hypot(m(1, 0)[1], m(2, 0)[1]) > 0.01 * m(0, 0)[1]) ++polarised;
        }
        // A non-delta sample's matrix is the mixture's matrix over the mixture's density.
        const auto s = mix->sample(wo, rng.nextDouble(), {rng.nextDouble(), rng.nextDouble()},
                                   TransportMode::Radiance);
        if (!s) continue;
        ++sampled;
        const Mueller w = mix->sampleMueller(wo, *s, TransportMode::Radiance);
        EXPECT_LT(
            relativeDistance(w, mix->evalMueller(wo, s->wi, TransportMode::Radiance) / s->pdf),
            1e-12);
    }
    EXPECT_GT(polarised, 50);
    EXPECT_GT(sampled, 200);
}

// Four smooth leaves whose reflections differ in shape (gold and copper retard by different
// phases, the black glass and the index-0.5 conductor do not), and a diffuse fifth, nested three
// deep: with every weight 0.5 the lobe number uc picks
//   [0, 1/4) gold, [1/4, 3/8) black glass, [3/8, 1/2) the index-0.5 conductor,
//   [1/2, 3/4) the diffuse, [3/4, 1) copper.
const char* const kGold =
    R"({"type":"conductor","eta":[0.18,0.42,1.37],"k":[3.42,2.35,1.77],"fresnel":"exact",)"
    R"("alpha":0})";
const char* const kBlackGlass =
    R"({"type":"conductor","eta":1.5,"k":0,"fresnel":"exact","alpha":0})";
const char* const kLowIndex = R"({"type":"conductor","eta":0.5,"k":6,"fresnel":"exact","alpha":0})";
const char* const kCopper =
    R"({"type":"conductor","eta":[0.27,0.68,1.2],"k":[3.6,2.6,2.3],"fresnel":"exact",)"
    R"("alpha":0})";

std::string mixOf(const std::string& a, const std::string& b) {
    return R"({"type":"mix","weight":0.5,"a":)" + a + R"(,"b":)" + b + "}";
}

TEST(PolarisedMix, ANestedMixHandsADeltaSampleBackToTheLeafThatDrewIt) {
    const auto mix =
        build(mixOf(mixOf(kGold, mixOf(kBlackGlass, kLowIndex)), mixOf(kMatte, kCopper)));
    const std::unique_ptr<Bxdf<Spec>> leaves[] = {build(kGold), build(kBlackGlass),
                                                  build(kLowIndex), nullptr, build(kCopper)};
    const double bounds[] = {0.0, 0.25, 0.375, 0.5, 0.75, 1.0};
    int checked = 0;
    for (const double theta : {30.0, 55.0, 70.0, 85.0})
        for (const double side : {1.0, -1.0}) {
            Vec3d wo = testing::directionAt(theta, 35.0);
            wo.z *= side;
            // The leaves' own matrices of this reflection, and how far apart they are: a sample
            // handed to the wrong leaf shows.
            std::vector<Mueller> own;
            for (const auto& leaf : leaves) {
                if (!leaf) {
                    own.emplace_back();
                    continue;
                }
                const auto s = leaf->sample(wo, 0.5, {0.5, 0.5}, TransportMode::Radiance);
                ASSERT_TRUE(s && s->isSpecular());
                own.push_back(leaf->sampleMueller(wo, *s, TransportMode::Radiance));
            }
            for (int a = 0; a < 5; ++a)
                for (int b = a + 1; b < 5; ++b) {
                    if (!leaves[a] || !leaves[b]) continue;
                    ASSERT_GT(relativeDistance(normalised(own[std::size_t(a)]),
                                               normalised(own[std::size_t(b)])),
                              0.01)
                        << "leaves " << a << " and " << b << " at " << theta;
                }
            for (int leaf = 0; leaf < 5; ++leaf)
                for (const double f : {0.01, 0.5, 0.99}) {
                    const double uc = bounds[leaf] + f * (bounds[leaf + 1] - bounds[leaf]);
                    const auto s = mix->sample(wo, uc, {0.3, 0.7}, TransportMode::Radiance);
                    ASSERT_TRUE(s);
                    ASSERT_EQ(s->isSpecular(), leaves[leaf] != nullptr) << "uc " << uc;
                    if (!s->isSpecular()) continue;
                    const Mueller m = mix->sampleMueller(wo, *s, TransportMode::Radiance);
                    // The leaf's matrix: its reflectance over the probability 1/4 or 1/8 of
                    // choosing it, which the sample's weight already holds.
                    EXPECT_LT(relativeDistance(m, own[std::size_t(leaf)]), 1e-12)
                        << "leaf " << leaf << " uc " << uc << " theta " << theta;
                    EXPECT_NEAR(s->pdf, bounds[leaf + 1] - bounds[leaf], 1e-12);
                    // The light running backwards (what the polarised mode's light paths ask
                    // for): the same sample seen from its other end reaches the same leaf.
                    const BsdfSample<Spec> reversed(wo, s->weight, s->pdf, s->flags, s->eta,
                                                    s->component);
                    const auto back =
                        leaves[leaf]->sample(s->wi, 0.5, {0.5, 0.5}, TransportMode::Radiance);
                    ASSERT_TRUE(back);
                    EXPECT_LT(
                        relativeDistance(
                            mix->sampleMueller(s->wi, reversed, TransportMode::Radiance),
                            leaves[leaf]->sampleMueller(s->wi, *back, TransportMode::Radiance)),
                        1e-12);
                    ++checked;
                }
        }
    EXPECT_EQ(checked, 4 * 2 * 4 * 3);
}

// kMaxMixNesting mixes inside each other route a delta sample to the innermost leaf; one more
// is refused when the material is read, with the JSON path of the mix that goes too deep.
TEST(PolarisedMix, SixteenNestedMixesRouteAndSeventeenAreRefused) {
    auto nested = [](int depth) {
        std::string json = kGold;
        for (int i = 0; i < depth; ++i)  // the gold on side b of every mix, the matte on a
            json = R"({"type":"mix","weight":0.5,"a":)" + std::string(kMatte) + R"(,"b":)" + json +
                   "}";
        return json;
    };
    const auto deepest = build(nested(kMaxMixNesting));
    const auto gold = build(kGold);
    const Vec3d wo = testing::directionAt(60.0);
    // uc in the last 2^-16 of [0, 1) picks b at every level.
    const auto s = deepest->sample(wo, 1.0 - 1e-7, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(s && s->isSpecular());
    EXPECT_EQ(s->component, 0xFFFFu);
    const auto own = gold->sample(wo, 0.5, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(own);
    EXPECT_LT(relativeDistance(deepest->sampleMueller(wo, *s, TransportMode::Radiance),
                               gold->sampleMueller(wo, *own, TransportMode::Radiance)),
              1e-9);
    try {
        build(nested(kMaxMixNesting + 1));
        FAIL() << "17 nested mixes were accepted";
    } catch (const InputError& e) {
        // The outermost mix is the 17th: its JSON path is the top of the material.
        const std::string what = e.what();
        EXPECT_NE(what.find("<material argument>: "), std::string::npos) << what;
        EXPECT_NE(what.find("17 mixes nest inside each other; at most 16"), std::string::npos)
            << what;
    }
}

}  // namespace
}  // namespace lamina
