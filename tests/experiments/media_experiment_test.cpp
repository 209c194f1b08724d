// `lamina media` (media.h) on short runs of small scenes written here: a sphere of absorbing and
// scattering medium behind an index-matched boundary, seen through its middle against a white
// lamp that fills the view.
//
// - The physics of RGB against spectral mode: with a grey medium (the same coefficients in every
//   channel and at every wavelength) the two modes render the same image but for noise, so the
//   differences must stay within their noise floors (not resolved); with a strongly chromatic
//   medium (extinction 0.1, 2 and 4 per unit in R, G and B, upsampled to a smooth spectrum in
//   spectral mode) a channel's transmittance exp(-sigma_t d) differs from the band's average of
//   exp(-sigma_t(lambda) d), and every statistic must be resolved above its floor.
// - Spectral MIS against the hero's density alone: with a grey medium the two are the same
//   estimator (every channel's density is the hero's), so their images are identical; with a
//   chromatic one both are unbiased (the blockwise Welch test of their images is in tests/render/
//   media_agreement_test.cpp, MediaSpectralMis) and spectral MIS has the smaller relMSE against
//   the reference, by more than three standard errors of the difference. That medium's
//   extinctions (1.2, 1.8 and 2.2) are within a factor 2 of each other: the hero-only weight of
//   a channel c, T_c / T_h along a flight of density sigma_h T_h, has a finite variance only
//   when sigma_c > sigma_h / 2 for every pair, and a relMSE's standard error means something only
//   then (the strongly chromatic medium's hero-only relMSE is 50 times spectral MIS's, but with
//   an infinite variance behind it).
// - The reference's premises: a given reference of RGB mode or of another resolution is refused
//   before anything is rendered, naming the premise.
// - Resume: interrupted at its second render, the experiment keeps the first; the resumed run
//   takes it back and reports the numbers of an uninterrupted run exactly.
// Fixed seeds (the scenes'); "resolved" is the experiment's own reading (twice its floor).
// Broken once each (see the report of the change): the floor computed from the first pair twice
// (so 0) makes the grey medium "resolved"; spectral MIS weighting by channel 0's density instead of
// the hero's makes the chromatic medium's relMSE comparison and the Welch test fail; a resume
// that does not take its renders back fails the resume test.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/experiments/kept_renders.h"
#include "lamina/experiments/media.h"
#include "lamina/output/image_output.h"
#include "lamina/output/render_metadata.h"
#include "scratch_directory.h"

