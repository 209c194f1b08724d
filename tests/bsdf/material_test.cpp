// Materials: the `standard` material reproduces the article's code sample, switches select
// the documented models, and bad parameters are rejected with their JSON path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/bsdf/conductor.h"
#include "lamina/bsdf/dielectric.h"
#include "lamina/bsdf/diffuse.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/mix.h"
#include "lamina/bsdf/standard.h"
#include "lamina/core/error.h"

namespace lamina {
namespace {

using Spec = Rgb<double>;
using V3 = Vec3<double>;

std::unique_ptr<Bxdf<Spec>> build(const std::string& json) {
    static const SpectrumContext<Spec> context;
    return buildBxdf(parseMaterialArgument(json), context);
}

// The article's evalCombinedBRDF for the default switches, written from its formulas in plain
// double arithmetic: GGX D, the optimised height-correlated Smith G2 / (4 NdotL NdotV)
// (Lagarde and de Rousiers 2014), Schlick with F90 = min(1, luminance(F0) / 0.04) at L.H,
// Lambert diffuse weighted by (1 - F).
Spec articleReference(const V3& v, const V3& l, const Spec& baseColor, double metalness,
                      double roughness) {
    const double alpha = roughness * roughness, a2 = alpha * alpha;
    const V3 h = glm::normalize(v + l);
    const double nl = l.z, nv = v.z, nh = h.z, lh = glm::dot(l, h);
    const Spec f0 = Spec(0.04) * (1.0 - metalness) + baseColor * metalness;
    const double f90 = std::min(1.0, (0.2126 * f0[0] + 0.7152 * f0[1] + 0.0722 * f0[2]) / 0.04);
    const Spec F = f0 + (Spec(f90) - f0) * std::pow(1.0 - lh, 5.0);
    const double d = a2 / (kPi<double> * sqr(nh * nh * (a2 - 1.0) + 1.0));
    const double ggxl = nv * std::sqrt((-nl * a2 + nl) * nl + a2);
    const double ggxv = nl * std::sqrt((-nv * a2 + nv) * nv + a2);
    const double vis = 0.5 / (ggxv + ggxl);
    const Spec specular = F * (d * vis * nl);
    const Spec diffuse = baseColor * (1.0 - metalness) * (nl / kPi<double>);
    return (Spec(1.0) - F) * diffuse + specular;
}

TEST(StandardMaterial, DefaultSwitchesReproduceTheArticle) {
    struct Params {
        Spec base;
        double metalness, roughness;
    };
    const Params params[] = {{Spec(0.8, 0.5, 0.2), 0.0, 0.5},
                             {Spec(0.9, 0.6, 0.3), 1.0, 0.3},
                             {Spec(0.2, 0.7, 0.4), 0.4, 0.8},
                             {Spec(0.01, 0.02, 0.03), 0.5, 0.1},
                             {Spec(1.0, 1.0, 1.0), 0.0, 1.0}};
    int checked = 0;
    for (const auto& p : params) {
        char json[256];
        std::snprintf(json, sizeof json,
                      R"({"type":"standard","base_color":[%.17g,%.17g,%.17g],)"
                      R"("metalness":%.17g,"roughness":%.17g})",
                      p.base[0], p.base[1], p.base[2], p.metalness, p.roughness);
        const auto bsdf = build(json);
        for (double thetaO : {0.0, 20.0, 45.0, 70.0, 88.0})
            for (double thetaI : {1.0, 30.0, 60.0, 85.0})
                for (double phi : {0.0, 60.0, 180.0}) {
                    const double to = thetaO * kPi<double> / 180, ti = thetaI * kPi<double> / 180,
                                 ph = phi * kPi<double> / 180;
                    const V3 wo(std::sin(to), 0.0, std::cos(to));
                    const V3 wi(std::sin(ti) * std::cos(ph), std::sin(ti) * std::sin(ph),
                                std::cos(ti));
                    const Spec ref = articleReference(wo, wi, p.base, p.metalness, p.roughness);
                    const Spec got = bsdf->eval(wo, wi, TransportMode::Radiance);
                    for (int c = 0; c < 3; ++c)
                        EXPECT_NEAR(got[c], ref[c], 1e-4 * std::abs(ref[c]) + 1e-12)
                            << json << " theta_o " << thetaO << " theta_i " << thetaI << " phi "
                            << phi;
                    ++checked;
                }
    }
    EXPECT_EQ(checked, 5 * 5 * 4 * 3);
}

TEST(StandardMaterial, PhongSpecularReproducesTheArticle) {
    // The article's Phong specular (F0 (s + 1) / (2 pi) max(0, R.V)^s N.L, s = 2 / alpha^2 - 2)
    // with Lambert diffuse weighted by 1 - F(L.H), Schlick with the shadowed F90.
    const double roughness = 0.6, alpha = roughness * roughness;
    const double s = 2.0 / std::clamp(alpha * alpha, 2e-4, 0.9999) - 2.0;
    const Spec base(0.7, 0.4, 0.2);
    const auto bsdf = build(R"({"type":"standard","base_color":[0.7,0.4,0.2],"roughness":0.6,)"
                            R"("specular_model":"phong"})");
    for (double thetaO : {0.0, 30.0, 70.0})
        for (double thetaI : {5.0, 35.0, 80.0}) {
            const double to = thetaO * kPi<double> / 180, ti = thetaI * kPi<double> / 180;
            const V3 v(std::sin(to), 0, std::cos(to)),
                l(-std::sin(ti) * 0.8, std::sin(ti) * 0.6, std::cos(ti));
            const V3 h = glm::normalize(v + l);
            const V3 r(-l.x, -l.y, l.z);  // L reflected about N
            const double f90 = std::min(1.0, 0.04 / 0.04);
            const double F = 0.04 + (f90 - 0.04) * std::pow(1 - glm::dot(l, h), 5.0);
            const double phong =
                0.04 * (s + 1) / (2 * kPi<double>)*std::pow(std::max(0.0, glm::dot(r, v)), s) * l.z;
            const Spec got = bsdf->eval(v, l, TransportMode::Radiance);
            for (int c = 0; c < 3; ++c) {
                const double ref = (1 - F) * base[c] / kPi<double> * l.z + phong;
                EXPECT_NEAR(got[c], ref, 1e-4 * ref) << thetaO << " " << thetaI;
            }
        }
}

TEST(LayeredMaterial, SpellsOutTheSameStackAsStandard) {
    // An interface of F0 0.04 over a Lambert base of the same colour is the article's default
    // standard material.
    const auto layered =
        build(R"({"type":"layered","interface":{"model":"ggx","roughness":0.5,"f0":0.04},)"
              R"("base":{"type":"lambert","reflectance":[0.8,0.5,0.2]}})");
    const auto standard =
        build(R"({"type":"standard","base_color":[0.8,0.5,0.2],"roughness":0.5})");
    const V3 wo = glm::normalize(V3(0.4, 0.1, 0.8)), wi = glm::normalize(V3(-0.3, 0.2, 0.6));
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(layered->eval(wo, wi, TransportMode::Radiance)[c],
                    standard->eval(wo, wi, TransportMode::Radiance)[c], 1e-12);
    // A base with its own roughness and no interface is that diffuse model alone.
    const auto base = build(
        R"({"type":"layered","base":{"type":"oren_nayar","reflectance":0.7,"roughness":0.9}})");
    const auto on = build(R"({"type":"oren_nayar","reflectance":0.7,"roughness":0.9})");
    EXPECT_NEAR(base->eval(wo, wi, TransportMode::Radiance)[0],
                on->eval(wo, wi, TransportMode::Radiance)[0], 1e-12);
}

TEST(StandardMaterial, FrostbiteDiffuseSumsWithSpecularByDefault) {
    const auto summed = build(R"({"type":"standard","diffuse_model":"frostbite"})");
    const auto explicitSum =
        build(R"({"type":"standard","diffuse_model":"frostbite","coupling":"sum"})");
    const auto weighted =
        build(R"({"type":"standard","diffuse_model":"frostbite","coupling":"fresnel"})");
    const V3 wo = glm::normalize(V3(0.6, 0.1, 0.5)), wi = glm::normalize(V3(-0.3, 0.2, 0.7));
    const Spec a = summed->eval(wo, wi, TransportMode::Radiance);
    const Spec b = explicitSum->eval(wo, wi, TransportMode::Radiance);
    const Spec c = weighted->eval(wo, wi, TransportMode::Radiance);
    EXPECT_DOUBLE_EQ(a[0], b[0]);
    EXPECT_GT(a[0], c[0]);  // (1 - F) < 1 removes energy from the diffuse term
}

TEST(ConductorMaterial, RgbModeF82MatchesExactFresnelAtItsTwoAngles) {
    // Auto Fresnel in RGB mode is Hoffman's F82 built from the exact reflectance per channel,
    // so it agrees with the exact conductor at normal incidence and at cos = 1/7.
    const auto f82 = build(R"({"type":"conductor","eta":[0.18,0.42,1.37],"k":[3.42,2.35,1.77]})");
    const auto exact = build(
        R"({"type":"conductor","eta":[0.18,0.42,1.37],"k":[3.42,2.35,1.77],"fresnel":"exact"})");
    for (double c : {1.0, kF82Cosine}) {
        const V3 wo(std::sqrt(1 - c * c), 0, c);
        const auto a = f82->sample(wo, 0.5, {0.5, 0.5}, TransportMode::Radiance);
        const auto b = exact->sample(wo, 0.5, {0.5, 0.5}, TransportMode::Radiance);
        ASSERT_TRUE(a && b);
        for (int ch = 0; ch < 3; ++ch)
            EXPECT_NEAR(a->weight[ch], b->weight[ch], 1e-9) << "cos " << c;
    }
}

TEST(MixMaterial, BlendsEvalAndPdfLinearly) {
    const auto mix =
        build(R"({"type":"mix","weight":0.25,"a":{"type":"lambert","reflectance":0.8},)"
              R"("b":{"type":"conductor","eta":1.5,"k":3,"roughness":0.5}})");
    const auto a = build(R"({"type":"lambert","reflectance":0.8})");
    const auto b = build(R"({"type":"conductor","eta":1.5,"k":3,"roughness":0.5})");
    const V3 wo = glm::normalize(V3(0.3, 0.1, 0.8)), wi = glm::normalize(V3(-0.4, 0.0, 0.7));
    const auto m = TransportMode::Radiance;
    EXPECT_NEAR(mix->eval(wo, wi, m)[1],
                0.75 * a->eval(wo, wi, m)[1] + 0.25 * b->eval(wo, wi, m)[1], 1e-12);
    EXPECT_NEAR(mix->pdf(wo, wi), 0.75 * a->pdf(wo, wi) + 0.25 * b->pdf(wo, wi), 1e-12);
}

void expectError(const std::string& json, const std::string& fragment) {
    try {
        build(json);
        FAIL() << "accepted " << json;
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), ::testing::HasSubstr(fragment)) << json;
    }
}

