// A catalogue of BSDF configurations shared by the statistical BSDF tests: every lobe and
// layered combination, across roughness, NDF, sampling method and Fresnel model. BSDFs made
// only of delta lobes (smooth dielectric, thin_dielectric, smooth conductors) have no density
// for these tests to check: bsdf_extremes_test.cpp, energy_test.cpp and their own tests
// (bsdf_properties_test.cpp, material_test.cpp) cover them.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <ostream>
#include <string>
#include <vector>

#include "lamina/bsdf/conductor.h"
#include "lamina/bsdf/dielectric.h"
#include "lamina/bsdf/diffuse.h"
#include "lamina/bsdf/diffuse_transmission.h"
#include "lamina/bsdf/hair.h"
#include "lamina/bsdf/layered.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/measured.h"
#include "rgl_file_writer.h"

namespace lamina::testing {

using Spec = Rgb<double>;

/// A case's BSDF, built when a test first dereferences it. gtest enumerates the catalogue in
/// every test process, and CTest starts one process per test: a material with energy
/// compensation computes its albedo tables when it is built, and building all of them up front
/// cost every one of those processes about 0.8 s.
class LazyBxdf {
  public:
    using Make = std::function<std::shared_ptr<const Bxdf<Spec>>()>;

    template <class B>
    LazyBxdf(std::shared_ptr<B> built)
        : LazyBxdf(Make([b = std::shared_ptr<const Bxdf<Spec>>(std::move(built))] { return b; })) {}
    explicit LazyBxdf(Make make) : state_(std::make_shared<State>()) {
        state_->make = std::move(make);
    }

    const Bxdf<Spec>& operator*() const {
        std::call_once(state_->once, [s = state_.get()] { s->bxdf = s->make(); });
        return *state_->bxdf;
    }

