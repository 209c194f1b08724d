// Mitsuba 3's `principled`, `principledthin` and `pplastic` BSDFs imported (docs/interchange.md,
// "Mitsuba 3"): the exact lamina material and warnings for files written in the style of
// mitsuba-data, the refusals, and, where the translation is exact, the imported material's
// eval against a double-precision transcription of what mitsuba3 src/bsdfs/principled.cpp,
// principledthin.cpp and pplastic.cpp evaluate, at a grid of direction pairs.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lamina/bsdf/material.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/interchange/scene_import.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using Spec = Rgb<double>;
using V3 = Vec3<double>;

constexpr const char* kLight = "<emitter type=\"constant\"/>";

class MitsubaPrincipled : public lamina::testing::ScratchDirectoryTest {
  protected:
    // A file whose BSDF `bsdf` (from line 2) has id "m".
    ImportedScene import(const std::string& bsdf) {
        const auto file =
            write("scene.xml", "<scene version=\"3.0.0\">\n" + bsdf + kLight + "\n</scene>\n");
        return importScene(file, dir_);
    }
    Json material(const std::string& bsdf) { return import(bsdf).scene["materials"]["m"]; }
    std::string error(const std::string& bsdf) {
        const auto file =
            write("scene.xml", "<scene version=\"3.0.0\">\n" + bsdf + kLight + "\n</scene>\n");
        return lamina::testing::errorOf([&] { importScene(file, dir_); });
    }
    std::string where(int line) const {
        return (dir_ / "scene.xml").string() + ":" + std::to_string(line);
    }
    // The warnings about the BSDF (not the default camera and integrator, line 1).
    std::vector<std::string> bsdfWarnings(const ImportedScene& s) const {
        std::vector<std::string> out;
        for (const auto& w : s.warnings)
            if (w.find(where(1) + ":") == std::string::npos) out.push_back(w);
        return out;
    }
    // The warnings that name `text`.
    static std::vector<std::string> warningsWith(const ImportedScene& s, const std::string& text) {
        std::vector<std::string> out;
        for (const auto& w : s.warnings)
            if (w.find(text) != std::string::npos) out.push_back(w);
        return out;
    }
};

// ---- the documents -------------------------------------------------------------------------

// mitsuba-data docs/scenes/principled_blend_creation/scene.xml: base_color alone.
TEST_F(MitsubaPrincipled, PrincipledBecomesStandard) {
    const ImportedScene s = import(R"(<bsdf type="principled" id="m">
<rgb name="base_color" value="0.02, 0.02, 0.02"/></bsdf>)");
    // specular 0.5: eta = 2 / (1 - sqrt(0.04)) - 1 = 1.5.
    EXPECT_EQ(s.scene["materials"]["m"], Json::parse(R"({"type": "standard",
        "base_color": 0.02, "roughness": 0.5, "ior": 1.5, "fresnel": "exact",
        "diffuse_model": "burley", "coupling": "sum", "g2": "separable"})"));
    EXPECT_THAT(bsdfWarnings(s),
                ElementsAre(HasSubstr(where(2) + ": one-sided in Mitsuba (black seen from behind) "
                                                 "became lamina's standard")));
}

TEST_F(MitsubaPrincipled, MetallicAnisotropicAndTransmission) {
    const ImportedScene s = import(R"(<bsdf type="twosided" id="m"><bsdf type="principled">
<rgb name="base_color" value="0.9, 0.5, 0.2"/><float name="metallic" value="0.7"/>
<float name="specular" value="0.6"/><float name="roughness" value="0.2"/>
<float name="anisotropic" value="0.5"/><float name="spec_trans" value="0.4"/>
<float name="spec_tint" value="0.4"/><float name="sheen" value="0.3"/>
<float name="sheen_tint" value="0.2"/><float name="flatness" value="0.1"/>
<float name="main_specular_sampling_rate" value="2"/></bsdf></bsdf>)");
    const Json m = s.scene["materials"]["m"];
    EXPECT_EQ(m["type"], "standard");
    EXPECT_EQ(m["metalness"], 0.7);
    EXPECT_EQ(m["fresnel"], "schlick");
    EXPECT_EQ(m["anisotropy"], 0.5);
    EXPECT_NEAR(m["transmission"].get<double>(), 0.3 * 0.4, 1e-12);  // (1 - metallic) spec_trans
    EXPECT_DOUBLE_EQ(m["ior"].get<double>(), 2 / (1 - std::sqrt(0.08 * 0.6)) - 1);
    for (const char* w :
         {"metallic between 0 and 1", "anisotropic: the retro-reflection",
          "spec_trans became lamina's transmission through the same rough dielectric, untinted "
          "where Mitsuba tints it by sqrt(base_color), of weight (1 - metallic) spec_trans as in "
          "Mitsuba, but the diffuse term's is (1 - metallic)(1 - (1 - metallic) spec_trans) "
          "where Mitsuba's is (1 - metallic)(1 - spec_trans); seen from inside",
          "spec_tint is not supported: dropped", "sheen and sheen_tint are not supported: dropped",
          "flatness is not supported: dropped", "main_specular_sampling_rate became lamina's own"})
        EXPECT_EQ(warningsWith(s, w).size(), 1u) << w;
    EXPECT_EQ(bsdfWarnings(s).size(), 7u);
}

