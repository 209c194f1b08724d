// The 1 nm n/k table (nk_table.h) against direct evaluation of the spectrum it tabulates:
// every Lorentz-Drude metal and the measured Johnson-Christy tables, at wavelengths between
// the samples (0.1 nm apart over the whole range), in n, k and in the exact conductor Fresnel
// reflectance that spectral mode computes from them.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "lamina/core/fresnel_equations.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/nk_table.h"

namespace lamina {
namespace {

namespace fs = std::filesystem;

struct Deviation {
    double index = 0;        ///< max |(n, k)_table - (n, k)| / |n + i k|
    double reflectance = 0;  ///< max |R_table - R| over cos theta in {1, 1/7, 0.02}
};

Deviation deviation(const std::shared_ptr<const IorSpectrum>& ior) {
    const NkTable table(ior);
    Deviation d;
    for (int i = 0; i <= 4700; ++i) {
        const double nm = kLambdaMin + 0.1 * i;
        const NkTable::Nk t = table(nm);
        const double n = ior->n(nm), k = ior->k(nm);
        d.index = std::max(d.index, std::hypot(t.n - n, t.k - k) / std::hypot(n, k));
        for (double c : {1.0, 1.0 / 7.0, 0.02})
            d.reflectance = std::max(
                d.reflectance, std::abs(fresnelConductor(c, t.n, t.k) - fresnelConductor(c, n, k)));
    }
    return d;
}

TEST(NkTable, ExactAtTheSamples) {
    const auto ior = std::make_shared<const IorSpectrum>(*namedIor("Au"));
    const NkTable table(ior);
    for (double nm = kLambdaMin; nm <= kLambdaMax; nm += 1.0) {
        EXPECT_EQ(table(nm).n, ior->n(nm)) << nm;
        EXPECT_EQ(table(nm).k, ior->k(nm)) << nm;
    }
}

// Lorentz-Drude curves are smooth: 1 nm linear interpolation is within 5e-5 of the index
// (relative) and 5e-5 of the reflectance (measured: at most 2.3e-5 and 2.6e-5, for silver,
// whose plasma edge lies just below 360 nm; below 1.5e-5 for the other ten metals).
TEST(NkTable, LorentzDrudeMetalsWithinTolerance) {
    int fits = 0;
    for (const std::string& metal : namedMetalNames()) {
        if (!metal.ends_with("_LD")) continue;  // the fits; the plain symbols are measured
        ++fits;
        const Deviation d = deviation(std::make_shared<const IorSpectrum>(*namedIor(metal)));
        EXPECT_LT(d.index, 5e-5) << metal;
        EXPECT_LT(d.reflectance, 5e-5) << metal;
    }
    EXPECT_EQ(fits, 11);
}

// A measured table's knots that fall between the 1 nm samples have their kinks cut off:
// within 2e-3 of the index (relative) and 1e-3 of the reflectance (measured: 8.5e-4 and
// 4.1e-4 for Johnson and Christy's gold at its own wavelengths, the .yml file; the CSV twins
// in ../shared/data are given at whole nanometres and agree to rounding).
TEST(NkTable, MeasuredTablesWithinTolerance) {
    const fs::path dir = fs::path(LAMINA_SHARED_DIR) / "data" / "nk";
    if (!fs::is_directory(dir)) GTEST_SKIP() << dir.string() << " is absent";
    for (const char* file :
         {"Au_JohnsonChristy1972.csv", "Ag_JohnsonChristy1972.csv", "Cu_JohnsonChristy1972.csv",
          "Cr_JohnsonChristy1974.csv", "Al_McPeak2015.yml", "Al_Rakic1995.yml",
          "Au_JohnsonChristy1972.yml"}) {
        const Deviation d = deviation(std::make_shared<const IorSpectrum>(loadIorFile(dir / file)));
        EXPECT_LT(d.index, 2e-3) << file;
        EXPECT_LT(d.reflectance, 1e-3) << file;
    }
}

TEST(NkTable, OutsideTheRangeEvaluatesTheSpectrum) {
    const auto ior = std::make_shared<const IorSpectrum>(*namedIor("Cu"));
    const NkTable table(ior);
    EXPECT_EQ(table(300.0).n, ior->n(300.0));
    EXPECT_EQ(table(900.5).k, ior->k(900.5));
}

}  // namespace
}  // namespace lamina
