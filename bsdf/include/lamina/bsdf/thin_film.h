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
// channel's index. The series converges geometrically (ratio sqrt(R12 R23)); it is summed until
// a term's weight is below 1e-7.
#pragma once

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
            return rgbReflectance(i, side);
        } else {
            const FresnelAmplitudes<Float> a = amplitudes(i, side);
            return clamp(Float(0.5) * (std::norm(a.rs) + std::norm(a.rp)), Float(0), Float(1));
        }
    }

  private:
    // Belcour and Barla's closed form for channel c (see the top of this file), clamped to
    // [0, 1]: a saturated fringe can have a negative Rec.709 component.
    Float rgbReflectance(int c, const Side& side) const {
        const FilmStack<double> stack{double(side.n1), double(ior),
                                      std::complex<double>(side.n3)};
        const auto series = airyFourier(double(side.cosI), stack);
        const FringeColors& fringes = FringeColors::rec709();
        if (!series) {  // an evanescent film has no fringes: its value at the channel's mean
            const FresnelAmplitudes<double> a =
                thinFilmAmplitudes(double(side.cosI), stack,
                                   double(thicknessNm) / fringes.meanWavelength(c));
            return Float(clamp(0.5 * (std::norm(a.rs) + std::norm(a.rp)), 0.0, 1.0));
        }
        const double opd = series->opdPerThickness * double(thicknessNm);
        const auto polarisation = [&](const AirySeries<double>& a) {
            double sum = 0, term = 1;
            for (int m = 1; m <= 64 && opd * m < FringeColors::kMaxPathDifference; ++m) {
                term *= a.ratio;
                if (!(term * (1.0 - a.c0) > 1e-7)) break;
                sum += term * std::real(std::polar(1.0, m * a.psi) * fringes(c, m * opd));
            }
            return a.c0 + 2.0 * (a.c0 - 1.0) * sum;
        };
        return Float(clamp(0.5 * (polarisation(series->s) + polarisation(series->p)), 0.0, 1.0));
    }
};

}  // namespace lamina
