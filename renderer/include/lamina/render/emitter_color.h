// The colour of an emitter in both modes, prepared once when the scene is loaded: its RGB
// (an RGB input, or the reduction of a spectrum) and its spectrum (the spectrum given, or the
// RGB upsampled as an illuminant, so RGB (1, 1, 1) is D65 and stays white).
#pragma once

#include <memory>
#include <optional>

#include "lamina/spectral/emission_spectrum.h"
#include "lamina/spectral/rgb_to_spectrum.h"

namespace lamina::render {

class EmitterColor {
  public:
    EmitterColor() = default;
    EmitterColor(const Rgb<double>& rgb, std::shared_ptr<const EmissionSpectrum> spectrum)
        : rgbD_(spectrum ? spectrum->rgb() : rgb),
          rgb_(float(rgbD_[0]), float(rgbD_[1]), float(rgbD_[2])),
          spectrum_(std::move(spectrum)) {
        if (!spectrum_) upsampled_.emplace(rgb, RgbSpectrumKind::Illuminant);
    }

    const Rgb<float>& rgb() const { return rgb_; }
    const Rgb<double>& rgbDouble() const { return rgbD_; }
    double spectral(double nm) const { return spectrum_ ? (*spectrum_)(nm) : (*upsampled_)(nm); }
    bool isBlack() const { return rgb_.maxValue() <= 0.0f && !spectrum_; }

  private:
    Rgb<double> rgbD_{0.0};
    Rgb<float> rgb_{0.0f};
    std::shared_ptr<const EmissionSpectrum> spectrum_;
    std::optional<RgbSpectrum> upsampled_;
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
