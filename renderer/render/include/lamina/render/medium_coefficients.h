// A medium's coefficients in a render mode's spectrum (docs/media.md), as the integrators read
// them at every segment in the medium: RenderMode<S>::medium. A grid medium's are per unit of
// its density (grid_tracking.h scales them at each point).
#pragma once

#include <array>

#include "lamina/core/spectrum.h"
#include "lamina/scene/density_grid.h"

namespace lamina::render {

template <SpectrumType S>
struct MediumCoefficients {
    S sigmaA{0.0f}, sigmaS{0.0f};  ///< absorption and scattering, 1 / scene unit
    S emission{0.0f};              ///< Le: the source term is sigma_a Le
    float g = 0;                   ///< Henyey-Greenstein asymmetry
    bool emits = false;
    const GridDensity* grid = nullptr;  ///< a grid medium's density; null: homogeneous
    /// The path's wavelengths in nm (spectral mode), where a grid of per-cell colours
    /// (GridDensity::colours) evaluates its cells' spectra.
    std::array<float, S::kSize> lambda{};
    S sigmaT() const { return sigmaA + sigmaS; }
};

}  // namespace lamina::render
