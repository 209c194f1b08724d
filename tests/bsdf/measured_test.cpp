// The `measured` material (measured.h, measured_table.h): tables written from lamina's own GGX
// conductor in the RGL layout (rgl_file_writer.h) give the conductor back within the
// interpolation's error, exactly on the grid, in RGB and spectral form; spectra reduce to RGB
// as the CIE observer under D65 says; the albedo stays within [0, 1]. The catalogue
// (bsdf_cases.h) holds the same tables to weight = eval / pdf, the adjoint relation and
// chi-square.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "lamina/bsdf/conductor.h"
#include "lamina/bsdf/measured.h"
#include "lamina/core/pcg32.h"
#include "rgl_file_writer.h"

namespace lamina {
namespace {

using Spec = Rgb<double>;
using Spectral = SampledSpectrum<double>;

Fresnel<Spec> gold() {
    return Fresnel<Spec>::conductor(Spec(0.18, 0.42, 1.37), Spec(3.42, 2.35, 1.77));
}

struct Tabulated {
    ConductorBxdf<Spec> conductor;
    std::shared_ptr<const MeasuredBsdfTable> table;
    MeasuredBxdf<Spec> measured;
};

Tabulated tabulate(double ax, double ay, const testing::RglTabulation& t) {
    const MicrofacetDistribution<double> d(NdfKind::Ggx, ax, ay);
    ConductorBxdf<Spec> conductor(MicrofacetReflectionLobe<Spec>(d, gold()));
    auto table = std::make_shared<const MeasuredBsdfTable>(
        testing::measuredFields(testing::rglFields(conductor, d, t)));
    return {conductor, table, MeasuredBxdf<Spec>(table, {})};
}

Vec3d direction(double thetaDeg, double phiDeg) {
    const double t = radians(thetaDeg), p = radians(phiDeg);
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

// The relative errors of the measured eval against the conductor's over directions wi the
// conductor itself samples (where its value is), for wo up to 70 degrees.
std::vector<double> relativeErrors(const Tabulated& t, int count) {
    Pcg32 rng(5);
    std::vector<double> errors;
    while (int(errors.size()) < count) {
        const Vec3d wo = direction(70.0 * rng.nextDouble(), 360.0 * rng.nextDouble());
        const auto s = t.conductor.sample(wo, 0.5, Vec2d(rng.nextDouble(), rng.nextDouble()),
                                          TransportMode::Radiance);
        if (!s || s->wi.z < 0.05) continue;
        const Spec want = t.conductor.eval(wo, s->wi, TransportMode::Radiance);
        const Spec got = t.measured.eval(wo, s->wi, TransportMode::Radiance);
        for (int c = 0; c < 3; ++c)
            errors.push_back(std::abs(got[c] - want[c]) / want[c]);
    }
    std::sort(errors.begin(), errors.end());
    return errors;
}

double quantile(const std::vector<double>& sorted, double q) {
    return sorted[std::size_t(q * double(sorted.size() - 1))];
}

TEST(MeasuredBsdf, IsotropicTableGivesTheConductorBackWithinTheInterpolationError) {
    // Measured: median 0.06%, 95th percentile 2%, 99th 10% (the grid's nodes near the peak).
    const Tabulated t = tabulate(0.3, 0.3, {});
    const std::vector<double> e = relativeErrors(t, 6000);
    EXPECT_LT(quantile(e, 0.5), 0.002);
    EXPECT_LT(quantile(e, 0.95), 0.04);
}

TEST(MeasuredBsdf, AnisotropicTableGivesTheConductorBackWithinTheInterpolationError) {
    // Measured: median 0.2%, 95th percentile 4.7% (17 phi_i over the turn).
    const Tabulated t = tabulate(0.15, 0.45, {.phiCount = 17});
    const std::vector<double> e = relativeErrors(t, 6000);
    EXPECT_LT(quantile(e, 0.5), 0.005);
    EXPECT_LT(quantile(e, 0.95), 0.08);
}

TEST(MeasuredBsdf, OnTheGridTheConductorComesBackExactly) {
    // wo at a tabulated theta_i, wi where the visible-normal warp takes a value node: the
    // stored value times D / (4 sigma) is the conductor's eval to float precision.
    const testing::RglTabulation grid;
    const Tabulated t = tabulate(0.3, 0.3, grid);
    const auto fields = testing::rglFields(
        t.conductor, MicrofacetDistribution<double>(NdfKind::Ggx, 0.3, 0.3), grid);
    const MeasuredBsdfFields f = testing::measuredFields(fields);
    const MarginalWarp2D vndf(grid.vndfSize, grid.vndfSize, {f.phiI.values, f.thetaI.values},
                              f.vndf.values, MarginalWarp2D::Kind::Density);
    int checked = 0;
    for (int k : {2, 5, 8}) {
        const double thetaO = f.thetaI.values[std::size_t(k)];
        const Vec3d wo(std::sin(thetaO), 0, std::cos(thetaO));
        const double params[2] = {0.0, thetaO};
        for (int y = 4; y < grid.valueSize; y += 9)
            for (int x = 4; x < grid.valueSize; x += 9) {
                const Vec2d ui(double(x) / (grid.valueSize - 1), double(y) / (grid.valueSize - 1));
                const Vec2d uM = vndf.sample(ui, params).first;
                const double thetaM = uM.x * uM.x * kPi<double> / 2,
                             phiM = (2 * uM.y - 1) * kPi<double>;
                const Vec3d m(std::sin(thetaM) * std::cos(phiM), std::sin(thetaM) * std::sin(phiM),
                              std::cos(thetaM));
                const Vec3d wi = reflect(wo, m);
                if (wi.z < 0.05) continue;
                const Spec want = t.conductor.eval(wo, wi, TransportMode::Radiance);
                const Spec got = t.measured.eval(wo, wi, TransportMode::Radiance);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(got[c], want[c], 1e-4 * want[c]) << "theta_o " << thetaO;
                ++checked;
            }
    }
    EXPECT_GT(checked, 20);
}

TEST(MeasuredBsdf, SpectraAtTheirWavelengthsAreTheChannelsTheyWereWrittenFrom) {
    // The spectral file holds blue, green and red at 450, 550 and 650 nm.
    const Tabulated rgb = tabulate(0.3, 0.3, {});
    const Tabulated spectra = tabulate(0.3, 0.3, {.spectral = true});
    ASSERT_TRUE(spectra.table->spectral());
    const MeasuredBxdf<Spectral> spectral(spectra.table, {650.0, 550.0, 450.0, 500.0});
    Pcg32 rng(3);
    for (int i = 0; i < 200; ++i) {
        const Vec3d wo = direction(80 * rng.nextDouble(), 360 * rng.nextDouble());
        const Vec3d wi = direction(80 * rng.nextDouble(), 360 * rng.nextDouble());
        const Spec want = rgb.measured.eval(wo, wi, TransportMode::Radiance);
        const Spectral got = spectral.eval(wo, wi, TransportMode::Radiance);
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(got[c], want[c], 1e-6 * want[c] + 1e-12);
        // Between two tabulated wavelengths: the linear interpolation of their values.
        ASSERT_NEAR(got[3], 0.5 * (want[1] + want[2]), 1e-6 * want[1] + 1e-12);
    }
}

TEST(MeasuredBsdf, AGreySpectrumReducesToTheSameGreyInRgb) {
    // Every wavelength holding the same values: under D65 with the CIE observer a constant
    // spectrum is the white (1, 1, 1) times it.
    const MicrofacetDistribution<double> d(NdfKind::Ggx, 0.3, 0.3);
    const ConductorBxdf<Spec> grey(
        MicrofacetReflectionLobe<Spec>(d, Fresnel<Spec>::schlick(Spec(0.7))));
    const auto fields = testing::measuredFields(testing::rglFields(grey, d, {.spectral = true}));
    const MeasuredBsdfTable table(fields);
    Pcg32 rng(11);
    int checked = 0;
    for (int i = 0; i < 300; ++i) {
        const auto l = table.lookup(direction(80 * rng.nextDouble(), 360 * rng.nextDouble()),
                                    direction(80 * rng.nextDouble(), 360 * rng.nextDouble()));
        if (!l) continue;
        const double v = table.value(*l, 550.0);
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(table.rgbValue(*l, c), v, 2e-3 * v + 1e-12);
        ++checked;
    }
    EXPECT_GT(checked, 200);
}

TEST(MeasuredBsdf, AlbedoIsAtMostOneAndCloseToTheConductors) {
    const Tabulated t = tabulate(0.3, 0.3, {});
    Pcg32 rng(13);
    for (double theta : {0.0, 30.0, 60.0, 80.0}) {
        const Vec3d wo = direction(theta, 40.0);
        constexpr int n = 100000;
        Spec sumMeasured(0.0), sumConductor(0.0);
        for (int i = 0; i < n; ++i) {
            const Vec2d u(rng.nextDouble(), rng.nextDouble());
            if (const auto s = t.measured.sample(wo, 0.5, u, TransportMode::Radiance))
                sumMeasured += s->weight;
            if (const auto s = t.conductor.sample(wo, 0.5, u, TransportMode::Radiance))
                sumConductor += s->weight;
        }
        for (int c = 0; c < 3; ++c) {
            const double albedo = sumMeasured[c] / n, conductor = sumConductor[c] / n;
            EXPECT_LE(albedo, 1.0) << "theta " << theta;
            EXPECT_NEAR(albedo, conductor, 0.03 * conductor) << "theta " << theta;
        }
    }
}

TEST(MeasuredBsdf, BelowTheSurfaceItMirrorsAndAcrossItIsBlack) {
    const Tabulated t = tabulate(0.3, 0.3, {});
    const Vec3d wo = direction(30, 10), wi = direction(40, 200);
    const Vec3d woBelow(-wo.x, -wo.y, -wo.z), wiBelow(-wi.x, -wi.y, -wi.z);
    const Spec above = t.measured.eval(wo, wi, TransportMode::Radiance);
    const Spec below = t.measured.eval(woBelow, wiBelow, TransportMode::Radiance);
    for (int c = 0; c < 3; ++c)
        EXPECT_DOUBLE_EQ(above[c], below[c]);
    EXPECT_TRUE(t.measured.eval(wo, wiBelow, TransportMode::Radiance).isZero());
    EXPECT_EQ(t.measured.pdf(wo, wiBelow), 0.0);
}

}  // namespace
}  // namespace lamina
