// A conductor's eta and k given as RGB triples: in spectral mode they are pbrt-v4's unbounded
// spectra (the Jakob-Hanika table applied to rgb / 2 max(rgb), times 2 max(rgb)), so the same
// numbers are the same metal in lamina's spectral mode and in pbrt-v4; grey triples stay
// exactly constant.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>

#include "lamina/bsdf/material_builder.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/color_space.h"

namespace lamina {
namespace {

using Spectral = SampledSpectrum<double>;

// pbrt-v4's RGBUnboundedSpectrum written out from its documented construction: m = the
// largest component, the sigmoid polynomial of the table at rgb / 2m, scaled by 2m.
double unboundedReference(const Rgb<double>& rgb, double nm) {
    const double scale = 2.0 * std::max({rgb[0], rgb[1], rgb[2]});
    const SigmoidPolynomial c = RgbToSpectrumTable::rec709().lookup(rgb / scale);
    const double x = c.c0 * nm * nm + c.c1 * nm + c.c2;
    return scale * (0.5 + x / (2.0 * std::sqrt(1.0 + x * x)));
}

// The Fresnel reflectance of unpolarised light from a medium of index 1 onto n + ik (Born and
// Wolf, section 14.2), with complex amplitudes: an independent form of lamina's real one.
double complexFresnel(double cosI, double n, double k) {
    const std::complex<double> eta(n, k);
    const double sin2 = 1.0 - cosI * cosI;
    const std::complex<double> cosT = std::sqrt(1.0 - sin2 / (eta * eta));
    const std::complex<double> rs = (cosI - eta * cosT) / (cosI + eta * cosT);
    const std::complex<double> rp = (eta * cosI - cosT) / (eta * cosI + cosT);
    return 0.5 * (std::norm(rs) + std::norm(rp));
}

struct Metal {
    const char* name;
    Rgb<double> eta, k;
};

// A gold-like triple and the copper-like one of Veach's MIS scene (Bitterli's pbrt-v4 port).
const Metal kMetals[] = {
    {"gold-like", {0.143119, 0.374957, 1.44248}, {3.98316, 2.38572, 1.60322}},
    {"copper-like", {0.200438, 0.924033, 1.102212}, {3.912949, 2.452848, 2.142188}},
};

std::string conductorJson(const Rgb<double>& eta, const Rgb<double>& k, const char* fresnel) {
    char json[256];
    std::snprintf(json, sizeof json,
                  R"({"type":"conductor","eta":[%.17g,%.17g,%.17g],"k":[%.17g,%.17g,%.17g],)"
                  R"("fresnel":"%s"})",
                  eta[0], eta[1], eta[2], k[0], k[1], k[2], fresnel);
    return json;
}

// The smooth conductor's sampled weight at cos theta is its Fresnel reflectance.
template <SpectrumType S>
S mirrorWeight(const Bxdf<S>& bsdf, double cosTheta) {
    const Vec3<double> wo(std::sqrt(1 - cosTheta * cosTheta), 0, cosTheta);
    const auto s = bsdf.sample(wo, 0.5, {0.5, 0.5}, TransportMode::Radiance);
    EXPECT_TRUE(s);
    return s ? s->weight : S(0.0);
}

TEST(RgbConductor, SpectralFresnelIsPbrtV4sUnboundedUpsampling) {
    const std::array<std::array<double, 4>, 2> wavelengths = {
        {{380, 452, 517, 575}, {611, 648, 702, 790}}};
    const double cosines[] = {1.0, 0.8, 0.5, 0.3, kF82Cosine, 0.05};
    for (const Metal& metal : kMetals)
        for (const char* fresnel : {"auto", "exact"}) {
            SCOPED_TRACE(std::string(metal.name) + ", fresnel " + fresnel);
            const MaterialDesc m =
                parseMaterialArgument(conductorJson(metal.eta, metal.k, fresnel));
            for (const auto& nm : wavelengths) {
                auto lambda = SampledWavelengths<double>::fixed(nm);
                const auto bsdf = buildBxdf(m, SpectrumContext<Spectral>{lambda});
                for (double c : cosines) {
                    const Spectral f = mirrorWeight(*bsdf, c);
                    for (int i = 0; i < 4; ++i) {
                        const double expected =
                            complexFresnel(c, unboundedReference(metal.eta, nm[std::size_t(i)]),
                                           unboundedReference(metal.k, nm[std::size_t(i)]));
                        EXPECT_NEAR(f[i], expected, 1e-9 * expected)
                            << nm[std::size_t(i)] << " nm, cos " << c;
                    }
                }
            }
        }
}

TEST(RgbConductor, UnboundedSpectraKeepTheirColourAndSize) {
    // The upsampled eta and k have the given triples as their colour under D65 (as a
    // reflectance's colour is its RGB), values above 1 included: a reflectance upsampling would
    // clamp them to 1.
    for (const Metal& metal : kMetals)
        for (const Rgb<double>& rgb : {metal.eta, metal.k}) {
            SCOPED_TRACE(metal.name);
            const Vec3d xyz = integrateAgainstCmf([&](double nm) {
                                  return unboundedReference(rgb, nm) * d65Normalized(nm);
                              }) /
                              cieYIntegral();
            const Vec3d colour = RgbColorSpace::rec709().toRgb(xyz);
            const double m = std::max({rgb[0], rgb[1], rgb[2]});
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(colour[c], rgb[c], 2e-3 * m) << "channel " << c;
        }
    // Gold reflects red far more than blue at normal incidence.
    const Metal& gold = kMetals[0];
    auto lambda = SampledWavelengths<double>::fixed({450, 550, 650, 700});
    const auto bsdf = buildBxdf(parseMaterialArgument(conductorJson(gold.eta, gold.k, "auto")),
                                SpectrumContext<Spectral>{lambda});
    const Spectral f0 = mirrorWeight(*bsdf, 1.0);
    EXPECT_GT(f0[3], 0.9);
    EXPECT_LT(f0[0], 0.6);
}

TEST(RgbConductor, GreyEtaAndKStayExactlyConstant) {
    // Grey triples (and plain numbers) are constant spectra: the same reflectance at every
    // wavelength, bit for bit the RGB mode's exact per-channel value, and a material built
    // without reading the wavelengths (built once for every path).
    const char* optics[] = {R"("eta":[0.4,0.4,0.4],"k":[6,6,6])", R"("eta":0.4,"k":6)",
                            R"("eta":1.7,"k":[0.3,0.3,0.3])"};
    for (const char* o : optics)
        for (const char* fresnel : {"auto", "exact"}) {
            const std::string json = std::string(R"({"type":"conductor",)") + o;
            SCOPED_TRACE(json + ", fresnel " + fresnel);
            auto lambda = SampledWavelengths<double>::fixed({383, 471, 555, 742});
            bool readsWavelengths = false;
            const auto spectral =
                buildBxdf(parseMaterialArgument(json + R"(,"fresnel":")" + fresnel + "\"}"),
                          SpectrumContext<Spectral>{lambda, nullptr, nullptr, &readsWavelengths});
            EXPECT_FALSE(readsWavelengths);
            const auto exactRgb = buildBxdf(parseMaterialArgument(json + R"(,"fresnel":"exact"})"),
                                            SpectrumContext<Rgb<double>>{});
            for (double c : {1.0, 0.6, kF82Cosine, 0.02}) {
                const Spectral f = mirrorWeight(*spectral, c);
                const Rgb<double> r = mirrorWeight(*exactRgb, c);
                for (int i = 0; i < 4; ++i)
                    EXPECT_EQ(f[i], r[0]) << "cos " << c;
            }
        }
}

}  // namespace
}  // namespace lamina
