// Mitsuba 3 scenes imported (docs/interchange.md, "Mitsuba 3") render the same image as the
// same scene written by hand in lamina's format: each of tests/data/interchange/mitsuba/X.xml
// and X.json is rendered as 32 independent batches (1024 spp in all, 256 for the glass sphere
// whose image mean is less noisy: a standard error of the relative difference below 0.2%;
// independent sampler, fixed seeds, different for the two) and compared with Welch's t-test on
// 4x4-pixel blocks of the luminance at alpha = 0.01 (experiments/estimator_agreement.h). Pass: no
// more rejected blocks than chance allows (binomial p >= 0.001), the image means within three
// standard errors (p >= 0.0027) and within 0.5% of each other. Breaking the importer's max_depth
// mapping by one bounce fails the Cornell box on both counts. And the orientation: Mitsuba's
// camera has +x on the image's left.
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/experiments/estimator_agreement.h"
#include "lamina/interchange/scene_import.h"
#include "render_helpers.h"
#include "scratch_directory.h"
#include "source_files.h"

namespace lamina::render {
namespace {

std::string mitsubaData(const std::string& name) {
    return (testing::sourceFile("tests/data/interchange/mitsuba") / name).string();
}

struct AgreementCase {
    const char* name;
    int spp;
};

class MitsubaAgreement : public ::testing::TestWithParam<AgreementCase> {};

TEST_P(MitsubaAgreement, ImportedSceneRendersLikeTheHandWrittenOne) {
    const std::string name = GetParam().name;
    const SceneDesc imported = loadScene(mitsubaData(name + ".xml"));
    const SceneDesc reference = loadScene(mitsubaData(name + ".json"));
    EXPECT_EQ(imported.format, SceneFormat::Mitsuba);
    RenderOptions o;
    o.seed = 1;
    const auto a = experiments::renderBatches(imported, o, GetParam().spp, 32);
    o.seed = 2;
    const auto b = experiments::renderBatches(reference, o, GetParam().spp, 32);
    experiments::AgreementTest test;
    test.alpha = 0.01;
    test.blockSize = 4;
    const auto r = experiments::testAgreement(a, b, test);
    std::printf("  %s: blocks %.2f%% rejected of %d; mean rel. diff %+.4f +- %.4f\n", name.c_str(),
                100 * r.blockRejectionRate(), r.blocksTested, r.relativeDifference,
                r.standardError);
    EXPECT_GE(r.blocksTested, 60);
    // The number of rejected blocks is binomial(blocks, alpha) when the images agree.
    EXPECT_GE(r.blockRejectionPValue(test.alpha), 0.001);
    EXPECT_GE(r.meanPValue, 0.0027);
    EXPECT_LT(std::abs(r.relativeDifference), 0.005);
}

// instances.xml (a shapegroup placed by instances) against instances.json, which writes the
// same placements as lamina objects and instances; principled.xml (Mitsuba's principled at
// metallic 1, which becomes lamina's standard) against conductors with Schlick's Fresnel.
INSTANTIATE_TEST_SUITE_P(Scenes, MitsubaAgreement,
                         ::testing::Values(AgreementCase{"cbox", 1024}, AgreementCase{"glass", 256},
                                           AgreementCase{"metals", 1024},
                                           AgreementCase{"instances", 256},
                                           AgreementCase{"principled", 1024}),
                         [](const ::testing::TestParamInfo<AgreementCase>& p) {
                             return std::string(p.param.name);
                         });

using MitsubaOrientation = lamina::testing::ScratchDirectoryTest;

TEST_F(MitsubaOrientation, CameraXIsTheImageLeftAndYIsUp) {
    // The camera at the origin looks along +z; one small emitter at +x, +y: in Mitsuba it is
    // in the image's top-left quarter (mitsuba3 perspective.cpp flips camera x onto the film).
    const auto file = write("orientation.xml", R"(<scene version="3.0.0">
  <sensor type="perspective">
    <float name="fov" value="60"/>
    <transform name="to_world"><lookat origin="0, 0, 0" target="0, 0, 1" up="0, 1, 0"/></transform>
    <film type="hdrfilm"><integer name="width" value="32"/><integer name="height" value="32"/>
      <rfilter type="box"/></film>
  </sensor>
  <shape type="rectangle">
    <transform name="to_world">
      <scale value="0.5"/><rotate y="1" angle="180"/><translate x="1.5" y="1" z="5"/>
    </transform>
    <emitter type="area"><rgb name="radiance" value="10"/></emitter>
  </shape>
</scene>)");
    const SceneDesc scene = loadScene(file);
    RenderOptions o;
    o.spp = 16;
    const RenderResult result = renderScene(scene, o);
    double quarter[2][2] = {{0, 0}, {0, 0}};  // [top][left]
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            quarter[y < 16][x < 16] += result.film->pixel(x, y)[1];
    std::printf("  top-left %.3f, top-right %.3f, bottom-left %.3f, bottom-right %.3f\n",
                quarter[1][1], quarter[1][0], quarter[0][1], quarter[0][0]);
    EXPECT_GT(quarter[1][1], 1.0);
    EXPECT_EQ(quarter[1][0], 0.0);
    EXPECT_EQ(quarter[0][1], 0.0);
    EXPECT_EQ(quarter[0][0], 0.0);
}

}  // namespace
}  // namespace lamina::render