// Textures on base_color and roughness are lamina's (roughness taken as it is: the same
// alpha = roughness^2, and Texture::eval_1's swapped checkerboard colours).
TEST_F(MitsubaPrincipled, TexturedBaseColorAndRoughness) {
    const ImportedScene s = import(R"(<bsdf type="principled" id="m">
<texture name="base_color" type="checkerboard"><rgb name="color0" value="0.1, 0.2, 0.3"/></texture>
<texture name="roughness" type="checkerboard"><float name="color0" value="0.2"/>
<float name="color1" value="0.9"/></texture></bsdf>)");
    const Json m = s.scene["materials"]["m"];
    EXPECT_EQ(m["base_color"], Json::parse(R"j({"texture": "checkerboard (line 3)"})j"));
    EXPECT_EQ(m["roughness"],
              Json::parse(R"j({"texture": "checkerboard (line 4) as roughness"})j"));
    EXPECT_EQ(s.scene["textures"]["checkerboard (line 4) as roughness"],
              Json::parse(R"({"type": "checkerboard", "a": 0.9, "b": 0.2, "scale": [2, 2]})"));
}

// mitsuba-data tests/scenes/bsdf_spheres/test_texturedprincipled1_path.xml: a textured
// metallic (lamina's standard takes textures on base_color and roughness only).
TEST_F(MitsubaPrincipled, TexturedWeightsAreRefused) {
    EXPECT_EQ(error(R"(<bsdf type="principled" id="m">
<texture name="metallic" type="checkerboard"/></bsdf>)"),
              where(3) +
                  ": <bsdf type=\"principled\">: a textured metallic is not supported (lamina's "
                  "standard material takes textures on base_color and roughness only; give a "
                  "number)");
    EXPECT_THAT(error(R"(<bsdf type="principled" id="m"><float name="eta" value="1.3"/>
<float name="specular" value="0.3"/></bsdf>)"),
                HasSubstr(where(2) + ": <bsdf type=\"principled\">: give eta or specular"));
}

// Mitsuba weighs the transmission (1 - metallic) spec_trans: a metal with spec_trans is opaque.
TEST_F(MitsubaPrincipled, MetalWithSpecTransStaysOpaque) {
    const ImportedScene s = import(R"(<bsdf type="principled" id="m">
<float name="metallic" value="1"/><float name="spec_trans" value="1"/></bsdf>)");
    EXPECT_FALSE(s.scene["materials"]["m"].contains("transmission"));
    EXPECT_EQ(warningsWith(s, "one-sided in Mitsuba").size(), 1u);
    EXPECT_TRUE(warningsWith(s, "spec_trans").empty());
}

// clearcoat: a mix of 0.25 clearcoat with the material under a clear coat of index 1.5 and
// alpha lerp(0.1, 0.001, clearcoat_gloss).
TEST_F(MitsubaPrincipled, ClearcoatBecomesAMixWithACoatedTwin) {
    const ImportedScene s = import(R"(<bsdf type="twosided" id="m"><bsdf type="principled">
<float name="clearcoat" value="0.6"/><float name="clearcoat_gloss" value="0.5"/>
<float name="metallic" value="1"/></bsdf></bsdf>)");
    const Json base = Json::parse(R"({"type": "standard", "base_color": 0.5, "roughness": 0.5,
        "ior": 1.5, "fresnel": "schlick", "metalness": 1, "diffuse_model": "burley",
        "coupling": "sum", "g2": "separable"})");
    const Json m = s.scene["materials"]["m"];
    EXPECT_EQ(m["type"], "mix");
    EXPECT_EQ(m["a"], base);
    EXPECT_EQ(m["b"]["base"], base);
    EXPECT_EQ(m["b"]["ior"], 1.5);
    EXPECT_NEAR(m["b"]["alpha"].get<double>(), 0.0505, 1e-12);
    EXPECT_NEAR(m["weight"].get<double>(), 0.15, 1e-12);
    EXPECT_EQ(warningsWith(s, "clearcoat became a mix of weight 0.25 clearcoat").size(), 1u);
    EXPECT_EQ(bsdfWarnings(s).size(), 1u);
}

