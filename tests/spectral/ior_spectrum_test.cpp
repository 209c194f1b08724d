// n/k data: the Lorentz-Drude model against its published tables, the refractiveindex.info
// YAML loader against the CSV twins, the exact conductor Fresnel of loaded gold against an
// independent computation, the RGB reductions, and clear errors for bad files. Tests that
// need ../shared/data skip with a message when it is absent.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <complex>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "lamina/core/error.h"
#include "lamina/core/fresnel_equations.h"
#include "lamina/spectral/color_difference.h"
#include "lamina/spectral/ior_spectrum.h"

namespace lamina {
namespace {

namespace fs = std::filesystem;

fs::path nkDir() {
    return fs::path(LAMINA_SHARED_DIR) / "data" / "nk";
}

#define REQUIRE_SHARED_DATA()                                           \
    if (!fs::is_directory(nkDir()))                                     \
    GTEST_SKIP() << "../shared/data/nk is absent (" << nkDir().string() \
                 << "): the n/k data tests need the shared folder beside the clone"

struct Row {
    double nm, n, k;
};

std::vector<Row> readCsv(const fs::path& p) {
    std::ifstream in(p);
    std::vector<Row> rows;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#' || line[0] == 'l') continue;
        Row r{};
        if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &r.nm, &r.n, &r.k) == 3) rows.push_back(r);
    }
    return rows;
}

// The rows of a refractiveindex.info "tabulated nk" block (wavelength in um, n, k).
std::vector<Row> readYamlRows(const fs::path& p) {
    std::ifstream in(p);
    std::vector<Row> rows;
    std::string line;
    while (std::getline(in, line)) {
        Row r{};
        char extra;
        if (std::sscanf(line.c_str(), " %lf %lf %lf %c", &r.nm, &r.n, &r.k, &extra) == 3) {
            r.nm *= 1000;
            rows.push_back(r);
        }
    }
    return rows;
}

TEST(LorentzDrude, MatchesRakicTables) {
    REQUIRE_SHARED_DATA();
    for (const std::string metal : {"Ag", "Au", "Cu", "Al"}) {
        // At the database's own sample wavelengths the model must agree within 1e-3 (the
        // samples carry 5 significant digits).
        const auto samples = readYamlRows(nkDir() / (metal + "_Rakic1998_LD.yml"));
        ASSERT_GT(samples.size(), 20u) << metal;
        for (const Row& r : samples) {
            const auto nk = lorentzDrudeIndex(metal, r.nm);
            EXPECT_NEAR(nk.real(), r.n, 1e-3) << metal << " at " << r.nm << " nm";
            EXPECT_NEAR(nk.imag(), r.k, 1e-3) << metal << " at " << r.nm << " nm";
        }
        // The 5 nm CSV twin interpolates those samples linearly (about 6 nm apart), which
        // adds up to ~2.3e-3 where the curves bend (Au near 420 nm, Cu near 350-400 nm): 3e-3.
        const auto rows = readCsv(nkDir() / (metal + "_Rakic1998_LD.csv"));
        ASSERT_GT(rows.size(), 90u) << metal;
        for (const Row& r : rows) {
            const auto nk = lorentzDrudeIndex(metal, r.nm);
            EXPECT_NEAR(nk.real(), r.n, 3e-3) << metal << " at " << r.nm << " nm";
            EXPECT_NEAR(nk.imag(), r.k, 3e-3) << metal << " at " << r.nm << " nm";
        }
    }
}

TEST(LorentzDrude, EveryNamedMetalIsAPlausibleConductor) {
    for (const auto& name : namedMetalNames()) {
        const auto ior = namedIor(name);
        ASSERT_TRUE(ior) << name;
        for (double nm = 360; nm <= 830; nm += 10) {
            EXPECT_GT(ior->n(nm), 0.0) << name;
            EXPECT_GT(ior->k(nm), 1.0) << name;  // metals absorb strongly in the visible
        }
    }
}

TEST(IorFiles, EveryYamlFileMatchesItsCsvTwin) {
    REQUIRE_SHARED_DATA();
    int files = 0;
    for (const auto& entry : fs::directory_iterator(nkDir())) {
        if (entry.path().extension() != ".yml") continue;
        const fs::path csv = fs::path(entry.path()).replace_extension(".csv");
        if (!fs::exists(csv)) continue;
        const IorSpectrum yaml = loadIorFile(entry.path());
        const IorSpectrum table = loadIorFile(csv);
        for (const Row& r : readCsv(csv)) {
            // The CSV twins carry 6 significant digits.
            EXPECT_NEAR(yaml.n(r.nm), r.n, 1e-5 + 2e-5 * std::abs(r.n))
                << entry.path().filename() << " at " << r.nm << " nm";
            EXPECT_NEAR(yaml.k(r.nm), r.k, 1e-5 + 2e-5 * std::abs(r.k))
                << entry.path().filename() << " at " << r.nm << " nm";
            EXPECT_NEAR(table.n(r.nm), r.n, 1e-12);
        }
        ++files;
    }
    EXPECT_GE(files, 20);
}

