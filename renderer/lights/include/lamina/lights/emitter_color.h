// The colour of an emitter in both modes, prepared once when the scene is loaded: its RGB
// (an RGB input, or the reduction of a spectrum) and its spectrum (the spectrum given, or the
// RGB upsampled as an illuminant, so RGB (1, 1, 1) is D65 and stays white), resampled at 1 nm
// (ResampledSpectrum): spectral mode evaluates it at four wavelengths at every emitter a path
// meets, and the resampled table is a lerp where the spectrum itself is a sigmoid, a square
// root and a division per wavelength. Emitters of the same colour share one table (a mesh
// light is one TriangleLight per triangle).
#pragma once

#include <memory>

#include "lamina/spectral/emission_spectrum.h"
#include "lamina/spectral/resampled_spectrum.h"

namespace lamina::render {

class EmitterColor {
  public:
    EmitterColor() = default;
    EmitterColor(const Rgb<double>& rgb, std::shared_ptr<const EmissionSpectrum> spectrum);

    const Rgb<float>& rgb() const { return rgb_; }
    const Rgb<double>& rgbDouble() const { return rgbD_; }
    /// The spectrum at a path's wavelengths, given by their table positions (zero for a
    /// default-constructed colour).
    template <int N>
    SampledSpectrum<float, N> spectral(const ResampledSpectrum::Positions<N>& at) const {
        return table_ ? table_->at(at) : SampledSpectrum<float, N>();
    }
    bool isBlack() const { return rgb_.maxValue() <= 0.0f && !given_; }

  private:
    Rgb<double> rgbD_{0.0};
    Rgb<float> rgb_{0.0f};
    std::shared_ptr<const EmissionSpectrum> given_;  ///< the spectrum given, if any
    std::shared_ptr<const ResampledSpectrum> table_;
};

/// Emitted radiance (or intensity / d^2, or irradiance): a colour times a scale. Image-based
/// emitters (environment maps) give a texel instead of a colour: its RGB is used as it is in
/// RGB mode and upsampled as an illuminant in spectral mode (render_mode.h).
struct Emission {
    const EmitterColor* color = nullptr;
    float scale = 0;
    Rgb<float> texel{0.0f};  ///< used when color is null

    bool isZero() const {
        if (!(scale > 0.0f)) return true;
        return color ? color->isBlack() : texel.maxValue() <= 0.0f;
    }
    Rgb<float> rgb() const { return (color ? color->rgb() : texel) * scale; }
};

}  // namespace lamina::render
