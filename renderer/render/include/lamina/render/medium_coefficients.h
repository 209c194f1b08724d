// A homogeneous medium's coefficients in a render mode's spectrum (docs/media.md), as the
// path integrator reads them at every segment in the medium: RenderMode<S>::medium.
#pragma once

#include "lamina/core/spectrum.h"

namespace lamina::render {

template <SpectrumType S>
struct MediumCoefficients {
    S sigmaA{0.0f}, sigmaS{0.0f};  ///< absorption and scattering, 1 / scene unit
    S emission{0.0f};              ///< Le: the source term is sigma_a Le
    float g = 0;                   ///< Henyey-Greenstein asymmetry
    bool emits = false;
    S sigmaT() const { return sigmaA + sigmaS; }
};

}  // namespace lamina::render
