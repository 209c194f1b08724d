// The polarised `layered` and `standard` materials (layered.h, docs/polarisation.md): the
// interface's reflection polarises by the Fresnel amplitudes of its index (an F0-only model by
// the dielectric of the same F0), the same from either side of the surface; the base, the
// transmission through the interface and the energy compensation depolarise. Checked against
// Fresnel's closed forms r_s = -sin(i - t) / sin(i + t), r_p = tan(i - t) / tan(i + t) (Born and
// Wolf, section 1.5.2), written here apart from lamina's amplitude code. Broken once on purpose:
// an interface evaluated from inside below the surface (the dielectric's one-sided Fresnel)
// fails the test from below at Brewster's angle, and a depolarised interface fails all three.
#include <gtest/gtest.h>

#include <string>

#include <numbers>

#include "bsdf_cases.h"
#include "lamina/bsdf/material_kind.h"
#include "lamina/core/pcg32.h"

namespace lamina {
namespace {

using testing::Spec;
using Mueller = MuellerMatrix<Spec>;

std::unique_ptr<Bxdf<Spec>> build(const std::string& json) {
    return buildBxdf(parseMaterialArgument(json), SpectrumContext<Spec>{});
}

/// Fresnel's reflectances of glass of index `eta` at the angle of incidence `i` (radians).
std::pair<double, double> fresnelRsRp(double i, double eta) {
    const double t = std::asin(std::sin(i) / eta);
    return {sqr(std::sin(i - t) / std::sin(i + t)), sqr(std::tan(i - t) / std::tan(i + t))};
}

struct Polarisation {
    double dolp;      ///< of unpolarised light after the event
    double offAxis;   ///< |sin| of the angle between its linear polarisation and s
    double circular;  ///< S3 / S0
};

/// What the event `m` (channel c) makes of unpolarised light leaving along wo: its degree of
/// linear polarisation and how far its angle is from the s direction, the normal of the plane
/// of incidence (wo's canonical frame: x = stokesAxis(wo), y = wo x x).
Polarisation polarisationOf(const Mueller& m, const Vec3d& wo, int c = 1) {
    const double s0 = m(0, 0)[c], s1 = m(1, 0)[c], s2 = m(2, 0)[c], s3 = m(3, 0)[c];
    const Vec3d x = stokesAxis(wo), y = glm::cross(wo, x);
    const Vec3d s = glm::normalize(glm::cross(wo, Vec3d(0.0, 0.0, 1.0)));
    const double angle = 0.5 * std::atan2(s2, s1);
    const double expected = std::atan2(glm::dot(s, y), glm::dot(s, x));
    return {std::hypot(s1, s2) / s0, std::abs(std::sin(angle - expected)), s3 / s0};
}

/// wo at `degrees` from the normal on the side `side` (+1 above, -1 below).
Vec3d at(double degrees, double side) {
    Vec3d wo = testing::directionAt(degrees, 25.0);
    wo.z *= side;
    return wo;
}

Vec3d mirror(const Vec3d& wo) {
    return {-wo.x, -wo.y, wo.z};
}

// The smooth interfaces: the delta sample of their reflection (uc = 0 picks the interface).
const char* const kSmoothMaterials[] = {
    R"({"type":"layered","interface":{"ior":1.5,"fresnel":"exact","roughness":0},)"
    R"("base":{"type":"lambert","reflectance":[0.8,0.4,0.2]}})",
    // F0 = 0.04 with shadowed Schlick: the dielectric of index 1.5.
    R"({"type":"standard","base_color":[0.2,0.5,0.8],"roughness":0})",
    R"({"type":"layered","interface":{"ior":1.5,"fresnel":"exact","roughness":0},)"
    R"("base":{"type":"lambert","reflectance":0.5},"transmission":0.4})",
};
// A rough interface alone: at the mirror direction its half vector is the normal.
const char* const kRoughInterface =
    R"({"type":"layered","interface":{"ior":1.5,"fresnel":"exact","roughness":0.3}})";

// An opaque stack is the same from either side; a transmitting one (the last smooth material)
// seen from inside reflects as the inside of its dielectric, whose Brewster angle is
// atan(1 / 1.5).
TEST(PolarisedLayered, AtBrewstersAngleOfItsInterfaceItReflectsOnlySFromEitherSide) {
    const double brewster = std::atan(1.5) * 180.0 / std::numbers::pi;
    const double insideBrewster = std::atan(1.0 / 1.5) * 180.0 / std::numbers::pi;
    for (const double side : {1.0, -1.0}) {
        const Vec3d wo = at(brewster, side);
        for (const char* json : kSmoothMaterials) {
            const bool transmits = std::string(json).find("transmission") != std::string::npos;
            const Vec3d w = at(transmits && side < 0 ? insideBrewster : brewster, side);
            const auto bxdf = build(json);
            const auto s = bxdf->sample(w, 0.0, {0.5, 0.5}, TransportMode::Radiance);
            ASSERT_TRUE(s && s->isSpecular() && !s->isTransmission()) << json;
            const Polarisation p =
                polarisationOf(bxdf->sampleMueller(w, *s, TransportMode::Radiance), w);
            EXPECT_NEAR(p.dolp, 1.0, 1e-9) << json << " side " << side;
            EXPECT_LT(p.offAxis, 1e-6) << json << " side " << side;
            EXPECT_NEAR(p.circular, 0.0, 1e-12);
        }
        const auto rough = build(kRoughInterface);
        const Polarisation p =
            polarisationOf(rough->evalMueller(wo, mirror(wo), TransportMode::Radiance), wo);
        EXPECT_NEAR(p.dolp, 1.0, 1e-9) << "rough, side " << side;
        EXPECT_LT(p.offAxis, 1e-6) << "rough, side " << side;
    }
}

TEST(PolarisedLayered, AtFortyFiveDegreesItsDegreeOfPolarisationIsFresnels) {
    // The interface alone over a black base: (Rs - Rp) / (Rs + Rp) = 0.8316 for index 1.5.
    const auto [rs, rp] = fresnelRsRp(std::numbers::pi / 4.0, 1.5);
    const double dolp = (rs - rp) / (rs + rp);
    const auto smooth =
        build(R"({"type":"layered","interface":{"ior":1.5,"fresnel":"exact","roughness":0},)"
              R"("base":{"type":"lambert","reflectance":0}})");
    const auto rough = build(kRoughInterface);
    for (const double side : {1.0, -1.0}) {
        const Vec3d wo = at(45.0, side);
        const auto s = smooth->sample(wo, 0.0, {0.5, 0.5}, TransportMode::Radiance);
        ASSERT_TRUE(s && s->isSpecular());
        const Mueller m = smooth->sampleMueller(wo, *s, TransportMode::Radiance);
        // The interface is the stack's only lobe: chosen always, weight (Rs + Rp) / 2.
        EXPECT_NEAR(m(0, 0)[1], (rs + rp) / 2.0, 1e-12);
        const Polarisation p = polarisationOf(m, wo);
        EXPECT_NEAR(p.dolp, dolp, 1e-9) << "smooth, side " << side;
        EXPECT_LT(p.offAxis, 1e-6);
        const Polarisation q =
            polarisationOf(rough->evalMueller(wo, mirror(wo), TransportMode::Radiance), wo);
        EXPECT_NEAR(q.dolp, dolp, 1e-9) << "rough, side " << side;
        EXPECT_LT(q.offAxis, 1e-6);
    }
}

TEST(PolarisedLayered, ItsBaseAndTransmissionDepolarise) {
    // With a base and transmission, the matrix is the interface's alone plus a depolariser:
    // every element but [0][0] is the interface's, and transmission has only [0][0].
    const auto stack =
        build(R"({"type":"layered","interface":{"ior":1.5,"fresnel":"exact","roughness":0.3,)"
              R"("multiscatter":true},"base":{"type":"lambert","reflectance":[0.8,0.4,0.2]},)"
              R"("transmission":0.3,"coupling":"albedo"})");
    // The interface with a black base and the same transmission: from inside it reflects with
    // the Fresnel seen from inside, as the stack does.
    const auto alone =
        build(R"({"type":"layered","interface":{"ior":1.5,"fresnel":"exact","roughness":0.3},)"
              R"("base":{"type":"lambert","reflectance":0},"transmission":0.3})");
    Pcg32 rng(12);
    int reflections = 0, transmissions = 0;
    for (int i = 0; i < 1000; ++i) {
        const Vec3d wo = squareToUniformSphere(Vec2d(rng.nextDouble(), rng.nextDouble()));
        const Vec3d wi = squareToUniformSphere(Vec2d(rng.nextDouble(), rng.nextDouble()));
        const Mueller m = stack->evalMueller(wo, wi, TransportMode::Radiance);
        const Mueller interface = alone->evalMueller(wo, wi, TransportMode::Radiance);
        for (int c = 0; c < 3; ++c) {
            if (!(m(0, 0)[c] > 0.0)) continue;
            for (int r = 0; r < 4; ++r)
                for (int k = 0; k < 4; ++k) {
                    if (r == 0 && k == 0) continue;
                    const double expected = sameHemisphere(wo, wi) ? interface(r, k)[c] : 0.0;
                    ASSERT_NEAR(m(r, k)[c], expected, 1e-12 * m(0, 0)[c]) << "element " << r << k;
                }
        }
        if (sameHemisphere(wo, wi))
            reflections += std::hypot(m(1, 0)[1], m(2, 0)[1]) > 1e-3 * m(0, 0)[1];
        else
            transmissions += m(0, 0)[1] > 0.0;
    }
    EXPECT_GT(reflections, 50);  // the interface polarises: something was compared
    EXPECT_GT(transmissions, 50);
}

TEST(PolarisedLayered, LaminaInfoSaysTheInterfacePolarises) {
    for (const char* name : {"standard", "layered"}) {
        const MaterialKind* kind = findMaterialKind(name);
        ASSERT_TRUE(kind);
        EXPECT_TRUE(kind->polarisation.starts_with("polarising at its interface")) << name;
    }
    EXPECT_EQ(findMaterialKind("phong")->polarisation, "an ideal depolariser");
}

}  // namespace
}  // namespace lamina
