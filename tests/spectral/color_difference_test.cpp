// CIEDE2000 against the supplementary test data of Sharma, Wu and Dalal 2005 (Table 1),
// which exercise the hue-angle wrap-around and the blue-region rotation term.
#include <gtest/gtest.h>

#include "lamina/spectral/color_difference.h"

namespace lamina {
namespace {

struct Pair {
    Vec3d lab1, lab2;
    double expected;
};

TEST(Ciede2000, MatchesSharmaWuDalalTestData) {
    const Pair pairs[] = {
        {{50.0, 2.6772, -79.7751}, {50.0, 0.0, -82.7485}, 2.0425},
        {{50.0, 3.1571, -77.2803}, {50.0, 0.0, -82.7485}, 2.8615},
        {{50.0, 2.8361, -74.0200}, {50.0, 0.0, -82.7485}, 3.4412},
        {{50.0, -1.3802, -84.2814}, {50.0, 0.0, -82.7485}, 1.0000},
        {{50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}, 2.3669},
        {{50.0, 2.4900, -0.0010}, {50.0, -2.4900, 0.0009}, 7.1792},
        {{50.0, 2.5, 0.0}, {73.0, 25.0, -18.0}, 27.1492},
        {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
        {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373},
    };
    for (const Pair& p : pairs) {
        EXPECT_NEAR(ciede2000(p.lab1, p.lab2), p.expected, 1e-4);
        EXPECT_NEAR(ciede2000(p.lab2, p.lab1), p.expected, 1e-4);  // symmetric
    }
}

TEST(Ciede2000, WhiteIsLStar100AndIdenticalColoursDoNotDiffer) {
    EXPECT_NEAR(ciede2000Rec709(Rgb<double>(1.0), Rgb<double>(1.0)), 0.0, 1e-12);
    EXPECT_GT(ciede2000Rec709(Rgb<double>(0.5), Rgb<double>(0.52)), 0.3);
}

}  // namespace
}  // namespace lamina
