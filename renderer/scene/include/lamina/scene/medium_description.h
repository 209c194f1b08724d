// The participating media of a scene (docs/media.md): the top-level "media" object names
// them, shapes bound them ("interior", "exterior") and the camera may sit in one ("medium").
// Plain data as the reader leaves it; the renderer turns the coefficients into the render
// mode's spectra (render_mode.h).
#pragma once

#include <array>
#include <memory>
#include <string>

#include "lamina/core/name_table.h"
#include "lamina/core/spectrum.h"
#include "lamina/scene/density_grid.h"
#include "lamina/spectral/emission_spectrum.h"

namespace lamina::render {

/// The `type` of a medium: constant coefficients, or coefficients scaled by a density grid or
/// by pbrt-v4's procedural cloud density (cloud_density.h; rendered as a grid medium whose
/// GridDensity evaluates the cloud).
enum class MediumKind { Homogeneous, Grid, Cloud };
inline constexpr NameTable kMediumKindNames{
    std::array{NameEntry{MediumKind::Homogeneous, "homogeneous"},
               NameEntry{MediumKind::Grid, "grid"}, NameEntry{MediumKind::Cloud, "cloud"}}};

/// A medium's coefficients, in 1 / scene unit, already multiplied by the file's `scale`: of
/// the whole medium (homogeneous), or per unit of the grid's density (grid: the coefficient at
/// a point is the density there times these). RGB coefficients are linear Rec.709 values;
/// spectral mode upsamples them as unbounded spectra (pbrt-v4's RGBUnboundedSpectrum), as it
/// does a material's unbounded parameters, so a grey coefficient is the same constant at every
/// wavelength.
struct MediumDesc {
    std::string name;
    MediumKind kind = MediumKind::Homogeneous;
    Rgb<double> sigmaA{0.0};  ///< absorption
    Rgb<double> sigmaS{0.0};  ///< scattering
    /// Henyey-Greenstein asymmetry in (-1, 1): > 0 scatters forward.
    double g = 0;
    /// Emitted radiance per unit length of absorption (the source term sigma_a Le of the
    /// radiative transfer equation): RGB upsampled as an illuminant, or a spectrum.
    Rgb<double> emission{0.0};
    std::shared_ptr<const EmissionSpectrum> emissionSpectrum;
    /// A grid or cloud medium's density and majorants (null for a homogeneous medium).
    std::shared_ptr<const GridDensity> grid;
    bool emits() const { return emissionSpectrum || emission.maxValue() > 0; }
};

/// What crossing a shape's surface does to the medium a path is in: entering against the
/// geometric normal leads into `interior`, leaving along it into `exterior` (indices into
/// SceneDesc::media; -1 is vacuum).
struct MediumInterfaceDesc {
    int interior = -1, exterior = -1;
    /// The medium on the side a direction leaves the surface to (dot(direction, ng)).
    int sideOf(float directionDotNormal) const {
        return directionDotNormal > 0.0f ? exterior : interior;
    }
};

}  // namespace lamina::render
