// The statistics of `lamina layering` (experiments/layering_statistics.h) and its analysis on
// materials whose answer is known: a coat of index 1 is no coat at all, so its walk and both
// twins are the bare base.
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/bsdf/diffuse.h"
#include "lamina/bsdf/standard.h"
#include "lamina/core/error.h"
#include "lamina/experiments/layering.h"
#include "scratch_directory.h"

namespace lamina::experiments {
namespace {

TEST(LayeringStatistics, RunningMeanGivesTheSampleMeanAndItsStandardError) {
    RunningMean m;
    for (int i = 1; i <= 10; ++i)
        m.add(double(i));
    const MeanEstimate e = m.estimate();
    EXPECT_EQ(e.count, 10);
    EXPECT_DOUBLE_EQ(e.mean, 5.5);
    // Sample variance of 1..10 is 55/6; the standard error is sqrt(55/6 / 10).
    EXPECT_NEAR(e.standardError, std::sqrt(55.0 / 6.0 / 10.0), 1e-12);
    RunningMean one;
    one.add(3.0);
    EXPECT_EQ(one.estimate().standardError, 0.0);
}

MeanEstimate value(double mean, double se) {
    return {mean, se, 100};
}

TEST(LayeringStatistics, ABandIsClaimedOnlyWhenTheWholeErrorBarIsInsideIt) {
    // 0.5% +- 0.1%: the bar reaches 0.7%, inside 1%.
    EXPECT_EQ(compareWithWalk(value(1.005, 0), value(1, 0.001)).agreement, Agreement::Within1);
    // 0.9% +- 0.2%: the bar reaches 1.3%, so only 5% is established.
    const TwinComparison c = compareWithWalk(value(1.009, 0), value(1, 0.002));
    EXPECT_EQ(c.agreement, Agreement::Within5);
    EXPECT_FALSE(c.within(0.01));
    EXPECT_FALSE(c.beyond(0.01));
    // Equal means, but the walk's error bar spans +-30%: nothing can be said.
    EXPECT_EQ(compareWithWalk(value(1, 0), value(1, 0.15)).agreement, Agreement::Unresolved);
    // 50% +- 2%: beyond 20% with confidence.
    const TwinComparison far = compareWithWalk(value(1.5, 0), value(1, 0.01));
    EXPECT_EQ(far.agreement, Agreement::Beyond20);
    EXPECT_NEAR(far.error, 0.5, 1e-12);
    // The twin's own error bar counts too.
    EXPECT_EQ(compareWithWalk(value(1.005, 0.004), value(1, 0)).agreement, Agreement::Within5);
}

TEST(LayeringStatistics, ANearZeroReferenceIsComparedAgainstTheFloor) {
    // The walk is 1e-6, the twin 1.5e-6: relative error 50%, but 0.5% of the floor 1e-4.
    const TwinComparison c = compareWithWalk(value(1.5e-6, 0), value(1e-6, 1e-7));
    EXPECT_TRUE(c.absolute);
    EXPECT_NEAR(c.error, 0.005, 1e-12);
    EXPECT_EQ(c.agreement, Agreement::Within1);
    // Above the floor the error is relative again.
    EXPECT_FALSE(compareWithWalk(value(2e-4, 0), value(1e-4, 0)).absolute);
    // Everything black: no division by zero, no NaN.
    const TwinComparison black = compareWithWalk(value(0, 0), value(0, 0));
    EXPECT_TRUE(black.absolute);
    EXPECT_EQ(black.error, 0.0);
    EXPECT_EQ(black.agreement, Agreement::Within1);
    BandCounts counts;
    counts.add(c);
    counts.add(black);
    counts.add(compareWithWalk(value(1.5, 0), value(1, 0.01)));
    EXPECT_EQ(counts.points, 3);
    EXPECT_EQ(counts.absolute, 2);
    EXPECT_EQ(counts.within[0], 2);
    EXPECT_EQ(counts.beyond[2], 1);
}

TEST(LayeringMaterials, NamesLiteralsAndRefusals) {
    for (const auto& [name, json] : layeringMaterials()) {
        const LayeringMaterial m = readLayeringMaterial(name, 1);
        EXPECT_EQ(m.stem, name);
        EXPECT_EQ(m.desc.type, "coated");
    }
    EXPECT_EQ(readLayeringMaterial(R"({"type":"coated","base":{"type":"lambert"}})", 3).stem,
              "material3");
    EXPECT_THROW(readLayeringMaterial("no-such-finish", 1), InputError);
    try {
        readLayeringMaterial(R"({"type":"lambert"})", 1);
        FAIL() << "a lambert material is not coated";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("expected \"coated\""), std::string::npos) << e.what();
    }
}

TEST(LayeringMaterials, TwinsExistForDiffuseAndRoughConductorBasesAndSayWhatTheyLeaveOut) {
    std::string note;
    const auto twins = analyticTwins(readLayeringMaterial("varnished-wood", 1), note);
    ASSERT_EQ(twins.size(), 2u);
    EXPECT_TRUE(note.empty());
    EXPECT_EQ(twins[0].name, "fresnel coupling");
    EXPECT_EQ(twins[1].name, "albedo coupling");
    const auto& s = twins[1].desc.model.as<StandardMaterial>();
    EXPECT_EQ(s.coupling, LayerCoupling::Albedo);
    EXPECT_EQ(s.fresnel, FresnelChoice::Exact);
    EXPECT_DOUBLE_EQ(s.ior, 1.55);
    EXPECT_DOUBLE_EQ(s.microfacet.alphaX, 0.04);
    EXPECT_EQ(s.diffuse, DiffuseModel::OrenNayar);

    const auto gold = analyticTwins(readLayeringMaterial("coated-gold", 1), note);
    ASSERT_EQ(gold.size(), 2u);
    EXPECT_NE(note.find("one pass through the coat"), std::string::npos) << note;
    for (const LayeringTwin& t : gold) {
        const auto& g = t.desc.model.as<StandardMaterial>();
        ASSERT_TRUE(g.conductorBase) << t.name;
        EXPECT_FALSE(g.diffuse.has_value());
        EXPECT_DOUBLE_EQ(g.conductorBase->microfacet.alphaX, 0.09);
        EXPECT_DOUBLE_EQ(g.microfacet.alphaX, 0.0225);
    }
    // A smooth conductor under the coat has no twin: the stack takes rough conductors only.
    EXPECT_TRUE(analyticTwins(readLayeringMaterial(R"({"type":"coated","roughness":0.2,)"
                                                   R"("base":{"type":"conductor","f0":0.9}})",
                                                   1),
                              note)
                    .empty());
    EXPECT_NE(note.find("a smooth conductor"), std::string::npos) << note;
    EXPECT_EQ(analyticTwins(readLayeringMaterial("tinted-coat", 1), note).size(), 2u);
    EXPECT_NE(note.find("medium"), std::string::npos) << note;
}

TEST(LayeringAnalysis, AnIndexMatchedCoatAgreesWithItsTwinsWithin1Percent) {
    LayeringInputs in;
    in.materials = {R"({"type":"coated","ior":1,"base":{"type":"lambert","reflectance":0.6}})"};
    in.estimates = 8;
    in.albedoSamples = 1 << 16;
    in.seed = 7;
    const LayeringResult r = runLayering(in);
    ASSERT_EQ(r.materials.size(), 1u);
    const LayeringMaterialResult& m = r.materials[0];
    ASSERT_EQ(m.twins.size(), 2u);
    // The walk through an index-matched coat is the base's own sampler: albedo 0.6 exactly.
    for (const MeanEstimate& a : m.walkAlbedo.values) {
        EXPECT_NEAR(a.mean, 0.6, 1e-12);
        EXPECT_NEAR(a.standardError, 0.0, 1e-12);
    }
    for (const LayeringTwinResult& t : m.twins) {
        for (std::size_t i = 0; i < t.albedo.comparisons.size(); ++i)
            EXPECT_EQ(t.albedo.comparisons[i].agreement, Agreement::Within1)
                << t.name << " at " << r.albedoAngles[i] << ": " << t.albedo.values[i].mean
                << " +- " << t.albedo.values[i].standardError;
        for (const LayeringValues& lobe : t.lobes)
            for (const TwinComparison& c : lobe.comparisons)
                EXPECT_EQ(c.agreement, Agreement::Within1) << t.name << " " << c.error;
        EXPECT_EQ(t.map.counts.within[0], t.map.counts.points) << t.name;
        EXPECT_EQ(t.map.counts.points, int(r.mapAngles.size() * r.mapAngles.size()));
    }
}

TEST(LayeringAnalysis, ARealCoatIsDarkerThanItsBaseAndCarriesAnErrorBar) {
    LayeringInputs in;
    in.materials = {"varnished-wood"};
    in.estimates = 64;
    in.albedoSamples = 4096;
    const LayeringResult r = runLayering(in);
    const LayeringMaterialResult& m = r.materials[0];
    for (const MeanEstimate& a : m.walkAlbedo.values) {
        EXPECT_GT(a.mean, 0.0);
        EXPECT_LT(a.mean, 1.0);
        EXPECT_GT(a.standardError, 0.0);
        EXPECT_TRUE(std::isfinite(a.standardError));
    }
    for (const LayeringTwinResult& t : m.twins)
        for (const TwinComparison& c : t.map.comparisons) {
            EXPECT_TRUE(std::isfinite(c.error));
            EXPECT_TRUE(std::isfinite(c.standardError));
        }
}

// The walk is the truth the twins are measured against: in the white furnace (white Lambert
// under a smooth clear coat, nothing absorbs) its albedo is 1 at every theta_o at the
// experiment's own settings (its albedo sample count, seed and double-precision RGB walk).
// Every path leaves with weight exactly 1, so the estimate is 1 to rounding (tolerance 1e-9).
TEST(LayeringAnalysis, TheWalkReflectsEverythingInTheWhiteFurnace) {
    LayeringInputs in;
    in.materials = {R"({"type":"coated","ior":1.5,"base":{"type":"lambert","reflectance":1}})",
                    R"({"type":"coated","ior":1.5,"thickness":0.5,"albedo":1,"g":0.5,)"
                    R"("base":{"type":"lambert","reflectance":1}})"};
    in.estimates = 2;  // eval's points do not enter the albedo
    const LayeringResult r = runLayering(in);
    ASSERT_EQ(r.materials.size(), 2u);
    for (const LayeringMaterialResult& m : r.materials) {
        EXPECT_EQ(m.walkMaxDepth, 0);
        for (std::size_t i = 0; i < m.walkAlbedo.values.size(); ++i)
            EXPECT_NEAR(m.walkAlbedo.values[i].mean, 1.0,
                        1e-9 + 4 * m.walkAlbedo.values[i].standardError)
                << m.stem << " at " << r.albedoAngles[i];
    }
}

class LayeringReportTest : public testing::ScratchDirectoryTest {};

// A capped walk is no truth: the experiment still runs it, and says so in the summary, on the
// console and in its data; its furnace albedo is measurably below 1.
TEST_F(LayeringReportTest, ACappedWalkIsFlaggedAsNoTruth) {
    LayeringInputs in;
    in.materials = {
        R"({"type":"coated","ior":1.5,"max_depth":10,"base":{"type":"lambert","reflectance":1}})"};
    in.estimates = 2;
    in.albedoSamples = 1 << 14;
    std::string console;
    in.progress = [&console](const std::string& text) { console += text; };
    const LayeringResult r = runLayering(in);
    const LayeringMaterialResult& m = r.materials[0];
    EXPECT_EQ(m.walkMaxDepth, 10);
    const MeanEstimate& normal = m.walkAlbedo.values.front();
    EXPECT_LT(normal.mean + 4 * normal.standardError, 1.0);
    EXPECT_NE(console.find("warning: material1: the walk is capped at max_depth 10"),
              std::string::npos)
        << console;
    Report report(dir_, nullptr);
    writeLayeringReport(r, report);
    EXPECT_NE(report.summary().find("**Not a truth: the walk is capped at max_depth 10"),
              std::string::npos)
        << report.summary();
}

}  // namespace
}  // namespace lamina::experiments
