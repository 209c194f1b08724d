// Fresnel models: how much light a (micro)surface reflects at a given angle. Every model is
// evaluated with the cosine of the angle between the direction and the microfacet normal
// (the article, section 4.3: evaluating it on the shading normal would ignore roughness).
#pragma once

#include <optional>

#include "lamina/bsdf/thin_film.h"
#include "lamina/core/fresnel_equations.h"
#include "lamina/core/spectrum.h"

namespace lamina {

enum class FresnelKind {
    Schlick,                   ///< Schlick 1994: F0 + (F90 - F0)(1 - cos)^5
    SchlickShadowed,           ///< Schlick with F90 = min(1, luminance(F0) / 0.04) (Schuler 2009)
    SchlickSphericalGaussian,  ///< Lagarde 2012: the exponent as a spherical Gaussian
    F82,                       ///< Hoffman 2019: Schlick minus a Lazanyi term matching F(1/7)
    ExactDielectric,           ///< Fresnel equations, real relative index per channel
    ExactConductor,            ///< Fresnel equations, complex relative index eta + i k
};

/// The reference cosine of Hoffman's F82 model: cos(theta) = 1/7, theta ~ 81.8 degrees.
inline constexpr double kF82Cosine = 1.0 / 7.0;

template <SpectrumType S>
struct Fresnel {
    using Float = typename S::Float;

    FresnelKind kind = FresnelKind::SchlickShadowed;
    S f0{Float(0.04)};
    S f90{Float(1)};
    S f82{};  ///< absolute reflectance at cos = 1/7 (F82 model)
    S eta{Float(1.5)};
    S k{};
    /// A thin film on the interface (the exact models only: the film needs the index).
    std::optional<ThinFilm<S>> film;

    static Fresnel schlick(const S& f0, const S& f90 = S(Float(1))) {
        Fresnel f;
        f.kind = FresnelKind::Schlick;
        f.f0 = f0;
        f.f90 = f90;
        return f;
    }
    /// The article's default: F90 = min(1, luminance(F0) / 0.04). The luminance is that of
    /// the RGB F0; in spectral mode the caller passes the RGB-derived F90 in `f90`.
    static Fresnel schlickShadowed(const S& f0, const S& f90) {
        Fresnel f = schlick(f0, f90);
        f.kind = FresnelKind::SchlickShadowed;
        return f;
    }
    static Fresnel schlickSphericalGaussian(const S& f0, const S& f90 = S(Float(1))) {
        Fresnel f = schlick(f0, f90);
        f.kind = FresnelKind::SchlickSphericalGaussian;
        return f;
    }
    /// Hoffman's F82 with the reflectance at cos = 1/7 given absolutely.
    static Fresnel hoffmanF82(const S& f0, const S& f82) {
        Fresnel f = schlick(f0);
        f.kind = FresnelKind::F82;
        f.f82 = f82;
        return f;
    }
    /// Hoffman's F82 with F82 as a tint (multiplier) of Schlick's value at cos = 1/7.
    static Fresnel hoffmanF82Tint(const S& f0, const S& tint) {
        return hoffmanF82(f0, tint * schlickAt(f0, S(Float(1)), Float(kF82Cosine)));
    }
    static Fresnel dielectric(const S& eta) {
        Fresnel f;
        f.kind = FresnelKind::ExactDielectric;
        f.eta = eta;
        return f;
    }
    static Fresnel conductor(const S& eta, const S& k) {
        Fresnel f;
        f.kind = FresnelKind::ExactConductor;
        f.eta = eta;
        f.k = k;
        return f;
    }

    static S schlickAt(const S& f0, const S& f90, Float cosTheta) {
        return f0 + (f90 - f0) * pow5(Float(1) - saturate(cosTheta));
    }

    /// Reflectance for light arriving at `cosTheta` to the microfacet normal. For the exact
    /// dielectric a negative cosine means "from inside" (eta inverted); the approximations
    /// and conductors use |cosTheta|.
    S evaluate(Float cosTheta) const {
        if (film) return filmReflectance(cosTheta);
        const Float c = std::abs(cosTheta);
        switch (kind) {
            case FresnelKind::Schlick:
            case FresnelKind::SchlickShadowed:
                return schlickAt(f0, f90, c);
            case FresnelKind::SchlickSphericalGaussian: {
                // Lagarde 2012, "Spherical Gaussian approximation for Blinn-Phong, Phong and
                // Fresnel": (1 - c)^5 ~ 2^((-5.55473 c - 6.98316) c).
                const Float w = std::exp2((Float(-5.55473) * c - Float(6.98316)) * c);
                return f0 + (f90 - f0) * w;
            }
            case FresnelKind::F82: {
                // Hoffman 2019, "Fresnel Equations Considered Harmful" (MAM workshop):
                // F = Schlick(c) - a c (1 - c)^6, with a chosen so that F(1/7) = F82:
                // a = (Schlick(1/7) - F82) / ((1/7)(6/7)^6).
                const Float cb = Float(kF82Cosine);
                const Float denom = cb * pow5(Float(1) - cb) * (Float(1) - cb);
                const S a = (schlickAt(f0, f90, cb) - f82) / denom;
                return saturate(schlickAt(f0, f90, c) -
                                a * (c * pow5(Float(1) - c) * (Float(1) - c)));
            }
            case FresnelKind::ExactDielectric: {
                S r;
                for (int i = 0; i < S::kSize; ++i)
                    r[i] = fresnelDielectric(cosTheta, eta[i]);
                return r;
            }
            case FresnelKind::ExactConductor: {
                S r;
                for (int i = 0; i < S::kSize; ++i)
                    r[i] = fresnelConductor(c, eta[i], k[i]);
                return r;
            }
        }
        return S(Float(1));
    }

    /// Where the light meets the film of channel i (the exact models): the cosine on its side
    /// and the stack from there (a conductor's index is relative to the outside, index 1).
    typename ThinFilm<S>::Side filmSide(Float cosTheta, int i) const {
        if (kind == FresnelKind::ExactConductor)
            return {std::abs(cosTheta), Float(1), std::complex<Float>(eta[i], k[i])};
        return ThinFilm<S>::dielectricSide(cosTheta, eta[i]);
    }

  private:
    S filmReflectance(Float cosTheta) const {
        S r;
        for (int i = 0; i < S::kSize; ++i)
            r[i] = film->reflectance(i, filmSide(cosTheta, i));
        return r;
    }
};

}  // namespace lamina
