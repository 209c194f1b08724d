// Colours upsampled in advance are the colours upsampled on demand, bit for bit, and the set
// stays bounded whatever it is asked to keep.
#include <gtest/gtest.h>

#include "lamina/spectral/cie.h"
#include "lamina/spectral/upsampled_colors.h"

namespace lamina {
namespace {

void expectSameSpectrum(const RgbSpectrum& a, const RgbSpectrum& b) {
    for (double nm = kLambdaMin; nm <= kLambdaMax; nm += 2.3)
        ASSERT_EQ(a(nm), b(nm)) << nm;
}

TEST(UpsampledColors, KeptColoursAreTheTableLookups) {
    UpsampledColors colors;
    const Rgb<double> floor(0.35, 0.35, 0.38), tint(1.2, 0.8, 0.3), grey(0.5);
    colors.keep(floor, RgbSpectrumKind::Reflectance);
    colors.keep(tint, RgbSpectrumKind::Unbounded);
    colors.keep(grey, RgbSpectrumKind::Reflectance);
    colors.keep(floor, RgbSpectrumKind::Reflectance);  // already kept
    EXPECT_EQ(colors.size(), 3u);
    expectSameSpectrum(colors.spectrum(floor, RgbSpectrumKind::Reflectance),
                       RgbSpectrum(floor, RgbSpectrumKind::Reflectance));
    expectSameSpectrum(colors.spectrum(tint, RgbSpectrumKind::Unbounded),
                       RgbSpectrum(tint, RgbSpectrumKind::Unbounded));
    expectSameSpectrum(colors.spectrum(grey, RgbSpectrumKind::Reflectance),
                       RgbSpectrum(grey, RgbSpectrumKind::Reflectance));
    // The kind is part of the key: the same triple as another kind, and a colour never kept,
    // are looked up in the table.
    expectSameSpectrum(colors.spectrum(floor, RgbSpectrumKind::Illuminant),
                       RgbSpectrum(floor, RgbSpectrumKind::Illuminant));
    const Rgb<double> other(0.1, 0.6, 0.2);
    expectSameSpectrum(colors.spectrum(other, RgbSpectrumKind::Reflectance),
                       RgbSpectrum(other, RgbSpectrumKind::Reflectance));
    EXPECT_EQ(colors.size(), 3u);
}

TEST(UpsampledColors, StaysBounded) {
    // A hundred different colours (what a textured material's builds would ask for).
    UpsampledColors colors;
    for (int i = 0; i < 100; ++i)
        colors.keep(Rgb<double>(0.01 * i, 0.3, 0.2), RgbSpectrumKind::Reflectance);
    EXPECT_EQ(colors.size(), UpsampledColors::kCapacity);
    // A full set still answers for colours it does not hold.
    const Rgb<double> c(0.7, 0.3, 0.2);
    expectSameSpectrum(colors.spectrum(c, RgbSpectrumKind::Reflectance),
                       RgbSpectrum(c, RgbSpectrumKind::Reflectance));
}

}  // namespace
}  // namespace lamina