// The Fresnel equations for a conductor written independently of lamina's real-arithmetic
// form: complex Snell's law and the amplitude coefficients r_s, r_p (Born and Wolf, 14.2).
double independentConductorFresnel(double cosI, std::complex<double> eta) {
    using C = std::complex<double>;
    const double sin2I = 1 - cosI * cosI;
    const C cosT = std::sqrt(C(1.0) - sin2I / (eta * eta));
    const C rs = (cosI - eta * cosT) / (cosI + eta * cosT);
    const C rp = (eta * cosI - cosT) / (eta * cosI + cosT);
    return 0.5 * (std::norm(rs) + std::norm(rp));
}

TEST(IorFiles, GoldFresnelMatchesAnIndependentComputation) {
    REQUIRE_SHARED_DATA();
    const IorSpectrum au = loadIorFile(nkDir() / "Au_JohnsonChristy1972.yml");
    for (double nm : {400.0, 450.0, 550.0, 650.0, 750.0})
        for (double degrees : {0.0, 45.0, 80.0, 89.0}) {
            const double c = std::cos(degrees * kPi<double> / 180);
            const double expected = independentConductorFresnel(c, {au.n(nm), au.k(nm)});
            EXPECT_NEAR(fresnelConductor(c, au.n(nm), au.k(nm)), expected, 1e-9)
                << nm << " nm, " << degrees << " degrees";
        }
}

TEST(IorReductions, GoldIsYellowAndSilverIsNeutralInRgbMode) {
    const auto [auF0, auF82] = conductorF0F82(*namedIor("Au"));
    EXPECT_GT(auF0[0], auF0[1]);
    EXPECT_GT(auF0[1], auF0[2]);
    EXPECT_GT(auF82[2], auF0[2]);  // reflectance rises towards grazing
    const auto [agF0, agF82] = conductorF0F82(*namedIor("Ag"));
    // The LD fit makes silver slightly darker in the blue (R0 0.919 at 450 nm, LD.md).
    EXPECT_NEAR(agF0[0], agF0[2], 0.06);
    EXPECT_GT(agF0[1], 0.9);
    (void)agF82;
}

TEST(IorFiles, DispersiveGlassesFollowTheirFormulas) {
    // N-BK7 at the d-line: nd = 1.5168 (SCHOTT data sheet).
    EXPECT_NEAR(namedIor("bk7")->n(kDLineNm), 1.5168, 1e-4);
    // Fused silica (Malitson 1965): 1.4585 at 587.6 nm.
    EXPECT_NEAR(namedIor("fused_silica")->n(kDLineNm), 1.4585, 1e-4);
    EXPECT_GT(namedIor("diamond")->n(450), namedIor("diamond")->n(650));
    EXPECT_NEAR(namedIor("water")->n(kDLineNm), 1.333, 1e-3);
}

class BadIorFile : public ::testing::Test {
  protected:
    fs::path write(const std::string& name, const std::string& text) {
        const fs::path p = fs::temp_directory_path() / ("lamina-ior-" + name);
        std::ofstream(p) << text;
        paths_.push_back(p);
        return p;
    }
    void TearDown() override {
        for (const auto& p : paths_)
            fs::remove(p);
    }
    static void expectError(const fs::path& p, const std::string& fragment) {
        try {
            loadIorFile(p);
            FAIL() << "accepted " << p;
        } catch (const InputError& e) {
            EXPECT_THAT(e.what(), ::testing::HasSubstr(p.filename().string()));
            EXPECT_THAT(e.what(), ::testing::HasSubstr(fragment));
        }
    }
    std::vector<fs::path> paths_;
};

TEST_F(BadIorFile, ErrorsNameTheFileAndTheProblem) {
    expectError(write("columns.csv", "nm,n,k\n400,1.5\n"), "line 2: expected three columns");
    expectError(write("order.csv", "400,1.5,0\n500,1.4,0\n450,1.3,0\n"),
                "row 3: wavelengths must increase");
    expectError(write("nan.csv", "400,1.5,0\n500,nan,0\n"), "row 2: value is not a finite");
    expectError(write("formula.yml", "DATA:\n  - type: formula 9\n    coefficients: 1 2 3\n"),
                "unsupported type");
    expectError(write("nodata.yml", "REFERENCES: x\n"), "no DATA list");
    expectError(write("missing.csv", ""), "needs at least two wavelengths");
    expectError(fs::path("/nonexistent/gold.yml"), "no such file");
}

// A negative n or k in a file is refused like an inline negative k.
TEST_F(BadIorFile, NegativeNOrKIsRefused) {
    expectError(write("negative-k.csv", "400,1.5,0\n500,1.4,-0.1\n"), "row 2: k is negative");
    expectError(write("negative-n.csv", "400,-1.5,0\n500,1.4,0\n"), "row 1: n is negative");
    expectError(write("negative-n.yml",
                      "DATA:\n  - type: tabulated nk\n    data: |\n      0.4 1.5 0\n"
                      "      0.5 -1.4 0\n"),
                "row 2: n is negative");
    expectError(write("negative-k.yml",
                      "DATA:\n  - type: tabulated k\n    data: |\n      0.4 1\n      0.5 -1\n"),
                "row 2: k is negative");
}

