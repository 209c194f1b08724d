// `lamina polarisation MATERIAL...` (polarisation_materials.h) against closed forms that do not
// go through lamina's amplitude code.
//
// Glass of index 1.5 (an n/k file written here): Fresnel's angle forms (Born and Wolf,
// "Principles of Optics", section 1.5.2, eq. 21), r_s = -sin(i - t) / sin(i + t) and
// r_p = tan(i - t) / tan(i + t) with Snell's sin t = sin i / n, in lamina's signs
// (docs/polarisation.md: r_s = (1 - n) / (1 + n) < 0 and r_p = -r_s at normal incidence), give
// every element: M00 = (Rs + Rp) / 2, M01 = M10 = (Rs - Rp) / 2, M11 = M00,
// M22 = M33 = r_s r_p, the other ten 0. Brewster's angle atan(1.5) is where r_p = 0: there
// M01 / M00 = +1 (only s is reflected, and x = s), and the retardance is 180 degrees below it
// and 0 above it.
//
// Gold at 550 nm (the preset's n, k): the retardance against the complex angle form
// r_p / r_s = -cos(i + t) / cos(i - t) with a complex refraction angle t (Born and Wolf 1.5
// eq. 21 and 14.2), as tests/core/mueller_test.cpp does for one index, here along the whole
// curve the experiment reports; and the diattenuation from |r_p / r_s|.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "lamina/core/math.h"
#include "lamina/experiments/polarisation_materials.h"
#include "lamina/spectral/ior_spectrum.h"
#include "scratch_directory.h"

namespace lamina::experiments {
namespace {

class PolarisationMaterials : public lamina::testing::ScratchDirectoryTest {};

TEST_F(PolarisationMaterials, GlassElementsFollowFresnelsAngleFormsAndBrewstersAngle) {
    const auto file = write("glass15.csv", "nm,n,k\n300,1.5,0\n900,1.5,0\n");
    const PolarisationMaterialsResult r =
        runPolarisationMaterials({{file.string()}, {450, 550, 650}});
    ASSERT_EQ(r.materials.size(), 1u);
    ASSERT_EQ(r.degrees.size(), 181u);
    const PolarisationMaterial& m = r.materials[0];
    EXPECT_FALSE(m.conductor);
    const double n = 1.5, brewster = degrees(std::atan(n));
    for (const MuellerCurve& c : m.curves) {
        for (std::size_t a = 1; a + 1 < r.degrees.size(); ++a) {
            const double i = radians(r.degrees[a]), t = std::asin(std::sin(i) / n);
            const double rs = -std::sin(i - t) / std::sin(i + t);
            const double rp = std::tan(i - t) / std::tan(i + t);
            const double Rs = rs * rs, Rp = rp * rp;
            const MuellerMatrix<double>& mm = c.mueller[a];
            double expected[4][4] = {};
            expected[0][0] = expected[1][1] = (Rs + Rp) / 2;
            expected[0][1] = expected[1][0] = (Rs - Rp) / 2;
            expected[2][2] = expected[3][3] = rs * rp;
            for (int row = 0; row < 4; ++row)
                for (int col = 0; col < 4; ++col)
                    ASSERT_NEAR(mm(row, col), expected[row][col], 1e-12)
                        << "M" << row << col << " at " << r.degrees[a] << " degrees";
            ASSERT_NEAR(c.diattenuation[a], (Rs - Rp) / (Rs + Rp), 1e-12);
            // Not at Brewster's angle itself (not on the grid): the phase is 180 or 0 exactly.
            ASSERT_EQ(c.retardance[a], r.degrees[a] < brewster ? 180.0 : 0.0) << r.degrees[a];
        }
        // Normal incidence: 4% of a half-wave retarder; grazing: the identity.
        const MuellerMatrix<double> normal = c.mueller.front(), grazing = c.mueller.back();
        EXPECT_NEAR(normal(0, 0), 0.04, 1e-15);
        EXPECT_NEAR(normal(2, 2), -0.04, 1e-15);
        EXPECT_EQ(c.retardance.front(), 180.0);
        EXPECT_NEAR(grazing(0, 0), 1.0, 1e-15);
        EXPECT_NEAR(grazing(2, 2), 1.0, 1e-15);
        // The angles found from the data: both Brewster's.
        ASSERT_TRUE(c.principalAngle.has_value());
        EXPECT_NEAR(*c.principalAngle, brewster, 1e-9);
        EXPECT_NEAR(c.minimumRpAngle, brewster, 1e-5);
        EXPECT_LT(c.minimumRp, 1e-12);
        const MuellerMatrix<double> atBrewster =
            specularReflectionMueller(c.index, *c.principalAngle);
        EXPECT_NEAR(atBrewster(0, 1) / atBrewster(0, 0), 1.0, 1e-9);
        EXPECT_NEAR(atBrewster(0, 0), 0.0739644970414201, 1e-12);  // (5/13)^2 / 2
    }
}

TEST_F(PolarisationMaterials, GoldsRetardanceAndDiattenuationFollowTheComplexAngleForm) {
    const PolarisationMaterialsResult r = runPolarisationMaterials({{"Au"}, {550}});
    const PolarisationMaterial& m = r.materials.at(0);
    EXPECT_TRUE(m.conductor);
    const MuellerCurve& c = m.curves.at(0);
    const IorSpectrum gold = *namedIor("Au");
    const std::complex<double> eta(gold.n(550), gold.k(550));
    EXPECT_EQ(c.index, eta);
    for (std::size_t a = 1; a + 1 < r.degrees.size(); ++a) {
        const double i = radians(r.degrees[a]);
        const std::complex<double> t = std::asin(std::complex<double>(std::sin(i)) / eta);
        const std::complex<double> ratio = -std::cos(i + t) / std::cos(i - t);  // r_p / r_s
        // r_s conj(r_p) = |r_s|^2 conj(r_p / r_s): its phase is -arg(ratio).
        double expected = degrees(-std::arg(ratio));
        if (expected < -90) expected += 360;
        ASSERT_NEAR(c.retardance[a], expected, 1e-9) << r.degrees[a] << " degrees";
        const double q = std::norm(ratio);  // Rp / Rs
        ASSERT_NEAR(c.diattenuation[a], (1 - q) / (1 + q), 1e-12) << r.degrees[a];
    }
    // From 180 at normal incidence down to 0 at grazing, through 90 at the principal angle.
    EXPECT_NEAR(c.retardance.front(), 180.0, 1e-9);
    EXPECT_NEAR(c.retardance.back(), 0.0, 1e-9);
    ASSERT_TRUE(c.principalAngle.has_value());
    EXPECT_GT(*c.principalAngle, 60.0);
    EXPECT_LT(*c.principalAngle, 80.0);
    const MuellerMatrix<double> principal = specularReflectionMueller(eta, *c.principalAngle);
    EXPECT_NEAR(degrees(std::atan2(principal(2, 3), principal(2, 2))), 90.0, 1e-9);
    // Gold's pseudo-Brewster angle (least Rp) lies a few degrees below its principal angle.
    EXPECT_GT(*c.principalAngle - c.minimumRpAngle, 0.0);
    EXPECT_LT(*c.principalAngle - c.minimumRpAngle, 10.0);
}

}  // namespace
}  // namespace lamina::experiments
