// What a material's inputs mean in a rendering mode. Material descriptions hold linear
// Rec.709 colours and (eta, k) numbers; a SpectrumContext turns them into the variant's
// spectrum type. RGB mode uses the colours as they are; spectral mode (spectral_context.h in
// lamina_spectral's users) upsamples them at the path's wavelengths.
#pragma once

#include "lamina/core/spectrum.h"
#include "lamina/spectral/ior_spectrum.h"
#include "lamina/spectral/rgb_to_spectrum.h"
#include "lamina/spectral/sampled_wavelengths.h"
#include "lamina/spectral/upsampled_colors.h"

namespace lamina {

template <SpectrumType S>
struct SpectrumContext;

/// RGB mode: colours are the coefficients themselves.
template <std::floating_point T>
struct SpectrumContext<Rgb<T>> {
    static constexpr bool kSpectral = false;

    /// The RGB-mode index of a possibly dispersive material: n at the d-line.
    T dielectricIor(const IorSpectrum& ior) const { return T(ior.n(kDLineNm)); }
    /// The index per channel where it does not bend the path (a thin slab): the d-line index.
    Rgb<T> indexPerChannel(const IorSpectrum& ior) const { return Rgb<T>(dielectricIor(ior)); }

    /// A reflectance in [0, 1] (albedo, F0).
    Rgb<T> reflectance(const Rgb<double>& c) const { return convert(c); }
    /// A colour input: its colour (a spectrum's reduction under D65).
    template <typename C>
    requires requires(const C& c) {
        c.rgb;
        c.spectrum;
    }
    Rgb<T> reflectance(const C& c) const { return convert(c.rgb); }
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

/// Spectral mode: colours are upsampled (Jakob and Hanika 2019) and evaluated at the path's
/// wavelengths. Per-channel values that are not reflectances (a conductor's eta, k given as
/// RGB triples) are upsampled as unbounded spectra, never as reflectances (which would clamp
/// them to [0, 1]).
template <std::floating_point T>
struct SpectrumContext<SampledSpectrum<T>> {
    static constexpr bool kSpectral = true;
    SampledWavelengths<T>& lambda;  ///< the path's: a dispersive material terminates it
    /// The material's colours upsampled in advance (when the scene was loaded), or none:
    /// then every colour is looked up in the table.
    const UpsampledColors* colors = nullptr;
    /// Where a build collects the colours it upsamples (done once per material at load,
    /// to fill its UpsampledColors), or none.
    UpsampledColors* collect = nullptr;

    /// Set to true by a build that reads the wavelengths: a colour that is not grey, a
    /// spectrum, an index or n, k at the path's wavelengths (or none is recorded). A build that
    /// leaves it false made the same BSDF as at any other wavelengths, and spectral mode builds
    /// such a material once for every path (render_mode.h). Read `lambda` only through
    /// wavelength() and hero(), which record it.
    bool* readsWavelengths = nullptr;

    T wavelength(int i) const {
        noteWavelengthsRead();
        return lambda[i];
    }
    T hero() const { return wavelength(0); }

    /// A dispersive index splits the wavelengths into different directions: only the hero
    /// wavelength continues (Wilkie et al. 2014, section 4.3), with its own index.
    T dielectricIor(const IorSpectrum& ior) const {
        if (ior.dispersive()) lambda.terminateSecondary();
        return T(ior.n(double(hero())));
    }

    /// The index at each of the path's wavelengths, for a boundary that does not bend the path
    /// (a thin slab transmits straight through): no wavelength is terminated.
    SampledSpectrum<T> indexPerChannel(const IorSpectrum& ior) const {
        return evaluate([&](double nm) { return ior.n(nm); });
    }

    SampledSpectrum<T> reflectance(const Rgb<double>& c) const {
        return evaluate(upsample(c, RgbSpectrumKind::Reflectance));
    }
    /// An upsampled colour at the path's wavelengths; a grey one is the same at all of them.
    SampledSpectrum<T> evaluate(const RgbSpectrum& s) const {
        if (s.isConstant()) return SampledSpectrum<T>(T(s.value()));
        return evaluate([&](double nm) { return s(nm); });
    }
    /// A colour input: its spectrum if it has one, else the upsampled colour.
    template <typename C>
    requires requires(const C& c) {
        c.rgb;
        c.spectrum;
    }
    SampledSpectrum<T> reflectance(const C& c) const {
        return c.spectrum ? evaluate(*c.spectrum) : reflectance(c.rgb);
    }
    /// Grey values are exactly constant spectra; others are pbrt-v4's unbounded spectra
    /// (RgbSpectrumKind::Unbounded: the table's spectrum of rgb / 2 max(rgb), times 2 max(rgb)).
    SampledSpectrum<T> unbounded(const Rgb<double>& c) const {
        if (c[0] == c[1] && c[1] == c[2]) return SampledSpectrum<T>(T(c[0]));
        return evaluate(upsample(c, RgbSpectrumKind::Unbounded));
    }

    RgbSpectrum upsample(const Rgb<double>& c, RgbSpectrumKind kind) const {
        if (collect) collect->keep(c, kind);
        return colors ? colors->spectrum(c, kind) : RgbSpectrum(c, kind);
    }

    template <typename F>
    SampledSpectrum<T> evaluate(const F& f) const {
        SampledSpectrum<T> s;
        for (int i = 0; i < SampledSpectrum<T>::kSize; ++i)
            s[i] = T(f(double(wavelength(i))));
        return s;
    }

  private:
    void noteWavelengthsRead() const {
        if (readsWavelengths) *readsWavelengths = true;
    }
};

}  // namespace lamina