// mitsuba-data docs/scenes/principled_blend_creation/scene_thin.xml: Burley's diffuse alone.
TEST_F(MitsubaPrincipled, PrincipledThinBecomesBurley) {
    const ImportedScene s = import(R"(<bsdf type="principledthin" id="m">
<rgb name="base_color" value="1.0,1.0,1.0"/></bsdf>)");
    EXPECT_EQ(s.scene["materials"]["m"],
              Json::parse(R"({"type": "burley", "reflectance": 1, "roughness": 0.5})"));
    EXPECT_TRUE(bsdfWarnings(s).empty());
    EXPECT_EQ(material(R"(<bsdf type="principledthin" id="m"><float name="diff_trans" value="0.5"/>
<float name="roughness" value="0.3"/></bsdf>)"),
              Json::parse(R"({"type": "mix", "weight": 0.25,
        "a": {"type": "burley", "reflectance": 0.5, "roughness": 0.3},
        "b": {"type": "diffuse_transmission", "reflectance": 0, "transmittance": 0.5}})"));
    EXPECT_EQ(error(R"(<bsdf type="principledthin" id="m">
<float name="spec_trans" value="0.2"/></bsdf>)"),
              where(2) +
                  ": <bsdf type=\"principledthin\">: spec_trans above 0 is not supported on "
                  "principledthin (a rough, tinted thin transmitting sheet; lamina's "
                  "thin_dielectric is smooth and untinted): use thindielectric, or principled on "
                  "a closed shape");
}

// mitsuba-data docs/scenes/bsdf_pplastic.xml and bsdf_pplastic_specular.xml.
TEST_F(MitsubaPrincipled, PolarisedPlasticBecomesLayered) {
    const ImportedScene s = import(R"(<bsdf type="pplastic" id="m">
<rgb name="diffuse_reflectance" value="0.05, 0.03, 0.1"/><float name="alpha" value="0.06"/>
</bsdf>)");
    EXPECT_EQ(s.scene["materials"]["m"], Json::parse(R"({"type": "layered",
        "interface": {"model": "beckmann", "alpha": 0.06, "ior": )" +
                                                     Json(1.49 / 1.000277).dump() +
                                                     R"(,
                      "fresnel": "exact", "g2": "separable"},
        "base": {"type": "lambert", "reflectance": [0.05, 0.03, 0.1]}, "coupling": "albedo"})"));
    EXPECT_EQ(warningsWith(s, "pplastic became lamina's layered").size(), 1u);
    EXPECT_EQ(warningsWith(s, "one-sided in Mitsuba").size(), 1u);
    // No diffuse term: the rough reflection alone, the same in every mode.
    const ImportedScene specular = import(R"(<bsdf type="twosided" id="m"><bsdf type="pplastic">
<rgb name="diffuse_reflectance" value="0"/><float name="eta" value="1.5"/>
<string name="distribution" value="ggx"/></bsdf></bsdf>)");
    EXPECT_EQ(specular.scene["materials"]["m"], Json::parse(R"({"type": "layered",
        "interface": {"model": "ggx", "alpha": 0.1, "ior": 1.5, "fresnel": "exact",
                      "g2": "separable"}})"));
    EXPECT_TRUE(bsdfWarnings(specular).empty());
    // bsdf_pplastic_diffuse.xml: the diffuse component alone has no lamina counterpart.
    EXPECT_EQ(error(R"(<bsdf type="pplastic" id="m">
<rgb name="specular_reflectance" value="0"/></bsdf>)"),
              where(2) +
                  ": <bsdf type=\"pplastic\">: parameter \"specular_reflectance\" other than 1 "
                  "is not supported");
}

// ---- the imported materials evaluate as Mitsuba's ------------------------------------------

double schlickWeight(double c) {
    return std::pow(1 - c, 5.0);
}

