// Figures that stand alone: `bsdf plot` and `spectrum --plot` are SVG figures, the fresnel
// swatches a figure spec for the figure module, whose title names what is drawn (material,
// mode), whose axes are named with units and carry tick values, and whose series or rows are
// named.
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
    // `svg` holds `text` as the whole content of one <text> element.
    static bool hasText(const std::string& svg, const std::string& text) {
        return svg.find(">" + text + "</text>") != std::string::npos;
    }
};

TEST_F(FigureLabels, BsdfPlotPanelsNameTheirAxesWithUnitsAndTheMaterial) {
    const std::string material = R"('{"type":"conductor","material":"Au","alpha":0.2}')";
    const fs::path out = dir_ / "gold.svg";
    const CommandRun r =
        runLamina("bsdf plot " + material + " --mode spectral --wo 0.6,0,0.8 -o " + out.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const std::string plane = read(out);
    const std::string hemisphere = read(dir_ / "gold-hemisphere.svg");
    ASSERT_FALSE(plane.empty());
    ASSERT_FALSE(hemisphere.empty());
    EXPECT_TRUE(fs::exists(dir_ / "gold-hemisphere.png"));
    for (const std::string* svg : {&plane, &hemisphere}) {
        EXPECT_NE(svg->find("conductor"), std::string::npos);  // the material ...
        EXPECT_NE(svg->find("spectral mode, 450,550,650 nm"), std::string::npos);  // ... the mode
        EXPECT_NE(svg->find("wo = (0.6, 0, 0.8)"), std::string::npos);
    }
    EXPECT_TRUE(hasText(plane, "theta_i from the normal, towards (1, 0, 0) (degrees)"));
    EXPECT_TRUE(hasText(plane, "f cos theta_i (1/sr)"));
    EXPECT_TRUE(hasText(plane, "wo (theta_o = 36.87 deg)"));
    EXPECT_TRUE(hasText(plane, "mirror direction"));
    for (const char* tick : {"-100", "0", "100"})
        EXPECT_TRUE(hasText(plane, tick)) << tick;
    EXPECT_TRUE(hasText(hemisphere, "wi.x (direction cosine)"));
    EXPECT_TRUE(hasText(hemisphere, "wi.y (direction cosine)"));
    EXPECT_TRUE(hasText(hemisphere, "f cos theta_i (1/sr)"));  // the colour bar
    EXPECT_TRUE(hasText(hemisphere, "0.5"));
}

TEST_F(FigureLabels, BsdfPlotRefusesAnOutputThatIsNotSvgBeforeWriting) {
    const CommandRun r = runLamina(R"(bsdf plot '{"type":"lambert"}' --wo 0,0,1 -o )" +
                                   (dir_ / "lobe.png").string());
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("expected a .svg file name"), std::string::npos) << r.output;
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

TEST_F(FigureLabels, SpectrumPlotIsTheSvgPlotWithAxesAndNamedCurves) {
    const fs::path metal = dir_ / "Au.svg", light = dir_ / "D65.svg";
    const CommandRun a = runLamina("spectrum Au --plot " + metal.string());
    const CommandRun b = runLamina("spectrum D65 --plot " + light.string());
    ASSERT_EQ(a.exitCode, 0) << a.output;
    ASSERT_EQ(b.exitCode, 0) << b.output;
    const std::string au = read(metal), d65 = read(light);
    EXPECT_TRUE(hasText(au, "wavelength (nm)"));
    EXPECT_TRUE(hasText(au, "refractive index n, extinction coefficient k (dimensionless)"));
    EXPECT_TRUE(hasText(au, "n"));  // the legend
    EXPECT_TRUE(hasText(au, "k"));
    for (const char* tick : {"400", "600", "800"})
        EXPECT_TRUE(hasText(au, tick)) << tick;
    EXPECT_TRUE(hasText(d65, "CIE illuminant D65"));
    EXPECT_TRUE(hasText(d65, "relative spectral power (dimensionless)"));
    const CommandRun png = runLamina("spectrum Au --plot " + (dir_ / "Au.png").string());
    EXPECT_EQ(png.exitCode, 2) << png.output;
    EXPECT_FALSE(fs::exists(dir_ / "Au.png"));
}

}  // namespace
}  // namespace lamina