// A formula with a pole in 360-830 nm gave n = inf at the pole (fuzz regression
// formula-pole-at-500nm.bin) and n = 0 beside it.
TEST_F(BadIorFile, FormulaPolesInTheRenderedRangeAreRefused) {
    expectError(write("pole.yml", "DATA:\n  - type: formula 1\n    coefficients: 0 2 -0.5\n"),
                "DATA[0] (formula 1): the formula has a pole at 500");
    expectError(write("pole2.yml", "DATA:\n  - type: formula 2\n    coefficients: 0 1 0.36\n"),
                "the formula has a pole at 600");
    expectError(
        write("negative.yml", "DATA:\n  - type: formula 2\n    coefficients: -3 0.1 0.01\n"),
        "n^2 is not a positive number at 360");
}

// yaml-cpp throws on a subscript of a scalar, a map where a string belongs and bad syntax;
// each must become an InputError naming the file and the line, never escape (the fuzz
// regression yaml-data-on-a-scalar.bin aborted the fuzzer).
TEST_F(BadIorFile, YamlExceptionsBecomeInputErrors) {
    expectError(write("scalar.yml", "DATA:\n  - 1.03961212 0.006\n"), "malformed YAML at line");
    expectError(write("map-type.yml", "DATA:\n  - type: {a: 1}\n"), "malformed YAML at line 2");
    expectError(write("syntax.yml", "DATA: [\n"), "malformed YAML");
    const fs::path regression = fs::path(LAMINA_SOURCE_DIR) / "tests" / "fuzz" / "regressions" /
                                "ior_file" / "yaml-data-on-a-scalar.bin";
    std::ifstream in(regression, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(bytes.empty());
    // The fuzz target's first byte chooses the format (odd: YAML); the rest is the file.
    expectError(write("fuzz-regression.yml", bytes.substr(1)), "malformed YAML");
}

}  // namespace
}  // namespace lamina

namespace lamina {
namespace {

// The named metals are measured data: a named copper is Johnson and Christy's copper, not the
// Lorentz-Drude fit, whose F0 (0.95, 0.75, 0.48) is 13 CIEDE2000 from the measurement and
// about 5 from gold: a copper that rendered gold. The colours compared are the RGB-mode F0
// (conductorF0F82: the exact spectral Fresnel reflectance at normal incidence under D65).
TEST(NamedMetals, CopperIsMeasuredCopperNotGold) {
    REQUIRE_SHARED_DATA();
    const auto f0 = [](const IorSpectrum& ior) { return conductorF0F82(ior).first; };
    const Rgb<double> measured = f0(loadIorFile(nkDir() / "Cu_JohnsonChristy1972.yml"));
    const Rgb<double> named = f0(*namedIor("Cu"));
    EXPECT_LT(ciede2000Rec709(named, measured), 2.0);
    EXPECT_GT(ciede2000Rec709(named, f0(*namedIor("Au"))), 10.0);
    // The fit stays available under its own name, and is the colour the measurement refutes.
    EXPECT_GT(ciede2000Rec709(f0(*namedIor("Cu_LD")), measured), 10.0);
}

// Every measured named metal is its file in ../shared/data/nk (the refractiveindex.info tables
// the repository's spectral/data/nk copies), at every sample and between them.
TEST(NamedMetals, MeasuredMetalsAreTheirTables) {
    REQUIRE_SHARED_DATA();
    for (const auto& [metal, file] :
         std::vector<std::pair<std::string, std::string>>{{"Ag", "Ag_JohnsonChristy1972"},
                                                          {"Au", "Au_JohnsonChristy1972"},
                                                          {"Cu", "Cu_JohnsonChristy1972"},
                                                          {"Al", "Al_Rakic1995"},
                                                          {"Cr", "Cr_JohnsonChristy1974"},
                                                          {"Fe", "Fe_JohnsonChristy1974"},
                                                          {"Ni", "Ni_JohnsonChristy1974"},
                                                          {"Ti", "Ti_JohnsonChristy1974"},
                                                          {"Pt", "Pt_Tselin2024"},
                                                          {"W", "W_Weaver1975"},
                                                          {"Zn", "Zn_Werner2009"}}) {
        const IorSpectrum table = loadIorFile(nkDir() / (file + ".csv"));
        const IorSpectrum named = *namedIor(metal);
        for (double nm = 360; nm <= 830; nm += 2.5) {
            EXPECT_NEAR(named.n(nm), table.n(nm), 1e-12) << metal << " at " << nm;
            EXPECT_NEAR(named.k(nm), table.k(nm), 1e-12) << metal << " at " << nm;
        }
        EXPECT_NE(named.name().find("("), std::string::npos) << named.name();
    }
    EXPECT_EQ(namedIor("Cu")->name(), "Cu (Johnson and Christy 1972)");
    // Be and Pd have no measured table here: their plain names are the fits.
    EXPECT_EQ(namedIor("Pd")->name(), "Pd (Rakic 1998 Lorentz-Drude)");
}

}  // namespace
}  // namespace lamina