// The exact Fresnel reflectance of a dielectric interface of relative index eta, seen at
// cos c from outside (Born and Wolf's unpolarised form).
double dielectricFresnel(double c, double eta) {
    const double g2 = eta * eta - 1 + c * c;
    if (g2 < 0) return 1;
    const double g = std::sqrt(g2);
    return 0.5 * std::pow((g - c) / (g + c), 2) *
           (1 + std::pow((c * (g + c) - 1) / (c * (g - c) + 1), 2));
}

struct Principled {
    Spec baseColor{0.5};
    double roughness = 0.5, anisotropic = 0, metallic = 0, eta = 1.5;
};

// principled.cpp's eval without spec_trans, sheen, clearcoat and flatness (v the viewer's
// direction, Mitsuba's si.wi; l the light's, its wo; both above the surface): F D G / (4 cos_v)
// with F = (1 - metallic) F_dielectric + metallic Schlick(base_color), anisotropic GGX and the
// separable Smith G, plus (1 - metallic) base_color / pi (f_diff + f_retro) cos_l.
Spec mitsubaPrincipled(const Principled& p, const V3& v, const V3& l) {
    const double aspect = std::sqrt(1 - 0.9 * p.anisotropic), r2 = p.roughness * p.roughness;
    const double ax = std::max(0.001, r2 / aspect), ay = std::max(0.001, r2 * aspect);
    const V3 h = glm::normalize(v + l);
    const double D = 1 / (kPi<double> * ax * ay * sqr(sqr(h.x / ax) + sqr(h.y / ay) + sqr(h.z)));
    const auto g1 = [&](const V3& w) {
        const double t2 = (sqr(ax * w.x) + sqr(ay * w.y)) / sqr(w.z);
        return 2 / (1 + std::sqrt(1 + t2));
    };
    const double vh = glm::dot(v, h);
    const Spec schlick = p.baseColor + (Spec(1) - p.baseColor) * schlickWeight(vh);
    const Spec F = Spec((1 - p.metallic) * dielectricFresnel(vh, p.eta)) + schlick * p.metallic;
    const Spec specular = F * (D * g1(v) * g1(l) / (4 * v.z));
    const double Fo = schlickWeight(l.z), Fi = schlickWeight(v.z);
    const double rr = 2 * p.roughness * sqr(glm::dot(h, l));
    const double shape = (1 - 0.5 * Fi) * (1 - 0.5 * Fo) + rr * (Fo + Fi + Fo * Fi * (rr - 1));
    return specular + p.baseColor * ((1 - p.metallic) * kInvPi<double> * shape * l.z);
}

std::unique_ptr<Bxdf<Spec>> build(const Json& material) {
    static const SpectrumContext<Spec> context;
    return buildBxdf(parseMaterialArgument(material.dump()), context);
}

// Direction pairs over the upper hemisphere, azimuths apart so anisotropy shows.
std::vector<std::pair<V3, V3>> directionPairs() {
    std::vector<std::pair<V3, V3>> out;
    const auto dir = [](double theta, double phi) {
        return V3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                  std::cos(theta));
    };
    for (double tv : {0.1, 0.6, 1.1, 1.45})
        for (double tl : {0.05, 0.5, 0.9, 1.35})
            for (double phi : {0.0, 0.7, 2.0, 3.1})
                out.push_back({dir(tv, 0.3), dir(tl, 0.3 + phi)});
    return out;
}

TEST_F(MitsubaPrincipled, ImportedPrincipledEvaluatesAsMitsubas) {
    struct Case {
        const char* xml;
        Principled p;
    };
    const Case cases[] = {
        {R"(<rgb name="base_color" value="0.8, 0.4, 0.1"/><float name="roughness" value="0.3"/>)",
         {Spec(0.8, 0.4, 0.1), 0.3, 0, 0, 1.5}},
        {R"(<rgb name="base_color" value="0.9, 0.6, 0.3"/><float name="metallic" value="1"/>
<float name="roughness" value="0.4"/><float name="anisotropic" value="0.6"/>)",
         {Spec(0.9, 0.6, 0.3), 0.4, 0.6, 1, 1.5}},
        {R"(<float name="eta" value="1.33"/><float name="roughness" value="0.8"/>)",
         {Spec(0.5), 0.8, 0, 0, 1.33}},
    };
    for (const Case& c : cases) {
        const Json m =
            material("<bsdf type=\"principled\" id=\"m\">" + std::string(c.xml) + "</bsdf>");
        const auto bsdf = build(m);
        for (const auto& [v, l] : directionPairs()) {
            const Spec got = bsdf->eval(v, l, TransportMode::Radiance);
            const Spec want = mitsubaPrincipled(c.p, v, l);
            for (int i = 0; i < 3; ++i)
                EXPECT_NEAR(got[i], want[i], 1e-9 * std::max(1.0, want[i]))
                    << m.dump() << " v " << v.z << " l " << l.z << " channel " << i;
        }
    }
}

