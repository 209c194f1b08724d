// Thin films (core/thin_film.h, bsdf/thin_film.h): the normal-incidence closed form, thickness
// 0 giving the bare interface, R + T = 1 for a lossless film, the quarter-wave antireflection
// minimum, RGB mode's closed form against the D65 colour of the exact spectrum, and the
// materials' thin_film key in every mode.
#include <gtest/gtest.h>

#include "lamina/bsdf/material_builder.h"
#include "lamina/core/error.h"
#include "lamina/core/thin_film.h"
#include "lamina/spectral/rgb_to_spectrum.h"

namespace lamina {
namespace {

using C = std::complex<double>;

double reflectance(const FresnelAmplitudes<double>& a) {
    return 0.5 * (std::norm(a.rs) + std::norm(a.rp));
}

double filmReflectance(double cosI, const FilmStack<double>& stack, double d, double nm) {
    return reflectance(thinFilmAmplitudes(cosI, stack, d / nm));
}

// Born and Wolf, "Principles of Optics", section 1.6.4, eq. 58: a film of index n2 between
// real indices n1 and n3 at normal incidence, in real arithmetic:
// R = (r12^2 + r23^2 + 2 r12 r23 cos 2 delta) / (1 + r12^2 r23^2 + 2 r12 r23 cos 2 delta).
double normalIncidenceClosedForm(double n1, double n2, double n3, double d, double nm) {
    const double r12 = (n1 - n2) / (n1 + n2), r23 = (n2 - n3) / (n2 + n3);
    const double c = std::cos(2 * (2 * kPi<double> * n2 * d / nm));
    return (r12 * r12 + r23 * r23 + 2 * r12 * r23 * c) /
           (1 + r12 * r12 * r23 * r23 + 2 * r12 * r23 * c);
}

TEST(ThinFilm, NormalIncidenceIsTheClosedForm) {
    for (const double d : {0.0, 50.0, 137.0, 420.0, 1500.0})
        for (const double nm : {380.0, 450.0, 550.0, 700.0}) {
            // A soap film in air, and a film on glass seen from the air and from the glass.
            for (const auto& [n1, n2, n3] : std::array<std::array<double, 3>, 4>{
                     {{1.0, 1.33, 1.0}, {1.0, 1.38, 1.52}, {1.52, 2.4, 1.0}, {1.0, 1.2, 3.0}}}) {
                const FresnelAmplitudes<double> a =
                    thinFilmAmplitudes(1.0, {n1, n2, C(n3)}, d / nm);
                const double expected = normalIncidenceClosedForm(n1, n2, n3, d, nm);
                EXPECT_NEAR(std::norm(a.rs), expected, 1e-12) << d << " nm at " << nm;
                EXPECT_NEAR(std::norm(a.rp), expected, 1e-12) << d << " nm at " << nm;
            }
        }
    // On a conductor (gold at 550 nm): the complex form, delta = 2 pi n2 d / lambda.
    const C r12 = (1.0 - 1.45) / (1.0 + 1.45),
            r23 = (1.45 - C(0.42, 2.35)) / (1.45 + C(0.42, 2.35));
    const C e = std::polar(1.0, 2 * 2 * kPi<double> * 1.45 * 120 / 550);
    const FresnelAmplitudes<double> a =
        thinFilmAmplitudes(1.0, {1.0, 1.45, C(0.42, 2.35)}, 120.0 / 550);
    EXPECT_NEAR(std::norm(a.rs), std::norm((r12 + r23 * e) / (1.0 + r12 * r23 * e)), 1e-12);
}

TEST(ThinFilm, ThicknessZeroIsTheBareInterface) {
    for (double theta = 0; theta < 90; theta += 2.5) {
        const double cosI = std::cos(radians(theta));
        for (const auto& [n1, n2, n3] : std::array<std::array<double, 3>, 3>{
                 {{1.0, 1.33, 1.5}, {1.5, 2.0, 1.0}, {1.0, 1.8, 1.33}}}) {
            const auto film = thinFilmAmplitudes(cosI, {n1, n2, C(n3)}, 0.0);
            const auto bare = fresnelAmplitudes(cosI, C(n3 / n1));
            EXPECT_NEAR(std::abs(film.rs - bare.rs), 0, 1e-12) << theta;
            EXPECT_NEAR(std::abs(film.rp - bare.rp), 0, 1e-12) << theta;
            EXPECT_NEAR(std::abs(film.ts - bare.ts), 0, 1e-12) << theta;
            EXPECT_NEAR(std::abs(film.tp - bare.tp), 0, 1e-12) << theta;
        }
        const auto film = thinFilmAmplitudes(cosI, {1.0, 1.6, C(0.18, 3.42)}, 0.0);
        EXPECT_NEAR(reflectance(film), fresnelConductor(cosI, 0.18, 3.42), 1e-12) << theta;
    }
    // RGB mode's closed form (Belcour and Barla) at thickness 0: the bare reflectance.
    const auto material = [](const std::string& optics, double d) {
        return buildBxdf(parseMaterialArgument(R"({"type":"conductor",)" + optics +
                                               R"(,"fresnel":"exact","roughness":0.3,)"
                                               R"("thin_film":{"thickness_nm":)" +
                                               std::to_string(d) + R"(,"ior":1.6}})"),
                         SpectrumContext<Rgbd>{});
    };
    const auto bare = buildBxdf(
        parseMaterialArgument(
            R"({"type":"conductor","eta":[0.18,0.42,1.37],"k":[3.42,2.35,1.77],"fresnel":"exact","roughness":0.3})"),
        SpectrumContext<Rgbd>{});
    const auto filmed = material(R"("eta":[0.18,0.42,1.37],"k":[3.42,2.35,1.77])", 0.0);
    for (double theta = 0; theta < 89; theta += 8) {
        const Vec3d wo(std::sin(radians(theta)), 0, std::cos(radians(theta)));
        const Vec3d wi(-0.3, 0.2, std::sqrt(1 - 0.13));
        const Rgbd a = filmed->eval(wo, wi, TransportMode::Radiance);
        const Rgbd b = bare->eval(wo, wi, TransportMode::Radiance);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(a[c], b[c], 1e-6 * std::max(1.0, b[c])) << theta;
    }
}

TEST(ThinFilm, ALosslessFilmReflectsAndTransmitsEverything) {
    for (double theta = 0; theta < 90; theta += 1.5) {
        const double cosI = std::cos(radians(theta));
        for (const double d : {0.0, 90.0, 333.0, 2000.0})
            // Into glass, out of glass (total reflection beyond 41.8 degrees), a free film.
            for (const auto& [n1, n2, n3] : std::array<std::array<double, 3>, 4>{
                     {{1.0, 1.38, 1.52}, {1.52, 1.38, 1.0}, {1.52, 2.4, 1.0}, {1.0, 1.33, 1.0}}}) {
                const auto a = thinFilmAmplitudes(cosI, {n1, n2, C(n3)}, d / 550);
                const double f = a.transmittedPowerFactor;
                EXPECT_NEAR(std::norm(a.rs) + f * std::norm(a.ts), 1.0, 1e-12) << theta << " " << d;
                EXPECT_NEAR(std::norm(a.rp) + f * std::norm(a.tp), 1.0, 1e-12) << theta << " " << d;
            }
    }
}

TEST(ThinFilm, AQuarterWaveOfMagnesiumFluorideIsTheKnownAntireflectionMinimum) {
    // MgF2 (1.38) a quarter wave thick at 550 nm on crown glass (1.52): at normal incidence
    // R = ((n1 n3 - n2^2) / (n1 n3 + n2^2))^2 = 1.26%, against 4.26% bare, and 550 nm is the
    // minimum over the visible (Hecht, "Optics", section 9.9).
    const FilmStack<double> stack{1.0, 1.38, C(1.52)};
    const double d = 550 / (4 * 1.38);
    const double minimum = sqr((1.52 - 1.38 * 1.38) / (1.52 + 1.38 * 1.38));
    EXPECT_NEAR(filmReflectance(1, stack, d, 550), minimum, 1e-12);
    EXPECT_NEAR(minimum, 0.0126, 1e-4);
    for (double nm = 380; nm <= 830; nm += 5)
        EXPECT_GE(filmReflectance(1, stack, d, nm), minimum - 1e-15) << nm;
    EXPECT_GT(filmReflectance(1, stack, d, 450), minimum + 0.002);
    EXPECT_NEAR(filmReflectance(1, stack, 0, 550), sqr(0.52 / 2.52), 1e-12);
}

// RGB mode against the D65 colour of the exact spectral reflectance (reflectanceColor), for
// indices that do not vary with the wavelength: the closed form integrates the same spectrum.
TEST(ThinFilm, RgbModeIsTheColourOfTheExactSpectrum) {
    struct Case {
        const char* json;
        FilmStack<double> stack;
        double d;
    };
    const Case cases[] = {
        {R"({"type":"dielectric","ior":1.0,"thin_film":{"thickness_nm":380,"ior":1.33}})",
         {1.0, 1.33, C(1.0)},
         380},
        {R"({"type":"dielectric","ior":1.5,"thin_film":{"thickness_nm":250,"ior":2.4}})",
         {1.0, 2.4, C(1.5)},
         250},
        {R"({"type":"conductor","eta":0.3,"k":3,"thin_film":{"thickness_nm":500,"ior":1.5}})",
         {1.0, 1.5, C(0.3, 3)},
         500},
    };
    for (const Case& c : cases) {
        const auto b = buildBxdf(parseMaterialArgument(c.json), SpectrumContext<Rgbd>{});
        for (const double theta : {0.0, 30.0, 60.0, 80.0}) {
            const double cosI = std::cos(radians(theta));
            const Vec3d wo(std::sin(radians(theta)), 0, cosI);
            const auto s = b->sample(wo, 0.0, {0.5, 0.5}, TransportMode::Radiance);
            ASSERT_TRUE(s && !s->isTransmission());
            const Rgbd rgb = s->weight * s->pdf;
            const Rgb<double> expected = reflectanceColor(
                [&](double nm) { return filmReflectance(cosI, c.stack, c.d, nm); });
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(rgb[k], expected[k], 5e-5) << c.json << " at " << theta;
        }
    }
}

TEST(ThinFilm, SpectralModeIsTheAirySumAtEachWavelength) {
    auto lambda = SampledWavelengths<double>::fixed({420, 510, 600, 690});
    const SpectrumContext<SampledSpectrum<double>> context{lambda};
    const auto b = buildBxdf(
        parseMaterialArgument(
            R"({"type":"dielectric","ior":1.5,"thin_film":{"thickness_nm":300,"ior":1.33}})"),
        context);
    const double cosI = std::cos(radians(35.0));
    const Vec3d wo(std::sin(radians(35.0)), 0, cosI);
    const auto s = b->sample(wo, 0.0, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(s && !s->isTransmission());
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(s->weight[i] * s->pdf,
                    filmReflectance(cosI, {1.0, 1.33, C(1.5)}, 300, lambda[i]), 1e-12);
    // The refracted share is the rest, and no wavelength is dropped (the film bends nothing).
    const auto t = b->sample(wo, 1 - 1e-12, {0.5, 0.5}, TransportMode::Importance);
    ASSERT_TRUE(t && t->isTransmission());
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(s->weight[i] * s->pdf + t->weight[i] * t->pdf, 1.0, 1e-12);
    EXPECT_FALSE(lambda.secondaryTerminated());
}

TEST(ThinFilm, MaterialsRefuseFilmsTheyCannotCarry) {
    EXPECT_NO_THROW(parseMaterialArgument(
        R"({"type":"conductor","material":"Au","thin_film":{"thickness_nm":100}})"));
    for (
        const char* bad : {
            R"({"type":"conductor","f0":0.9,"thin_film":{"thickness_nm":100}})",
            R"({"type":"conductor","material":"Au","fresnel":"f82","thin_film":{"thickness_nm":100}})",
            R"({"type":"dielectric","thin_film":{"ior":1.4}})",
            R"({"type":"dielectric","thin_film":{"thickness_nm":-1}})",
            R"({"type":"dielectric","thin_film":{"thickness_nm":100,"ior":0.8}})",
            R"({"type":"dielectric","thin_film":{"thickness_nm":1e9}})",
            R"({"type":"dielectric","thin_film":{"thickness_nm":100,"colour":1}})",
            R"({"type":"layered","base":{"type":"conductor","material":"Au","roughness":0.3,"thin_film":{"thickness_nm":100}}})",
        })
        EXPECT_THROW(parseMaterialArgument(bad), InputError) << bad;
}

}  // namespace
}  // namespace lamina
