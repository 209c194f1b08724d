// What a material's inputs mean in a rendering mode. Material descriptions hold linear
// Rec.709 colours and (eta, k) numbers; a SpectrumContext turns them into the variant's
// spectrum type. RGB mode uses the colours as they are; spectral mode (spectral_context.h in
// lamina_spectral's users) upsamples them at the path's wavelengths.
#pragma once

#include "lamina/core/spectrum.h"

namespace lamina {

template <SpectrumType S>
struct SpectrumContext;

/// RGB mode: colours are the coefficients themselves.
template <std::floating_point T>
struct SpectrumContext<Rgb<T>> {
    static constexpr bool kSpectral = false;

    /// A reflectance in [0, 1] (albedo, F0).
    Rgb<T> reflectance(const Rgb<double>& c) const { return convert(c); }
    /// A value that varies per channel without bound (a conductor's eta or k per channel).
    Rgb<T> unbounded(const Rgb<double>& c) const { return convert(c); }

  private:
    static Rgb<T> convert(const Rgb<double>& c) {
        if constexpr (std::same_as<T, double>)
            return c;
        else
            return Rgb<T>(c);
    }
};

}  // namespace lamina
