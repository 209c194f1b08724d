// The colour of an emitter in both modes, prepared once when the scene is loaded: its RGB
// (an RGB input, or the reduction of a spectrum) and its spectrum (the spectrum given, or the
// RGB upsampled as an illuminant, so RGB (1, 1, 1) is D65 and stays white).
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "lamina/spectral/emission_spectrum.h"
#include "lamina/spectral/rgb_to_spectrum.h"
#include "lamina/spectral/sampled_wavelengths.h"

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

/// The spectra of the emitters one spectral path has met, at its wavelengths: a path asks for
/// the same few emitters again and again (next-event estimation samples a light at every
/// vertex), and evaluating an emitter's spectrum costs per wavelength what its colour is (an
/// upsampled RGB times D65, a black body, a table). A cache of the last kSlots emitters, valid
/// for one set of wavelengths: it lives in the path, whose wavelengths are drawn once.
template <typename Spectrum>
class EmitterSpectra {
  public:
    static constexpr int kSlots = 4;

    const Spectrum& at(const EmitterColor& color, const SampledWavelengths<float>& lambda) {
        for (int k = 0; k < kSlots; ++k)
            if (colors_[k] == &color) return values_[k];
        const int k = next_;
        next_ = (next_ + 1) % kSlots;
        colors_[k] = &color;
        for (int i = 0; i < Spectrum::kSize; ++i)
            values_[k][i] = float(color.spectral(double(lambda[i])));
        return values_[k];
    }

  private:
    std::array<const EmitterColor*, kSlots> colors_{};
    std::array<Spectrum, kSlots> values_{};
    int next_ = 0;
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