// principled.cpp's transmission at spec_trans 1, metallic 0 and a white base_color (no tint),
// seen from either side: (1 - F) D G |v.h| |l.h| / (|cos_v| (v.h + eta' l.h)^2) in radiance
// mode, eta' the index ratio across the boundary as the path crosses it. (Seen from inside,
// the reflection differs: lamina's standard reflects with the outside's Fresnel, without total
// internal reflection, where Mitsuba takes the inside's; the import warns.)
TEST_F(MitsubaPrincipled, ImportedTransmittingPrincipledEvaluatesAsMitsubas) {
    const double roughness = 0.5, alpha = roughness * roughness, eta = 1.5;
    const Json m = material(R"(<bsdf type="principled" id="m"><rgb name="base_color" value="1"/>
<float name="spec_trans" value="1"/><float name="roughness" value="0.5"/></bsdf>)");
    EXPECT_EQ(m["transmission"], 1.0);
    const auto bsdf = build(m);
    const auto D = [&](const V3& h) {
        return 1 /
               (kPi<double> * alpha * alpha * sqr(sqr(h.x / alpha) + sqr(h.y / alpha) + sqr(h.z)));
    };
    // Smith's G1 of GGX, 0 where w sees the back of the microfacet h.
    const auto g1 = [&](const V3& w, const V3& h) {
        if (glm::dot(w, h) * w.z <= 0) return 0.0;
        return 2 / (1 + std::sqrt(1 + sqr(alpha) * (sqr(w.x) + sqr(w.y)) / sqr(w.z)));
    };
    // Fresnel at cos c of the microfacet normal: from inside (c < 0) the index inverts.
    const auto F = [&](double c) {
        return c >= 0 ? dielectricFresnel(c, eta) : dielectricFresnel(-c, 1 / eta);
    };
    int compared = 0;
    for (const auto& [up, other] : directionPairs())
        for (const bool inside : {false, true}) {
            const V3 v = inside ? V3(up.x, up.y, -up.z) : up;
            const V3 l = inside ? other : V3(other.x, other.y, -other.z);
            const double etaPath = inside ? 1 / eta : eta;
            V3 h = glm::normalize(v + l * etaPath);
            if (h.z < 0) h = -h;
            const double vh = glm::dot(v, h), lh = glm::dot(l, h);
            double want = (1 - F(vh)) * D(h) * g1(v, h) * g1(l, h) *
                          std::abs(vh * lh / (v.z * sqr(vh + etaPath * lh)));
            if (vh * lh >= 0) want = 0;  // not a refraction through h
            const Spec got = bsdf->eval(v, l, TransportMode::Radiance);
            EXPECT_NEAR(got[0], want, 1e-9 * std::max(1.0, want))
                << "inside " << inside << " v " << v.z << " l " << l.z;
            compared += want > 0;
        }
    EXPECT_GE(compared, 40);
}

// principledthin.cpp at spec_trans 0: (1 - diff_trans / 2) Burley's diffuse reflection and
// diff_trans / 2 base_color / pi |cos_l| on the other side.
TEST_F(MitsubaPrincipled, ImportedPrincipledThinEvaluatesAsMitsubas) {
    const Json m = material(R"(<bsdf type="principledthin" id="m">
<rgb name="base_color" value="0.7, 0.3, 0.2"/><float name="roughness" value="0.35"/>
<float name="diff_trans" value="0.6"/></bsdf>)");
    const auto bsdf = build(m);
    const Spec bc(0.7, 0.3, 0.2);
    const double dt = 0.3;
    for (const auto& [v, l] : directionPairs()) {
        const double Fo = schlickWeight(l.z), Fi = schlickWeight(v.z);
        const double rr = 2 * 0.35 * sqr(glm::dot(glm::normalize(v + l), l));
        const double shape = (1 - 0.5 * Fi) * (1 - 0.5 * Fo) + rr * (Fo + Fi + Fo * Fi * (rr - 1));
        const Spec reflected = bc * ((1 - dt) * kInvPi<double> * shape * l.z);
        const Spec transmitted = bc * (dt * kInvPi<double> * l.z);
        const V3 below(l.x, l.y, -l.z);
        const Spec gotR = bsdf->eval(v, l, TransportMode::Radiance);
        const Spec gotT = bsdf->eval(v, below, TransportMode::Radiance);
        for (int i = 0; i < 3; ++i) {
            EXPECT_NEAR(gotR[i], reflected[i], 1e-9);
            EXPECT_NEAR(gotT[i], transmitted[i], 1e-9);
        }
    }
}