namespace lamina::experiments {
namespace {

using ::testing::HasSubstr;

/// The sphere of medium (radius 1, seen through its diameter by a narrow camera) in front of a
/// lamp of radiance 1 that fills the view.
std::string sphereScene(const std::string& sigmaA, const std::string& sigmaS) {
    return R"({
      "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 12},
      "film": {"resolution": [12, 12]},
      "integrator": {"max_depth": 16},
      "sampler": {"spp": 64},
      "media": {"m": {"type": "homogeneous", "sigma_a": )" +
           sigmaA + R"(, "sigma_s": )" + sigmaS + R"(, "g": 0.3}},
      "materials": {"lamp": {"type": "lambert", "reflectance": 0}},
      "shapes": [
        {"type": "sphere", "radius": 1, "material": "interface", "interior": "m"},
        {"type": "rectangle", "material": "lamp", "emission": {"radiance": 1},
         "transform": [{"scale": 3}, {"rotate": {"axis": [0, 1, 0], "angle": 180}},
                       {"translate": [0, 0, 2]}]}]})";
}

class MediaExperiment : public lamina::testing::ScratchDirectoryTest {
  protected:
    MediaResult run(const std::string& name, const std::string& sigmaA, const std::string& sigmaS,
                    int size = 12) {
        MediaInputs in;
        in.scenes = {write(name, sphereScene(sigmaA, sigmaS)).string()};
        in.overrides.resolution = std::make_pair(size, size);
        in.referenceSpp = 256;  // its noise adds to both relMSEs alike
        return runMedia(in);
    }
};

bool resolved(const FlooredStatistic& s, int spp) {
    return readAgainstFloor(s.value, s.floor, spp).resolved;
}

TEST_F(MediaExperiment, AGreyMediumIsTheSameInRgbAndSpectralMode) {
    const MediaResult r = run("grey.json", "0.4", "0.8");
    ASSERT_EQ(r.scenes.size(), 1u);
    const MediaSceneResult& s = r.scenes[0];
    EXPECT_EQ(s.comparedPixels, 144u);
    for (const FlooredStatistic* f :
         {&s.relative.mean, &s.relative.p95, &s.ciede2000.mean, &s.ciede2000.p95})
        EXPECT_FALSE(resolved(*f, s.spp)) << f->value << " against a floor of " << f->floor;
    // The floor is of the noise that is there: spectral mode's colour noise.
    EXPECT_GT(s.relative.mean.floor, 0.0);
    // Without spectral MIS the same estimator: the hero's density is every channel's.
    EXPECT_EQ(s.heroOnly.metrics.relmse, s.spectralMis.metrics.relmse);
    EXPECT_EQ(filmImage(*s.heroOnly.render.film).pixels,
              filmImage(*s.spectralMis.render.film).pixels);
}

TEST_F(MediaExperiment, AChromaticMediumDiffersBetweenRgbAndSpectralModeAboveTheFloor) {
    const MediaResult r = run("chromatic.json", "[0.05, 1, 2]", "[0.05, 1, 2]");
    const MediaSceneResult& s = r.scenes[0];
    for (const FlooredStatistic* f :
         {&s.relative.mean, &s.relative.p95, &s.ciede2000.mean, &s.ciede2000.p95})
        EXPECT_TRUE(resolved(*f, s.spp)) << f->value << " against a floor of " << f->floor;
    // A difference that is real shows in the second pair too.
    EXPECT_GT(s.relative.mean.otherSeed, 2 * s.relative.mean.floor);
}

TEST_F(MediaExperiment, SpectralMisHasTheSmallerErrorThroughAChromaticMedium) {
    const MediaResult r = run("chromatic.json", "[0.6, 0.9, 1.1]", "[0.6, 0.9, 1.1]", 32);
    const MediaSceneResult& s = r.scenes[0];
    // The smaller error at the same samples, beyond the noise of the two relMSEs.
    const ImageMetrics& mis = s.spectralMis.metrics;
    const ImageMetrics& hero = s.heroOnly.metrics;
    const double se = std::hypot(mis.relmseStandardError, hero.relmseStandardError);
    EXPECT_GT(hero.relmse - mis.relmse, 3 * se) << hero.relmse << " against " << mis.relmse;
    EXPECT_GT(s.spectralMis.efficiency, 0.0);
    // A rendered reference: self-rendered (flagged), its noise measured.
    ASSERT_GE(s.premises.size(), 2u);
    EXPECT_EQ(s.premises.front().check, "reference");
    EXPECT_EQ(s.premises.back().check, "reference noise");
    EXPECT_NE(s.premises.back().outcome, PremiseOutcome::NotChecked) << s.premises.back().detail;
    EXPECT_EQ(s.referenceSpp, 256);
}

TEST_F(MediaExperiment, AReferenceOfAnotherModeOrSizeIsRefusedBeforeRendering) {
    MediaInputs in;
    in.scenes = {write("grey.json", sphereScene("0.4", "0.8")).string()};
    const auto refusalFor = [&](const std::string& options) {
        const std::filesystem::path ref = dir_ / "ref.exr";
        render::SceneDesc scene = render::loadScene(in.scenes[0]);
        render::RenderOptions o;
        o.spp = 2;
        o.seed = 5;
        if (options == "rgb")
            o.mode = render::RenderModeKind::Rgb;
        else
            o.mode = render::RenderModeKind::Spectral;
        if (options == "size") o.resolution = std::make_pair(8, 8);
        const render::RenderResult rr = render::renderScene(scene, o);
        render::writeExr(ref, *rr.film, false, render::renderMetadata(scene, o, rr, {}));
        in.reference = ref.string();
        std::string log;
        in.progress = [&](const std::string& text) { log += text; };
        const std::string message = lamina::testing::errorOf([&] { runMedia(in); });
        EXPECT_EQ(log, "") << "rendered before refusing";
        return message;
    };
    EXPECT_THAT(refusalFor("rgb"), HasSubstr("ref.exr: mode (refused): the reference was rendered "
                                             "with mode rgb, the measured renders use spectral"));
    EXPECT_THAT(refusalFor("size"),
                HasSubstr("ref.exr: resolution (refused): the reference is 8x8, the measured "
                          "renders 12x12"));
}

TEST_F(MediaExperiment, ResumesFromItsKeptRendersWithTheSameNumbers) {
    MediaInputs in;
    in.scenes = {write("chromatic.json", sphereScene("[0.05, 1, 2]", "[0.05, 1, 2]")).string()};
    in.spp = 4;
    in.keepDirectory = dir_ / "whole";
    const MediaResult whole = runMedia(in);

    // Interrupted when the second render is announced (as SIGINT raises the flag).
    in.keepDirectory = dir_ / "interrupted";
    int announced = 0;
    in.progress = [&](const std::string& text) {
        if (text.rfind("rendering ", 0) == 0 && ++announced == 2)
            render::renderInterruptFlag().store(true);
    };
    std::string kept;
    try {
        runMedia(in);
        ADD_FAILURE() << "not interrupted";
    } catch (const Interrupted& stopped) {
        kept = stopped.kept;
    }
    render::renderInterruptFlag().store(false);
    EXPECT_THAT(kept, HasSubstr("renders/chromatic_spectral.exr"));

    in.resume = true;
    std::string log;
    in.progress = [&](const std::string& text) { log += text; };
    const MediaResult resumed = runMedia(in);
    EXPECT_THAT(log, HasSubstr("in spectral mode: kept from renders/chromatic_spectral.exr"));
    const MediaSceneResult &a = whole.scenes[0], &b = resumed.scenes[0];
    for (const auto& [u, v] : {std::pair{a.relative.mean, b.relative.mean},
                               {a.relative.p95, b.relative.p95},
                               {a.ciede2000.mean, b.ciede2000.mean},
                               {a.ciede2000.p95, b.ciede2000.p95}}) {
        EXPECT_EQ(u.value, v.value);
        EXPECT_EQ(u.floor, v.floor);
    }
    EXPECT_EQ(a.spectralMis.metrics.relmse, b.spectralMis.metrics.relmse);
    EXPECT_EQ(a.heroOnly.metrics.relmse, b.heroOnly.metrics.relmse);
}

}  // namespace
}  // namespace lamina::experiments
