// A thin film on a Fresnel interface (docs/bsdf.md, "Thin films"): a layer of real index `ior`
// and thickness `thicknessNm` on the outside of a dielectric boundary or on a conductor. Its
// reflectance replaces the bare interface's on every microfacet; directions are the bare
// interface's (the film is thin: it shifts no ray), and a dielectric transmits 1 - R, since the
// film absorbs nothing.
//
// Spectral and polarised modes: the exact Airy sum at each of the path's wavelengths, for s and
// p (core/thin_film.h). RGB mode: the reflectance's colour under D65, integrated in closed form
// against each channel's sensitivity (Belcour and Barla 2017, "A Practical Extension to
// Microfacet Theory for the Modeling of Varying Iridescence", eqs. 7-10: the Airy reflectance as
// a Fourier series in the phase, each term's spectral integral the sensitivity's Fourier
// transform at the term's optical path difference), with the interfaces' amplitudes from the
// channel's index. The series converges geometrically (ratio sqrt(R12 R23)); it is summed while
// a term's weight (1 - C0) ratio^m is above 1e-7 (at most 64 terms).
#pragma once

#include <algorithm>
#include <complex>

#include "lamina/core/spectrum.h"
#include "lamina/core/thin_film.h"
#include "lamina/spectral/fringe_colors.h"

namespace lamina {

template <SpectrumType S>
struct ThinFilm {
    using Float = typename S::Float;
    static constexpr bool kRgb = std::same_as<S, Rgb<Float>>;

    Float thicknessNm = 0;
    Float ior = Float(1.33);
    /// The path's wavelengths (spectral variants); in RGB mode the channels' centre wavelengths
    /// (FringeColors::meanWavelength), where evalMueller takes the film's polarisation shape.
    S wavelengthsNm{};

    /// Where light arriving at `cosTheta` to the normal of a dielectric boundary (negative: from
    /// inside) meets the film: the cosine on its side and the stack from there. eta is the
    /// boundary's inside over outside index; the film is on the outside.
    struct Side {
        Float cosI;
        Float n1;
        std::complex<Float> n3;
    };
    static Side dielectricSide(Float cosTheta, Float eta) {
        if (cosTheta < Float(0)) return {-cosTheta, eta, std::complex<Float>(Float(1))};
        return {cosTheta, Float(1), std::complex<Float>(eta)};
    }

    /// The film's exact amplitudes at channel i's wavelength.
    FresnelAmplitudes<Float> amplitudes(int i, const Side& side) const {
        return thinFilmAmplitudes(side.cosI, FilmStack<Float>{side.n1, ior, side.n3},
                                  thicknessNm / wavelengthsNm[i]);
    }

    /// Unpolarised reflectance of channel i: the mean of s and p.
    Float reflectance(int i, const Side& side) const {
        if constexpr (kRgb) {
            return Float(RgbSeries(*this, side).channel(i));
        } else {
            const FresnelAmplitudes<Float> a = amplitudes(i, side);
            return clamp(Float(0.5) * (std::norm(a.rs) + std::norm(a.rp)), Float(0), Float(1));
        }
    }

    /// Every channel's reflectance for one stack (a dielectric: the same index in every
    /// channel), the RGB series computed once.
    S reflectance(const Side& side) const {
        S r;
        if constexpr (kRgb) {
            const RgbSeries series(*this, side);
            for (int c = 0; c < S::kSize; ++c)
                r[c] = Float(series.channel(c));
        } else {
            for (int i = 0; i < S::kSize; ++i)
                r[i] = reflectance(i, side);
        }
        return r;
    }

  private:
    static constexpr int kMaxTerms = 64;

    // Belcour and Barla's closed form (see the top of this file) for one stack: the series of
    // both polarisations, then each channel's value, clamped to [0, 1] (a saturated fringe can
    // have a negative Rec.709 component).
    class RgbSeries {
      public:
        RgbSeries(const ThinFilm& film, const Side& side)
            : film_(film),
              stack_{double(side.n1), double(film.ior), std::complex<double>(side.n3)},
              cosI_(double(side.cosI)),
              series_(airyFourier(cosI_, stack_)) {
            if (!series_) return;
            opd_ = series_->opdPerThickness * double(film.thicknessNm);
            // The terms whose weight (1 - C0) ratio^m exceeds 1e-7, in either polarisation.
            const auto termsNeeded = [](const AirySeries<double>& a) {
                int m = 0;
                for (double weight = (1.0 - a.c0) * a.ratio; m < kMaxTerms && weight > 1e-7;
                     weight *= a.ratio)
                    ++m;
                return m;
            };
            terms_ = std::max(termsNeeded(series_->s), termsNeeded(series_->p));
        }

        double channel(int c) const {
            const FringeColors& fringes = FringeColors::rec709();
            if (!series_) {  // an evanescent film has no fringes: its value at the centre
                const FresnelAmplitudes<double> a = thinFilmAmplitudes(
                    cosI_, stack_, double(film_.thicknessNm) / fringes.meanWavelength(c));
                return clamp(0.5 * (std::norm(a.rs) + std::norm(a.rp)), 0.0, 1.0);
            }
            std::complex<double> transform[kMaxTerms];  // F_c(m OPD), m = 1 .. terms
            fringes.atMultiples(c, opd_, terms_, transform);
            const auto polarisation = [&](const AirySeries<double>& a, std::complex<double> turn) {
                std::complex<double> phase = 1.0;
                double sum = 0, ratio = 1;
                for (int m = 1; m <= terms_; ++m) {
                    ratio *= a.ratio;
                    phase *= turn;
                    sum += ratio * std::real(phase * transform[m - 1]);
                }
                return a.c0 + 2.0 * (a.c0 - 1.0) * sum;
            };
            return clamp(0.5 * (polarisation(series_->s, series_->s.turn) +
                                polarisation(series_->p, series_->p.turn)),
                         0.0, 1.0);
        }

      private:
        const ThinFilm& film_;
        FilmStack<double> stack_;
        double cosI_;
        std::optional<AiryFourier<double>> series_;
        double opd_ = 0;
        int terms_ = 0;
    };
};

}  // namespace lamina
