// The experiments that render with BDPT refuse a scene with media before they render anything
// (docs/media.md, "not yet"), with the renderer's one line, rather than render the media as
// vacuum; path and light tracing render media.
#include <gtest/gtest.h>

#include "lamina/core/error.h"
#include "lamina/experiments/convergence.h"
#include "lamina/experiments/reciprocity.h"
#include "source_files.h"

namespace lamina::experiments {
namespace {

const std::string kFogSlab = testing::sourceFile("scenes/media/fog-slab.json").string();

std::string messageOf(const std::function<void()>& run) {
    try {
        run();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(MediaRefusal, ReciprocityRefusesBdptThroughMedia) {
    ReciprocityInputs in;
    in.scene = kFogSlab;
    EXPECT_EQ(messageOf([&] { runReciprocity(in); }),
              kFogSlab +
                  ": media: the bdpt integrator does not render media yet; use --integrator "
                  "path or light");
}

TEST(MediaRefusal, ConvergenceRefusesABdptReferenceThroughMedia) {
    ConvergenceInputs in;
    in.scene = kFogSlab;
    in.integrators = {render::IntegratorKind::Path};
    in.referenceIntegrator = render::IntegratorKind::Bdpt;
    in.seconds = 0.01;
    const std::string m = messageOf([&] { runConvergence(in); });
    EXPECT_NE(m.find(": media: the bdpt integrator does not render media yet"), std::string::npos)
        << m;
}

}  // namespace
}  // namespace lamina::experiments