TEST(MaterialErrors, NameTheJsonPathAndWhatWasExpected) {
    expectError(R"({"type":"standard","roughness":-0.2})",
                "roughness: expected a number in [0, 1], got -0.2");
    expectError(R"({"type":"standard","roughness":"nan"})", "roughness: expected a number");
    expectError(R"({"type":"standard","rougness":0.2})", "rougness: unknown key");
    expectError(R"({"type":"plastic"})", "unknown material type \"plastic\"");
    expectError(R"({"roughness":0.2})", "type: missing");
    expectError(R"({"type":"dielectric","ior":0})", "ior: expected a number > 0, got 0");
    expectError(R"({"type":"dielectric","ior":-1.5})", "ior: expected a number > 0");
    expectError(R"({"type":"standard","base_color":[1,0.5]})", "base_color: expected a number or");
    expectError(R"({"type":"standard","base_color":[1,0.5,1e999]})", "number overflow");
    expectError(R"({"type":"standard","diffuse_model":"lamber"})",
                "diffuse_model: expected one of lambert, oren_nayar");
    expectError(R"({"type":"conductor","eta":1.5})", "k: missing");
    expectError(R"({"type":"conductor","eta":1.5,"k":3,"f0":0.9})", "exactly one of");
    expectError(R"({"type":"layered","interface":{"model":"cook"}})",
                "interface.model: expected one of");
    expectError(R"({"type":"layered"})", "needs an interface, a base or transmission");
    expectError(R"({"type":"mix","a":{"type":"lambert"},"b":{"type":"lambert","reflectance":2}})",
                "b.reflectance: expected a number in [0, 1], got 2");
    expectError(R"({"type":"coated"})", "base: missing");
    expectError(R"({"type":"coated","base":{"type":"dielectric"}})",
                "base: expected a material without transmission");
    expectError(R"({"type":"coated","base":{"type":"standard","transmission":0.5}})",
                "base: expected a material without transmission");
    expectError(R"({"type":"coated","g":1,"base":{"type":"lambert"}})",
                "g: expected a number in [-0.99, 0.99], got 1");
    expectError(R"({"type":"coated","samples":0,"base":{"type":"lambert"}})", "samples");
    expectError(R"({"type":"coated","base":{"type":"lambert","reflectance":[1,2,0]}})",
                "base.reflectance[1]: expected a number in [0, 1], got 2");
    expectError(R"({"type":"coated","thickness":1,"albedo":0.5,"base":{"type":"conductor",)"
                R"("f0":0.9}})",
                "base: a smooth coat over a base with a smooth (delta) lobe");
    expectError(R"({"type":"coated","base":{"type":"standard","roughness":0}})",
                "base: a smooth coat over a base with a smooth (delta) lobe");
    expectError(R"({"type":"standard", "roughness": 0.2,})", "malformed JSON at line 1");
    expectError(R"({"type":"standard","roughness":0.2,"alpha":0.1})", "only one of");
    expectError(R"({"type":"conductor","distribution":"beckmann","sampling":"caps","eta":1,"k":1})",
                "GGX only");
}

