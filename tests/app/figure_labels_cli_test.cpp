// Figures that stand alone: `bsdf plot`, `spectrum --plot` and the fresnel swatches are figure
// specs for the figure module (drawn as PNG and PDF), whose title names what is drawn
// (material, mode), whose axes are named with units, and whose series or rows are named.
// tests/python/test_figures.py checks the drawn figures.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "cli_helpers.h"

namespace lamina {
namespace {

class FigureLabels : public CliTest {
  protected:
    static std::string read(const fs::path& file) {
        std::ifstream in(file);
        std::stringstream s;
        s << in.rdbuf();
        return s.str();
    }
    // The spec holds `text` as one JSON string.
    static bool hasText(const std::string& spec, const std::string& text) {
        return spec.find("\"" + text + "\"") != std::string::npos;
    }
};

TEST_F(FigureLabels, BsdfPlotPanelsNameTheirAxesWithUnitsAndTheMaterial) {
    const std::string material = R"('{"type":"conductor","material":"Au","alpha":0.2}')";
    const fs::path out = dir_ / "gold.png";
    const CommandRun r =
        runLamina("bsdf plot " + material + " --mode spectral --wo 0.6,0,0.8 -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string plane = read(dir_ / "gold.figure.json");
    const std::string hemisphere = read(dir_ / "gold-hemisphere.figure.json");
    ASSERT_FALSE(plane.empty());
    ASSERT_FALSE(hemisphere.empty());
    EXPECT_TRUE(fs::exists(dir_ / "gold-hemisphere.f32"));
    for (const std::string* spec : {&plane, &hemisphere}) {
        EXPECT_NE(spec->find("conductor"), std::string::npos);  // the material ...
        EXPECT_NE(spec->find("spectral mode, 450,550,650 nm"), std::string::npos);  // ... the mode
        EXPECT_NE(spec->find("wo = (0.6, 0, 0.8)"), std::string::npos);
    }
    EXPECT_TRUE(hasText(plane, "theta_i from the normal, towards (1, 0, 0) (degrees)"));
    EXPECT_TRUE(hasText(plane, "f cos theta_i (1/sr)"));
    EXPECT_TRUE(hasText(plane, "wo (theta_o = 36.87 deg)"));
    EXPECT_TRUE(hasText(plane, "mirror direction"));
    EXPECT_TRUE(hasText(hemisphere, "wi.x (direction cosine)"));
    EXPECT_TRUE(hasText(hemisphere, "wi.y (direction cosine)"));
    EXPECT_TRUE(hasText(hemisphere, "f cos theta_i"));  // the colour bar: quantity ...
    EXPECT_TRUE(hasText(hemisphere, "1/sr"));           // ... and unit
}

TEST_F(FigureLabels, BsdfPlotRefusesAnOutputThatIsNotPngBeforeWriting) {
    const CommandRun r = runLamina(R"(bsdf plot '{"type":"lambert"}' --wo 0,0,1 -o )" +
                                   (dir_ / "lobe.svg").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("expected a .png file name"), std::string::npos) << r.output;
    EXPECT_EQ(filesIn(), 0u);
}

TEST_F(FigureLabels, FresnelSwatchesNameTheMaterialTheModelsAndTheirMode) {
    // The figure module draws the swatches from this spec (tests/python/test_figures.py checks
    // the drawn figures); the spec holds every name the figure shows.
    const CommandRun r = runLamina("fresnel Cu -o " + dir_.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string spec = read(dir_ / "Cu_swatches.figure.json");
    ASSERT_FALSE(spec.empty());
    const auto has = [&spec](const std::string& text) {
        return spec.find("\"" + text + "\"") != std::string::npos;
    };
    EXPECT_NE(spec.find("Fresnel reflectance of Cu"), std::string::npos);
    EXPECT_TRUE(has("swatches"));
    EXPECT_TRUE(has("angle of incidence (degrees)"));
    EXPECT_TRUE(has("model"));
    EXPECT_TRUE(has("exact (spectral)"));
    EXPECT_TRUE(has("Schlick (RGB mode)"));
    EXPECT_TRUE(has("Hoffman F82 (RGB mode)"));
    for (const char* angle : {"0", "30", "60", "75", "82", "87"})
        EXPECT_TRUE(has(angle)) << angle;
    EXPECT_NE(read(dir_ / "summary.md").find("Cu_swatches.png"), std::string::npos);
}

TEST_F(FigureLabels, SpectrumPlotIsAFigureWithAxesAndNamedCurves) {
    const fs::path metal = dir_ / "Au.png", light = dir_ / "D65.png";
    const CommandRun a = runLamina("spectrum Au --plot " + metal.string());
    const CommandRun b = runLamina("spectrum D65 --plot " + light.string());
    ASSERT_EQ(a.exitCode, 0) << a.output;
    ASSERT_EQ(b.exitCode, 0) << b.output;
    const std::string au = read(dir_ / "Au.figure.json"), d65 = read(dir_ / "D65.figure.json");
    EXPECT_TRUE(hasText(au, "wavelength (nm)"));
    EXPECT_TRUE(hasText(au, "refractive index n, extinction coefficient k (dimensionless)"));
    EXPECT_TRUE(hasText(au, "n"));  // the legend
    EXPECT_TRUE(hasText(au, "k"));
    EXPECT_TRUE(hasText(d65, "CIE illuminant D65"));
    EXPECT_TRUE(hasText(d65, "relative spectral power (dimensionless)"));
    const CommandRun svg = runLamina("spectrum Au --plot " + (dir_ / "Au.svg").string());
    EXPECT_EQ(svg.exitCode, 2) << svg.output;
    EXPECT_FALSE(fs::exists(dir_ / "Au.svg"));
}

}  // namespace
}  // namespace lamina
