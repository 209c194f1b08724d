#include <gtest/gtest.h>

#include <glm/matrix.hpp>

#include "lamina/spectral/cie.h"
#include "lamina/spectral/color_space.h"

namespace lamina {
namespace {

TEST(Cie, TablesAreReadFromColord) {
    EXPECT_NEAR(cieY(555.0), 1.0, 1e-6);  // y-bar peaks at 555 nm with value 1
    EXPECT_NEAR(cieX(600.0), 1.0622, 1e-6);
    EXPECT_NEAR(cieY(557.5), 0.5 * (cieY(555.0) + cieY(560.0)), 1e-12);  // linear in between
    EXPECT_EQ(cieY(300.0), 0.0);
    EXPECT_EQ(cieY(900.0), 0.0);
    EXPECT_NEAR(cieYIntegral(), 106.857, 0.01);
    for (const char* name : {"A", "D50", "D65", "E", "F2", "F11"})
        EXPECT_NE(findCieIlluminant(name), nullptr) << name;
    EXPECT_EQ(findCieIlluminant("D66"), nullptr);
}

TEST(Cie, XyzIsTheThreeFunctionsExactly) {
    // cieXyz shares one table position among the three functions: bit for bit the same as
    // looking each up, at knots, between them, at both ends and outside the range.
    for (double nm : {300.0, 359.999, 360.0, 360.1, 412.5, 555.0, 557.3, 700.01, 829.9, 830.0,
                      830.001, 900.0}) {
        const Vec3d xyz = cieXyz(nm);
        EXPECT_EQ(xyz.x, cieX(nm)) << nm;
        EXPECT_EQ(xyz.y, cieY(nm)) << nm;
        EXPECT_EQ(xyz.z, cieZ(nm)) << nm;
    }
    for (double nm = kLambdaMin; nm <= kLambdaMax; nm += 0.37) {
        const Vec3d xyz = cieXyz(nm);
        ASSERT_EQ(xyz.x, cieX(nm)) << nm;
        ASSERT_EQ(xyz.y, cieY(nm)) << nm;
        ASSERT_EQ(xyz.z, cieZ(nm)) << nm;
    }
    EXPECT_GT(cieXyz(830.0).x, 0.0);  // the last knot is inside
}

TEST(Cie, D65IntegratesToItsWhitePoint) {
    const Vec3d w = d65WhiteXyz();
    EXPECT_NEAR(w.x, 0.9505, 1e-3);
    EXPECT_NEAR(w.y, 1.0, 1e-12);
    EXPECT_NEAR(w.z, 1.0890, 1e-3);
    // Chromaticity of CIE D65: (0.3127, 0.3290) (CIE 015:2018).
    EXPECT_NEAR(w.x / (w.x + w.y + w.z), 0.3127, 1e-4);
    EXPECT_NEAR(w.y / (w.x + w.y + w.z), 0.3290, 1e-4);
}

TEST(ColorSpace, Rec709MatricesRoundTripAndMapWhite) {
    const RgbColorSpace& cs = RgbColorSpace::rec709();
    const Mat3<double> identity = cs.xyzToRgb() * cs.rgbToXyz();
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            EXPECT_NEAR(identity[c][r], c == r ? 1.0 : 0.0, 1e-6);
    const Vec3d white = cs.toRgb(d65WhiteXyz());
    EXPECT_NEAR(white.x, 1.0, 1e-12);
    EXPECT_NEAR(white.y, 1.0, 1e-12);
    EXPECT_NEAR(white.z, 1.0, 1e-12);
    // The Y row is Rec.709 luminance (0.2126, 0.7152, 0.0722) to 4 digits.
    EXPECT_NEAR(cs.rgbToXyz()[0][1], 0.2126, 1e-4);
    EXPECT_NEAR(cs.rgbToXyz()[1][1], 0.7152, 1e-4);
    EXPECT_NEAR(cs.rgbToXyz()[2][1], 0.0722, 1e-4);
    // Each primary lands on its chromaticity.
    const Vec3d red = cs.toXyz(Vec3d(1, 0, 0));
    EXPECT_NEAR(red.x / (red.x + red.y + red.z), 0.64, 1e-9);
    EXPECT_NEAR(red.y / (red.x + red.y + red.z), 0.33, 1e-9);
}

}  // namespace
}  // namespace lamina
