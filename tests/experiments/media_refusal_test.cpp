// The experiments that render with BDPT refuse a scene with an emitting medium that fills space
// (the camera's medium, bounded by no shape: its volume cannot be sampled) before they render
// anything (docs/media.md), with the renderer's one line, rather than render it without its
// glow.
#include <gtest/gtest.h>

#include "lamina/core/error.h"
#include "lamina/experiments/convergence.h"
#include "lamina/experiments/reciprocity.h"
#include "scratch_directory.h"

namespace lamina::experiments {
namespace {

using testing::errorOf;

/// Glowing gas around the camera, filling space, with a sphere and an emitter in it.
constexpr const char* kGlowScene = R"({
  "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "medium": "glow"},
  "media": {"glow": {"type": "homogeneous", "sigma_a": 0.5, "Le": 1}},
  "materials": {"m": {"type": "lambert"}},
  "shapes": [{"type": "sphere", "material": "m"},
             {"type": "sphere", "center": [0, 3, 0], "radius": 0.5, "material": "m",
              "emission": {"radiance": 1}}]})";

class MediaRefusal : public testing::ScratchDirectoryTest {};

TEST_F(MediaRefusal, ReciprocityRefusesBdptInAnEmittingMediumThatFillsSpace) {
    ReciprocityInputs in;
    in.scene = write("glow.json", kGlowScene).string();
    in.integrators = {render::IntegratorKind::Path, render::IntegratorKind::Bdpt};
    EXPECT_EQ(errorOf([&] { runReciprocity(in); }),
              in.scene +
                  ": media.glow.Le: the light and bdpt integrators start particles in an "
                  "emitting medium's volume, and this one reaches infinity (no shapes enclose "
                  "it); enclose it with shapes or use --integrator path");
}

TEST_F(MediaRefusal, ConvergenceRefusesABdptReferenceInAnEmittingMediumThatFillsSpace) {
    ConvergenceInputs in;
    in.scene = write("glow.json", kGlowScene).string();
    in.integrators = {render::IntegratorKind::Path};
    in.referenceIntegrator = render::IntegratorKind::Bdpt;
    in.seconds = 0.01;
    const std::string m = errorOf([&] { runConvergence(in); });
    EXPECT_NE(m.find(": media.glow.Le: the light and bdpt integrators start particles in an "
                     "emitting medium's volume, and this one reaches infinity"),
              std::string::npos)
        << m;
}

}  // namespace
}  // namespace lamina::experiments