// pplastic.cpp's specular component (diffuse_reflectance 0): F D G / (4 cos_v) with the exact
// Fresnel and Beckmann's D; Mitsuba's G1 is a rational fit to Beckmann's Smith G1 (within 0.35%,
// its comment says), lamina's is exact, so the pair agrees to 0.7%.
TEST_F(MitsubaPrincipled, ImportedSpecularPolarisedPlasticEvaluatesAsMitsubas) {
    const double alpha = 0.3, eta = 1.5;
    const Json m = material(R"(<bsdf type="twosided" id="m"><bsdf type="pplastic">
<rgb name="diffuse_reflectance" value="0"/><float name="eta" value="1.5"/>
<float name="alpha" value="0.3"/></bsdf></bsdf>)");
    const auto bsdf = build(m);
    for (const auto& [v, l] : directionPairs()) {
        const V3 h = glm::normalize(v + l);
        const double tan2 = (sqr(h.x) + sqr(h.y)) / sqr(h.z);
        const double D =
            std::exp(-tan2 / sqr(alpha)) / (kPi<double> * sqr(alpha) * std::pow(h.z, 4.0));
        const auto g1 = [&](const V3& w) {
            const double a = w.z / (alpha * std::sqrt(1 - sqr(w.z)));
            if (a >= 1.6) return 1.0;
            return (3.535 * a + 2.181 * a * a) / (1 + 2.276 * a + 2.577 * a * a);
        };
        const double want = dielectricFresnel(glm::dot(v, h), eta) * D * g1(v) * g1(l) / (4 * v.z);
        const Spec got = bsdf->eval(v, l, TransportMode::Radiance);
        EXPECT_NEAR(got[0], want, 7e-3 * want + 1e-12) << "v " << v.z << " l " << l.z;
    }
}

// pplastic.cpp's diffuse term, (1 - F(theta_v))(1 - F(theta_l)) rho / pi cos_l, against the
// imported layered's albedo coupling away from the specular peak (alpha 0.06): what the import's
// warning says, about 1 / (1 - E_avg) brighter (1.10 for eta 1.5), the same shape: measured
// 1.097 to 1.098 over the pairs with viewing and lighting angles up to 60 degrees.
TEST_F(MitsubaPrincipled, ImportedPolarisedPlasticDiffuseIsAboutATenthBrighter) {
    const double rho = 0.5, eta = 1.5;
    const Json m = material(R"(<bsdf type="twosided" id="m"><bsdf type="pplastic">
<rgb name="diffuse_reflectance" value="0.5"/><float name="eta" value="1.5"/>
<float name="alpha" value="0.06"/></bsdf></bsdf>)");
    const auto bsdf = build(m);
    int compared = 0;
    double lowest = 1e9, highest = 0;
    for (const auto& [v, l] : directionPairs()) {
        if (v.z < 0.5 || l.z < 0.5) continue;
        const V3 mirror(-v.x, -v.y, v.z);
        if (glm::dot(mirror, l) > 0.9) continue;  // the specular peak
        const double mitsuba = (1 - dielectricFresnel(v.z, eta)) *
                               (1 - dielectricFresnel(l.z, eta)) * rho * kInvPi<double> * l.z;
        const double ratio = bsdf->eval(v, l, TransportMode::Radiance)[0] / mitsuba;
        EXPECT_GE(ratio, 1.08) << "v " << v.z << " l " << l.z;
        EXPECT_LE(ratio, 1.12) << "v " << v.z << " l " << l.z;
        lowest = std::min(lowest, ratio);
        highest = std::max(highest, ratio);
        ++compared;
    }
    std::printf("  %d pairs: lamina / Mitsuba from %.4f to %.4f\n", compared, lowest, highest);
    EXPECT_GE(compared, 10);
}

}  // namespace
}  // namespace lamina::render