  private:
    struct State {
        std::once_flag once;
        Make make;
        std::shared_ptr<const Bxdf<Spec>> bxdf;
    };
    std::shared_ptr<State> state_;  ///< shared by the copies gtest makes of a case
};

struct BsdfCase {
    std::string name;
    LazyBxdf bxdf;
    bool transmissive = false;
    double eta = 1.0;  ///< relative index of the transmissive boundary (inside / outside)
    /// Whether f(wo, wi) = f(wi, wo) holds (measured data need not: measured.h).
    bool reciprocal = true;
};

inline void PrintTo(const BsdfCase& c, std::ostream* os) {
    *os << c.name;
}

inline std::string alphaName(double a) {
    std::string s = std::to_string(a);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    for (char& c : s)
        if (c == '.') c = 'p';
    return s;
}

/// Gold-like conductor optics at three wavelengths (n, k at ~650, 550, 450 nm).
inline Fresnel<Spec> goldFresnel() {
    return Fresnel<Spec>::conductor(Spec(0.18, 0.42, 1.37), Spec(3.42, 2.35, 1.77));
}

/// The material of a JSON description (docs/bsdf.md), built on first use.
inline LazyBxdf lazyMaterial(const std::string& json) {
    return LazyBxdf([json] {
        return std::shared_ptr<const Bxdf<Spec>>(
            buildBxdf(parseMaterialArgument(json), SpectrumContext<Spec>{}));
    });
}

inline std::vector<BsdfCase> bsdfCases() {
    std::vector<BsdfCase> cases;
    const Spec albedo(0.8, 0.5, 0.3);
    for (const auto& [model, name] : kDiffuseModelNames.entries())
        cases.push_back(
            {std::string(name), std::make_shared<DiffuseBxdf<Spec>>(albedo, model, 0.7)});
    // Diffuse transmission (no index: eta 1), with coloured and unequal reflectance and
    // transmittance so that both lobe choices and their weights are exercised.
    cases.push_back(
        {"diffuse_transmission",
         std::make_shared<DiffuseTransmissionBxdf<Spec>>(Spec(0.6, 0.3, 0.1), Spec(0.2, 0.5, 0.4)),
         true, 1.0});
    cases.push_back({"diffuse_transmission_reflection_only",
                     std::make_shared<DiffuseTransmissionBxdf<Spec>>(Spec(0.5), Spec(0.0)), true,
                     1.0});

    // Conductors: GGX over alpha and sampling methods, Beckmann, Blinn-Phong, anisotropic.
    for (double alpha : {0.05, 0.2, 0.5, 1.0})
        for (auto s : {MicrofacetSampling::VisibleNormals, MicrofacetSampling::SphericalCaps,
                       MicrofacetSampling::Walter, MicrofacetSampling::WalterWidened})
            cases.push_back({std::string("conductor_ggx_") +
                                 std::string(kMicrofacetSamplingNames.name(s)) + "_a" +
                                 alphaName(alpha),
                             std::make_shared<ConductorBxdf<Spec>>(MicrofacetReflectionLobe<Spec>(
                                 MicrofacetDistribution<double>(NdfKind::Ggx, alpha, alpha),
                                 goldFresnel(), s))});
    for (double alpha : {0.05, 0.2, 0.5, 1.0})
        for (auto s : {MicrofacetSampling::VisibleNormals, MicrofacetSampling::Walter})
            cases.push_back({std::string("conductor_beckmann_") +
                                 std::string(kMicrofacetSamplingNames.name(s)) + "_a" +
                                 alphaName(alpha),
                             std::make_shared<ConductorBxdf<Spec>>(MicrofacetReflectionLobe<Spec>(
                                 MicrofacetDistribution<double>(NdfKind::Beckmann, alpha, alpha),
                                 goldFresnel(), s))});
    cases.push_back({"conductor_blinn_phong_a0p3",
                     std::make_shared<ConductorBxdf<Spec>>(MicrofacetReflectionLobe<Spec>(
                         MicrofacetDistribution<double>(NdfKind::BlinnPhong, 0.3, 0.3),
                         Fresnel<Spec>::schlick(Spec(0.9, 0.6, 0.3))))});
    cases.push_back({"conductor_ggx_anisotropic_vndf",
                     std::make_shared<ConductorBxdf<Spec>>(MicrofacetReflectionLobe<Spec>(
                         MicrofacetDistribution<double>(NdfKind::Ggx, 0.1, 0.5), goldFresnel()))});
    cases.push_back({"conductor_ggx_anisotropic_walter",
                     std::make_shared<ConductorBxdf<Spec>>(MicrofacetReflectionLobe<Spec>(
                         MicrofacetDistribution<double>(NdfKind::Ggx, 0.5, 0.1), goldFresnel(),
                         MicrofacetSampling::Walter))});
    cases.push_back(
        {"conductor_beckmann_anisotropic_vndf",
         std::make_shared<ConductorBxdf<Spec>>(MicrofacetReflectionLobe<Spec>(
             MicrofacetDistribution<double>(NdfKind::Beckmann, 0.15, 0.6), goldFresnel()))});

    // Rough dielectrics, entering and leaving (eta < 1 seen from the other side: TIR).
    for (double alpha : {0.05, 0.2, 0.5, 1.0})
        for (double eta : {1.5, 1.0 / 1.5})
            cases.push_back({std::string("dielectric_ggx_a") + alphaName(alpha) +
                                 (eta > 1 ? "_eta1p5" : "_eta0p67"),
                             std::make_shared<DielectricBxdf<Spec>>(
                                 eta, MicrofacetDistribution<double>(NdfKind::Ggx, alpha, alpha)),
                             true, eta});
    cases.push_back({"dielectric_beckmann_a0p3",
                     std::make_shared<DielectricBxdf<Spec>>(
                         1.33, MicrofacetDistribution<double>(NdfKind::Beckmann, 0.3, 0.3)),
                     true, 1.33});
    // Thin films (RGB mode: Belcour and Barla's closed form) on a rough dielectric (entered and
    // left: the "_below" cases) and a rough conductor. Two cases only: a film costs the
    // chi-square test's millions of pdf calls some 5 times the bare interface's time.
    cases.push_back({"dielectric_thin_film_a0p3_eta1p5",
                     lazyMaterial(R"({"type":"dielectric","ior":1.5,"alpha":0.3,)"
                                  R"("thin_film":{"thickness_nm":350,"ior":1.38}})"),
                     true, 1.5});
    cases.push_back({"conductor_thin_film_a0p3",
                     lazyMaterial(R"({"type":"conductor","eta":[0.18,0.42,1.37],)"
                                  R"("k":[3.42,2.35,1.77],"alpha":0.3,)"
                                  R"("thin_film":{"thickness_nm":300,"ior":2.0}})")});

    // Layered: the article's default (GGX + Lambert, shadowed Schlick, fresnel coupling),
    // sum coupling with Frostbite, and a transmissive stack.
    auto layered = [&](double alpha, DiffuseModel dm, LayerCoupling c, double t, FresnelKind fk) {
        typename LayeredBxdf<Spec>::Layers l;
        const Fresnel<Spec> f = fk == FresnelKind::ExactDielectric
                                    ? Fresnel<Spec>::dielectric(Spec(1.5))
                                    : Fresnel<Spec>::schlickShadowed(Spec(0.04), Spec(1.0));
        const MicrofacetDistribution<double> d(NdfKind::Ggx, alpha, alpha);
        l.interface.emplace(d, f);
        l.diffuse.emplace(albedo, dm, std::sqrt(alpha));
        if (t > 0) l.transmission.emplace(1.5, d);
        l.transmissionWeight = t;
        l.coupling = c;
        return std::make_shared<LayeredBxdf<Spec>>(l);
    };
    for (double alpha : {0.05, 0.2, 0.5, 1.0}) {
        cases.push_back({"layered_article_a" + alphaName(alpha),
                         layered(alpha, DiffuseModel::Lambert, LayerCoupling::Fresnel, 0.0,
                                 FresnelKind::SchlickShadowed)});
        cases.push_back({"layered_transmission_a" + alphaName(alpha),
                         layered(alpha, DiffuseModel::Lambert, LayerCoupling::Fresnel, 0.6,
                                 FresnelKind::ExactDielectric),
                         true, 1.5});
    }
    cases.push_back(
        {"layered_frostbite_sum", layered(0.3, DiffuseModel::Frostbite, LayerCoupling::Sum, 0.0,
                                          FresnelKind::SchlickShadowed)});
    cases.push_back({"layered_schlick_transmission",
                     layered(0.3, DiffuseModel::OrenNayar, LayerCoupling::Fresnel, 0.5,
                             FresnelKind::SchlickShadowed),
                     true, 1.5});

    // Layered over a rough conductor seen through the interface (refracted_conductor.h): the
    // fresnel and sum couplings, rough and smooth interfaces, GGX and anisotropic Beckmann bases.
    auto overConductor = [&](double interfaceAlpha, const MicrofacetDistribution<double>& base,
                             const Fresnel<Spec>& baseFresnel, LayerCoupling c, double eta) {
        typename LayeredBxdf<Spec>::Layers l;
        l.interface.emplace(
            MicrofacetDistribution<double>(NdfKind::Ggx, interfaceAlpha, interfaceAlpha),
            Fresnel<Spec>::dielectric(Spec(eta)));
        l.conductorBase.emplace(
            ConductorBxdf<Spec>(MicrofacetReflectionLobe<Spec>(base, baseFresnel)), eta);
        l.coupling = c;
        return std::make_shared<LayeredBxdf<Spec>>(l);
    };
    for (double alpha : {0.05, 0.3})
        cases.push_back(
            {"layered_conductor_fresnel_a" + alphaName(alpha),
             overConductor(0.1, MicrofacetDistribution<double>(NdfKind::Ggx, alpha, alpha),
                           goldFresnel(), LayerCoupling::Fresnel, 1.5)});
    cases.push_back(
        {"layered_conductor_sum_beckmann_anisotropic",
         overConductor(0.3, MicrofacetDistribution<double>(NdfKind::Beckmann, 0.15, 0.5),
                       Fresnel<Spec>::schlick(Spec(0.9, 0.6, 0.3)), LayerCoupling::Sum, 1.33)});
    cases.push_back({"layered_conductor_smooth_interface",
                     overConductor(0.0, MicrofacetDistribution<double>(NdfKind::Ggx, 0.2, 0.2),
                                   goldFresnel(), LayerCoupling::Fresnel, 1.5)});

    // Energy-compensated materials: Kulla-Conty multiple scattering and the albedo coupling.
    cases.push_back(
        {"layered_conductor_albedo_gold",
         lazyMaterial(R"({"type":"layered","interface":{"roughness":0.15,"ior":1.5,)"
                      R"("fresnel":"exact"},"base":{"type":"conductor","eta":[0.18,0.42,1.37],)"
                      R"("k":[3.42,2.35,1.77],"roughness":0.3},"coupling":"albedo"})")});
    cases.push_back(
        {"layered_conductor_albedo_multiscatter",
         lazyMaterial(R"({"type":"layered","interface":{"roughness":0.6,"ior":1.5,)"
                      R"("fresnel":"exact","multiscatter":true},"base":{"type":"conductor",)"
                      R"("f0":[0.9,0.6,0.3],"roughness":0.7,"multiscatter":true},)"
                      R"("coupling":"albedo"})")});
    cases.push_back({"conductor_multiscatter_r0p3",
                     lazyMaterial(R"({"type":"conductor","eta":[0.2,0.4,1.4],"k":[3.4,2.4,1.8],)"
                                  R"("fresnel":"exact","roughness":0.3,"multiscatter":true})")});
    cases.push_back(
        {"conductor_multiscatter_r1",
         lazyMaterial(R"({"type":"conductor","f0":0.9,"roughness":1,"multiscatter":true})")});
    cases.push_back(
        {"standard_albedo_coupling_r0p5",
         lazyMaterial(R"({"type":"standard","base_color":[0.8,0.5,0.2],"roughness":0.5,)"
                      R"("coupling":"albedo"})")});
    cases.push_back(
        {"standard_albedo_multiscatter_r0p2",
         lazyMaterial(R"({"type":"standard","base_color":[0.8,0.5,0.2],"roughness":0.2,)"
                      R"("coupling":"albedo","multiscatter":true})")});
    cases.push_back({"standard_albedo_multiscatter_metal_r0p8",
                     lazyMaterial(R"({"type":"standard","base_color":[0.9,0.6,0.3],"metalness":1,)"
                                  R"("roughness":0.8,"coupling":"albedo","multiscatter":true})")});
    cases.push_back(
        {"phong_r0p3", lazyMaterial(R"({"type":"phong","reflectance":0.9,"roughness":0.3})")});
    cases.push_back(
        {"phong_r0p8", lazyMaterial(R"({"type":"phong","reflectance":0.9,"roughness":0.8})")});
    cases.push_back(
        {"standard_phong_r0p5",
         lazyMaterial(R"({"type":"standard","base_color":[0.8,0.5,0.2],"roughness":0.5,)"
                      R"("specular_model":"phong"})")});

    // Mixes: a rough conductor with a diffuse; mixes nested two deep over a layered stack, a
    // rough conductor and a rough glass (its only transmission, index 1.5); a smooth (delta)
    // conductor with a diffuse, whose delta samples the mix hands back to the conductor.
    cases.push_back(
        {"mix_conductor_lambert",
         lazyMaterial(R"({"type":"mix","weight":0.3,"a":{"type":"conductor",)"
                      R"("eta":[0.18,0.42,1.37],"k":[3.42,2.35,1.77],"fresnel":"exact",)"
                      R"("roughness":0.4},"b":{"type":"lambert","reflectance":[0.7,0.5,0.3]}})")});
    cases.push_back(
        {"mix_nested_layered_conductor_dielectric",
         lazyMaterial(R"({"type":"mix","weight":0.4,"a":{"type":"mix","weight":0.6,)"
                      R"("a":{"type":"layered","interface":{"roughness":0.3,"ior":1.5,)"
                      R"("fresnel":"exact"},"base":{"type":"lambert","reflectance":0.6}},)"
                      R"("b":{"type":"conductor","f0":[0.9,0.6,0.3],"roughness":0.5}},)"
                      R"("b":{"type":"dielectric","ior":1.5,"roughness":0.4}})"),
         true, 1.5});
    cases.push_back(
        {"mix_smooth_conductor_oren_nayar",
         lazyMaterial(R"({"type":"mix","weight":0.5,"a":{"type":"conductor",)"
                      R"("eta":[0.18,0.42,1.37],"k":[3.42,2.35,1.77],"fresnel":"exact",)"
                      R"("alpha":0},"b":{"type":"oren_nayar","reflectance":0.6,)"
                      R"("roughness":0.5}})")});
    // Measured: RGL tables (measured_table.h) of a rough gold conductor, written as the RGL
    // database writes them (rgl_file_writer.h), isotropic with RGB values and anisotropic
    // with spectra (in RGB mode, reduced to RGB). Not reciprocal: tabulated around wo.
    auto measured = [](double ax, double ay, RglTabulation t) {
        return LazyBxdf([ax, ay, t] {
            const MicrofacetDistribution<double> d(NdfKind::Ggx, ax, ay);
            const ConductorBxdf<Spec> conductor(MicrofacetReflectionLobe<Spec>(d, goldFresnel()));
            auto table = std::make_shared<const MeasuredBsdfTable>(
                measuredFields(rglFields(conductor, d, t)));
            return std::shared_ptr<const Bxdf<Spec>>(
                std::make_shared<MeasuredBxdf<Spec>>(table, std::array<double, 3>{}));
        });
    };
    cases.push_back({"measured_ggx_rgb_a0p3", measured(0.3, 0.3, {}), false, 1.0, false});
    cases.push_back({"measured_ggx_anisotropic_spectra",
                     measured(0.15, 0.45, {.phiCount = 9, .spectral = true}), false, 1.0, false});
    // Hair (hair.h): Chiang et al. 2016's fibre outside, a pass-through delta inside; not
    // reciprocal (A_p depends on theta_o and h only), so importance evaluates the adjoint.
    // Brown hair at the defaults, a light rough one and a smooth dark one with a steep tilt
    // (the white furnace of an absorption-free fibre: tests/bsdf/hair_test.cpp). Three only:
    // the fibre's pdf costs the chi-square test some 10 s a case.
    auto hair = [](const Spec& sigmaA, double betaM, double betaN, double alpha) {
        return std::make_shared<HairBxdf<Spec>>(HairFiber<Spec>(1.55, sigmaA, betaM, betaN, alpha));
    };
    cases.push_back({"hair_brown", hair(Spec(0.54, 0.91, 1.78), 0.3, 0.3, 2), true, 1.0, false});
    cases.push_back(
        {"hair_blond_rough", hair(Spec(0.06, 0.1, 0.2), 0.6, 0.7, 3), true, 1.0, false});
    cases.push_back({"hair_dark_smooth", hair(Spec(2.5, 3.5, 5), 0.1, 0.15, 8), true, 1.0, false});
    return cases;
}

/// The coated (random-walk) materials: their eval and pdf are estimates, so the exact
/// properties run over bsdfCases() do not apply; tests/bsdf/coated_test.cpp runs the
/// statistical ones over these (docs/bsdf.md, "coated").
inline std::vector<BsdfCase> coatedCases() {
    return {
        {"coated_rough_lambert",
         lazyMaterial(R"({"type":"coated","roughness":0.4,"base":{"type":"lambert",)"
                      R"("reflectance":[0.8,0.5,0.3]}})")},
        {"coated_smooth_rough_gold",
         lazyMaterial(R"({"type":"coated","ior":1.5,"base":{"type":"conductor","material":"Au",)"
                      R"("roughness":0.4}})")},
        {"coated_rough_medium",
         lazyMaterial(R"({"type":"coated","roughness":0.3,"thickness":0.5,"albedo":[0.9,0.6,0.3],)"
                      R"("g":0.4,"base":{"type":"lambert","reflectance":0.7}})")},
        {"coated_rough_medium_over_mirror",
         lazyMaterial(R"({"type":"coated","roughness":0.3,"thickness":1,"albedo":0.8,"g":-0.3,)"
                      R"("base":{"type":"conductor","f0":0.9}})")},
    };
}

/// Directions of wo at the given polar angle (degrees), off the xz-plane so anisotropy shows.
inline Vec3d directionAt(double thetaDeg, double phiDeg = 20.0) {
    const double t = radians(thetaDeg), p = radians(phiDeg);
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

}  // namespace lamina::testing