TEST(MaterialErrors, AMissingFileIsNamed) {
    expectError("@/nonexistent/material.json", "/nonexistent/material.json: cannot open file");
}

}  // namespace
}  // namespace lamina

namespace lamina {
namespace {

TEST(ConductorMaterial, NamedMetalIsExactInSpectralModeAndF82InRgbMode) {
    const MaterialDesc gold = parseMaterialArgument(R"({"type":"conductor","material":"Au"})");
    const Vec3<double> normal(0, 0, 1);
    // Spectral: the exact Fresnel reflectance of the measured gold at each wavelength.
    auto lambda = SampledWavelengths<double>::fixed({450, 550, 650, 700});
    const SpectrumContext<SampledSpectrum<double>> spectral{lambda};
    const auto s =
        buildBxdf(gold, spectral)->sample(normal, 0.5, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(s);
    const IorSpectrum au = *namedIor("Au");
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(s->weight[i], fresnelConductor(1.0, au.n(lambda[i]), au.k(lambda[i])), 1e-12);
    // RGB: the reductions of the same n, k, as reflectances in [0, 1] (measured gold's F0 is
    // outside the Rec.709 gamut: its red is 1.04).
    const SpectrumContext<Rgb<double>> rgb;
    const auto r = buildBxdf(gold, rgb)->sample(normal, 0.5, {0.5, 0.5}, TransportMode::Radiance);
    const auto [f0, f82] = conductorF0F82(au);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(r->weight[c], std::min(f0[c], 1.0), 1e-12);
    (void)f82;
}

TEST(ConductorMaterial, InlineSpectraOfEtaAndK) {
    const MaterialDesc m = parseMaterialArgument(
        R"({"type":"conductor","eta":[[400,1.4],[700,0.2]],"k":[[400,1.9],[700,4.0]]})");
    auto lambda = SampledWavelengths<double>::fixed({400, 550, 700, 700});
    const SpectrumContext<SampledSpectrum<double>> spectral{lambda};
    const auto s =
        buildBxdf(m, spectral)->sample({0, 0, 1}, 0.5, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->weight[0], fresnelConductor(1.0, 1.4, 1.9), 1e-12);
    EXPECT_NEAR(s->weight[1], fresnelConductor(1.0, 0.8, 2.95), 1e-12);  // linear in between
    expectError(R"({"type":"conductor","eta":[[400,1.4],[300,0.2]],"k":2})",
                "wavelengths must increase");
}

TEST(SpectralMaterials, ColoursCollectedInAdvanceGiveTheSameBsdf) {
    // Spectral mode collects each material's colours once at load (render_mode.h) and builds
    // it at every path from them: bit for bit the BSDF built from the table itself. One
    // material per kind of colour input the builder upsamples.
    const char* materials[] = {
        R"({"type":"lambert","reflectance":[0.35,0.35,0.38]})",
        R"({"type":"standard","base_color":[0.8,0.2,0.1],"roughness":0.3})",
        R"({"type":"standard","base_color":[0.95,0.64,0.54],"metalness":1,"roughness":0.2})",
        R"({"type":"standard","base_color":[0.9,0.6,0.2],"metalness":0.5,"fresnel":"f82",)"
        R"("f82_tint":[1.1,0.9,0.8],"roughness":0.4})",
        R"({"type":"conductor","f0":[0.9,0.6,0.3],"f82":[0.8,0.55,0.35],"roughness":0.3})",
        R"({"type":"conductor","eta":[0.2,0.4,1.3],"k":[3.9,2.4,1.8],"roughness":0.3})",
        R"({"type":"phong","reflectance":[0.6,0.3,0.2],"shininess":20})",
        R"({"type":"diffuse_transmission","reflectance":[0.3,0.2,0.1],)"
        R"("transmittance":[0.1,0.3,0.2]})",
        R"({"type":"coated","roughness":0.1,"thickness":0.2,"albedo":[0.9,0.8,0.6],)"
        R"("base":{"type":"lambert","reflectance":[0.2,0.5,0.3]}})",
        R"({"type":"mix","a":{"type":"lambert","reflectance":[0.7,0.1,0.1]},)"
        R"("b":{"type":"standard","base_color":[0.1,0.2,0.7]}})",
    };
    const Vec3<double> wo = normalize(Vec3<double>(0.3, -0.2, 0.8));
    const Vec3<double> wi = normalize(Vec3<double>(-0.4, 0.1, 0.7));
    for (const char* json : materials) {
        SCOPED_TRACE(json);
        const MaterialDesc m = parseMaterialArgument(json);
        auto any = SampledWavelengths<double>::fixed({500, 500, 500, 500});
        UpsampledColors colors;
        (void)buildBxdf(m, SpectrumContext<SampledSpectrum<double>>{any, nullptr, &colors});
        EXPECT_GT(colors.size(), 0u);
        auto lambda = SampledWavelengths<double>::fixed({412, 487, 561, 688});
        const auto fromTable = buildBxdf(m, SpectrumContext<SampledSpectrum<double>>{lambda});
        const auto collected =
            buildBxdf(m, SpectrumContext<SampledSpectrum<double>>{lambda, &colors});
        const SampledSpectrum<double> a = fromTable->eval(wo, wi, TransportMode::Radiance);
        const SampledSpectrum<double> b = collected->eval(wo, wi, TransportMode::Radiance);
        EXPECT_GT(a.maxValue(), 0.0);
        for (int i = 0; i < 4; ++i)
            EXPECT_EQ(a[i], b[i]) << i;
        const auto sa = fromTable->sample(wo, 0.3, {0.6, 0.2}, TransportMode::Radiance);
        const auto sb = collected->sample(wo, 0.3, {0.6, 0.2}, TransportMode::Radiance);
        ASSERT_EQ(sa.has_value(), sb.has_value());
        if (sa) {
            for (int i = 0; i < 4; ++i)
                EXPECT_EQ(sa->weight[i], sb->weight[i]) << i;
        }
    }
}

// A build records whether it read the path's wavelengths (spectrum_context.h): spectral mode
// shares the BSDF of a material whose build did not (render_mode.h). Grey colours and plain
// numbers read none, and then builds at two sets of wavelengths give the same eval, pdf and
// sample bit for bit; every colour, spectrum, index spectrum or n, k input reads them.
TEST(SpectralMaterials, BuildsThatReadNoWavelengthAreTheSameAtAnyWavelengths) {
    const std::pair<const char*, bool> materials[] = {
        {R"({"type":"lambert","reflectance":1})", false},
        {R"({"type":"lambert","reflectance":[0.4,0.4,0.4]})", false},
        {R"({"type":"conductor","f0":1,"roughness":1,"multiscatter":true})", false},
        {R"({"type":"standard","base_color":1,"roughness":0.3,"coupling":"albedo",)"
         R"("multiscatter":true})",
         false},
        {R"({"type":"standard","base_color":0.5,"metalness":0.5,"roughness":0.4})", false},
        {R"({"type":"conductor","eta":1.5,"k":3,"roughness":0.3})", false},
        {R"({"type":"dielectric","ior":1.5,"roughness":0.2})", false},
        {R"({"type":"coated","roughness":0.1,"thickness":0.2,"albedo":0.8,)"
         R"("base":{"type":"lambert","reflectance":0.5}})",
         false},
        {R"({"type":"mix","a":{"type":"lambert","reflectance":0.7},)"
         R"("b":{"type":"conductor","f0":0.9,"roughness":0.5}})",
         false},
        {R"({"type":"lambert","reflectance":[0.35,0.35,0.38]})", true},
        {R"({"type":"standard","base_color":[0.8,0.2,0.1],"roughness":0.3})", true},
        {R"({"type":"conductor","material":"Au","roughness":0.2})", true},
        {R"({"type":"conductor","eta":[0.2,0.4,1.3],"k":[3.9,2.4,1.8]})", true},
        {R"({"type":"dielectric","ior":"bk7"})", true},
        {R"({"type":"mix","a":{"type":"lambert","reflectance":0.7},)"
         R"("b":{"type":"lambert","reflectance":[0.1,0.2,0.7]}})",
         true},
    };
    const Vec3<double> wo = normalize(Vec3<double>(0.3, -0.2, 0.8));
    const Vec3<double> wi = normalize(Vec3<double>(-0.4, 0.1, 0.7));
    for (const auto& [json, reads] : materials) {
        SCOPED_TRACE(json);
        const MaterialDesc m = parseMaterialArgument(json);
        auto lambdaA = SampledWavelengths<double>::fixed({412, 487, 561, 688});
        auto lambdaB = SampledWavelengths<double>::fixed({371, 530, 602, 799});
        bool readA = false, readB = false;
        const auto a = buildBxdf(
            m, SpectrumContext<SampledSpectrum<double>>{lambdaA, nullptr, nullptr, &readA}, 3);
        const auto b = buildBxdf(
            m, SpectrumContext<SampledSpectrum<double>>{lambdaB, nullptr, nullptr, &readB}, 3);
        EXPECT_EQ(readA, reads);
        EXPECT_EQ(readB, reads);
        if (reads) continue;
        const SampledSpectrum<double> fa = a->eval(wo, wi, TransportMode::Radiance);
        const SampledSpectrum<double> fb = b->eval(wo, wi, TransportMode::Radiance);
        for (int i = 0; i < 4; ++i)
            EXPECT_EQ(fa[i], fb[i]) << i;
        EXPECT_EQ(a->pdf(wo, wi), b->pdf(wo, wi));
        for (const double u : {0.1, 0.5, 0.9}) {
            const auto sa = a->sample(wo, u, {0.6, 0.2}, TransportMode::Radiance);
            const auto sb = b->sample(wo, u, {0.6, 0.2}, TransportMode::Radiance);
            ASSERT_EQ(sa.has_value(), sb.has_value());
            if (!sa) continue;
            EXPECT_EQ(sa->wi, sb->wi);
            EXPECT_EQ(sa->pdf, sb->pdf);
            for (int i = 0; i < 4; ++i)
                EXPECT_EQ(sa->weight[i], sb->weight[i]) << i;
        }
    }
}

TEST(DielectricMaterial, DispersiveGlassKeepsOnlyTheHeroWavelength) {
    const MaterialDesc glass = parseMaterialArgument(R"({"type":"dielectric","ior":"bk7"})");
    auto lambda = SampledWavelengths<float>::fixed({450, 550, 650, 700});
    const SpectrumContext<SampledSpectrum<float>> spectral{lambda};
    (void)buildBxdf(glass, spectral);
    EXPECT_TRUE(lambda.secondaryTerminated());
    const MaterialDesc constant = parseMaterialArgument(R"({"type":"dielectric","ior":1.5})");
    auto lambda2 = SampledWavelengths<float>::fixed({450, 550, 650, 700});
    const SpectrumContext<SampledSpectrum<float>> spectral2{lambda2};
    (void)buildBxdf(constant, spectral2);
    EXPECT_FALSE(lambda2.secondaryTerminated());
}

TEST(DiffuseMaterial, ReflectanceSpectraInBothModes) {
    // A measured reflectance: spectral mode evaluates it at the path's wavelengths, RGB mode
    // uses its colour under D65 (a flat spectrum is grey).
    const MaterialDesc m = parseMaterialArgument(
        R"({"type":"lambert","reflectance":{"spectrum":[[400,0.1],[500,0.9],[700,0.5]]}})");
    auto lambda = SampledWavelengths<double>::fixed({400, 450, 600, 700});
    const SpectrumContext<SampledSpectrum<double>> spectral{lambda};
    const auto s =
        buildBxdf(m, spectral)->sample({0, 0, 1}, 0.5, {0.3, 0.3}, TransportMode::Radiance);
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->weight[0], 0.1, 1e-12);
    EXPECT_NEAR(s->weight[1], 0.5, 1e-12);
    EXPECT_NEAR(s->weight[2], 0.7, 1e-12);
    const MaterialDesc flat = parseMaterialArgument(
        R"({"type":"lambert","reflectance":{"spectrum":[[360,0.5],[830,0.5]]}})");
    const auto r = buildBxdf(flat, SpectrumContext<Rgb<double>>{})
                       ->sample({0, 0, 1}, 0.5, {0.3, 0.3}, TransportMode::Radiance);
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(r->weight[c], 0.5, 1e-6);
    expectError(R"({"type":"lambert","reflectance":{"spectrum":[[400,1.5],[500,0.2]]}})",
                "reflectance.spectrum[0][1]: expected a number in [0, 1], got 1.5");
}

TEST(DielectricMaterial, CauchyAndSellmeierFormulas) {
    // BK7 by its Sellmeier coefficients (SCHOTT) equals the named preset; Cauchy follows its
    // formula; both are dispersive.
    const auto sell = parseMaterialArgument(
        R"({"type":"dielectric","ior":{"sellmeier":{"b":[1.03961212,0.231792344,1.01046945],)"
        R"("c":[0.00600069867,0.0200179144,103.560653]}}})");
    const auto& d = sell.model.as<DielectricMaterial>();
    EXPECT_NEAR(d.ior, 1.5168, 1e-4);
    EXPECT_NEAR(d.spectrum->n(450), namedIor("bk7")->n(450), 1e-12);
    const auto cauchy =
        parseMaterialArgument(R"({"type":"dielectric","ior":{"cauchy":[1.5046,0.0042]}})");
    const auto& c = cauchy.model.as<DielectricMaterial>();
    EXPECT_NEAR(c.spectrum->n(500), 1.5046 + 0.0042 / 0.25, 1e-12);
    EXPECT_TRUE(c.spectrum->dispersive());
    expectError(R"({"type":"dielectric","ior":{"cauchy":[1.5]}})", "ior.cauchy: expected [A, B]");
    expectError(R"({"type":"dielectric","ior":{"sellmeier":{"b":[1],"c":[]}}})",
                "equal, non-zero length");
}

TEST(MaterialErrors, UnknownMetalsGlassesAndFilesAreNamed) {
    expectError(R"({"type":"conductor","material":"Unobtainium"})",
                "unknown metal \"Unobtainium\"; expected one of Ag, Al, Au");
    expectError(R"({"type":"dielectric","ior":"crown"})", "unknown glass \"crown\"");
    expectError(R"({"type":"conductor","nk_file":"no/such/file.yml"})",
                "nk_file: no/such/file.yml: no such file");
}

}  // namespace
}  // namespace lamina
