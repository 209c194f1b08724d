// Mueller matrices: how an optical element or a surface interaction maps the Stokes vector of
// the light arriving (in its input frame) to the light leaving (in its output frame), with
// lamina's convention of stokes.h. The element matrices are the standard ones (Collett,
// "Field Guide to Polarization", SPIE 2005, pp. 14-18), written out for that convention;
// docs/polarisation.md derives each.
#pragma once

#include <complex>

#include "lamina/core/fresnel_amplitudes.h"
#include "lamina/core/stokes.h"

namespace lamina {

/// A 4x4 Mueller matrix whose elements are numbers (float, double) or spectra (one matrix per
/// wavelength of a SampledSpectrum, the element-wise products of the spectrum types doing the
/// per-wavelength arithmetic).
template <typename E>
struct MuellerMatrix {
    std::array<std::array<E, 4>, 4> m{};  ///< m[row][column]

    constexpr MuellerMatrix() = default;
    /// v times the identity: 0 is the zero matrix, 1 the identity.
    constexpr explicit MuellerMatrix(const E& v) {
        for (int i = 0; i < 4; ++i)
            m[i][i] = v;
    }

    static constexpr MuellerMatrix zero() { return {}; }
    static constexpr MuellerMatrix identity() { return MuellerMatrix(E(1)); }
    static constexpr MuellerMatrix diagonal(const E& a, const E& b, const E& c, const E& d) {
        MuellerMatrix r;
        r.m[0][0] = a;
        r.m[1][1] = b;
        r.m[2][2] = c;
        r.m[3][3] = d;
        return r;
    }

    E& operator()(int row, int column) { return m[row][column]; }
    const E& operator()(int row, int column) const { return m[row][column]; }

    friend MuellerMatrix operator*(const MuellerMatrix& a, const MuellerMatrix& b) {
        MuellerMatrix r;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                E sum = a.m[i][0] * b.m[0][j];
                for (int k = 1; k < 4; ++k)
                    sum += a.m[i][k] * b.m[k][j];
                r.m[i][j] = sum;
            }
        return r;
    }
    MuellerMatrix& operator*=(const MuellerMatrix& b) { return *this = *this * b; }
    friend StokesVector<E> operator*(const MuellerMatrix& a,
                                     const StokesVector<E>& s) requires std::floating_point<E> {
        StokesVector<E> r{};
        for (int i = 0; i < 4; ++i)
            r[i] = a.m[i][0] * s[0] + a.m[i][1] * s[1] + a.m[i][2] * s[2] + a.m[i][3] * s[3];
        return r;
    }
    /// Scaling by a number or, element-wise, by a spectrum of the elements' kind.
    template <typename F>
    requires requires(E e, F f) { e *= f; }
    MuellerMatrix& operator*=(const F& scale) {
        for (auto& row : m)
            for (E& v : row)
                v *= scale;
        return *this;
    }
    template <typename F>
    requires requires(E e, F f) { e *= f; }
    friend MuellerMatrix operator*(MuellerMatrix a, const F& scale) { return a *= scale; }
    template <typename F>
    requires requires(E e, F f) { e /= f; }
    MuellerMatrix& operator/=(const F& scale) {
        for (auto& row : m)
            for (E& v : row)
                v /= scale;
        return *this;
    }
    template <typename F>
    requires requires(E e, F f) { e /= f; }
    friend MuellerMatrix operator/(MuellerMatrix a, const F& scale) { return a /= scale; }
    MuellerMatrix& operator+=(const MuellerMatrix& b) {
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                m[i][j] += b.m[i][j];
        return *this;
    }
    friend MuellerMatrix operator+(MuellerMatrix a, const MuellerMatrix& b) { return a += b; }

    MuellerMatrix transposed() const {
        MuellerMatrix r;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                r.m[i][j] = m[j][i];
        return r;
    }
};

/// Turning the reference frame by `phi` about the direction (x' = cos(phi) x + sin(phi) y):
/// the matrix that re-expresses the same light in the new frame. It is not an optical element.
template <std::floating_point T>
MuellerMatrix<T> stokesRotation(T phi) {
    const T c = std::cos(T(2) * phi), s = std::sin(T(2) * phi);
    MuellerMatrix<T> r = MuellerMatrix<T>::identity();
    r(1, 1) = c;
    r(1, 2) = s;
    r(2, 1) = -s;
    r(2, 2) = c;
    return r;
}

/// The matrix that carries a Stokes vector from frame `from` into the frame with x axis `toX`
/// of the same direction.
template <std::floating_point T>
MuellerMatrix<T> stokesRotation(const StokesFrame<T>& from, const Vec3<T>& toX) {
    return stokesRotation(frameTurn(from, toX));
}

/// m followed by a frame turn on its output side: stokesRotation(phi) * m, touching only rows 1
/// and 2 (the turn given as its doubled angle, doubledFrameTurn, or as phi).
template <typename E, std::floating_point T>
void turnOutputFrame(MuellerMatrix<E>& m, const DoubledTurn<T>& turn) {
    for (int j = 0; j < 4; ++j) {
        const E r1 = m(1, j), r2 = m(2, j);
        m(1, j) = r1 * turn.c + r2 * turn.s;
        m(2, j) = r2 * turn.c - r1 * turn.s;
    }
}
template <typename E, std::floating_point T>
void turnOutputFrame(MuellerMatrix<E>& m, T phi) {
    turnOutputFrame(m, DoubledTurn<T>::of(phi));
}

/// m preceded by a frame turn on its input side: m * stokesRotation(phi), touching only columns
/// 1 and 2.
template <typename E, std::floating_point T>
void turnInputFrame(MuellerMatrix<E>& m, const DoubledTurn<T>& turn) {
    for (int i = 0; i < 4; ++i) {
        const E c1 = m(i, 1), c2 = m(i, 2);
        m(i, 1) = c1 * turn.c - c2 * turn.s;
        m(i, 2) = c1 * turn.s + c2 * turn.c;
    }
}
template <typename E, std::floating_point T>
void turnInputFrame(MuellerMatrix<E>& m, T phi) {
    turnInputFrame(m, DoubledTurn<T>::of(phi));
}

/// An element `m` expressed in frames turned by `theta` from the ones it is written in: an
/// element whose axis is at theta from x acts as m does on light seen from its own axis.
template <std::floating_point T>
MuellerMatrix<T> rotatedElement(const MuellerMatrix<T>& m, T theta) {
    return stokesRotation(-theta) * m * stokesRotation(theta);
}

/// An ideal depolariser of albedo `a` (a number or a spectrum): whatever arrives, unpolarised
/// light of a times its radiance leaves. Diffuse reflection and the random walks are modelled
/// as this.
template <typename E>
MuellerMatrix<E> depolarising(const E& a) {
    return MuellerMatrix<E>::diagonal(a, E(0), E(0), E(0));
}

/// An ideal linear polariser whose transmission axis is at `theta` from x (towards y).
template <std::floating_point T>
MuellerMatrix<T> linearPolariser(T theta) {
    const T c = std::cos(T(2) * theta), s = std::sin(T(2) * theta);
    MuellerMatrix<T> r;
    r.m = {{{T(1), c, s, T(0)}, {c, c * c, c * s, T(0)}, {s, c * s, s * s, T(0)}, {}}};
    return r * T(0.5);
}

/// The Mueller matrix of fields that add as intensities, each of the form E_s -> a E_s,
/// E_p -> b E_p in frames whose x axes are s (the input's and the output's): with the sums
/// A = sum |a|^2, B = sum |b|^2 and sum a conj(b) = u + i v,
///   [[ (A+B)/2, (A-B)/2, 0, 0], [(A-B)/2, (A+B)/2, 0, 0], [0, 0, u, v], [0, 0, -v, u]].
template <std::floating_point T>
MuellerMatrix<T> incoherentSumMueller(T aa, T bb, std::complex<T> w) {
    MuellerMatrix<T> r;
    r(0, 0) = r(1, 1) = T(0.5) * (aa + bb);
    r(0, 1) = r(1, 0) = T(0.5) * (aa - bb);
    r(2, 2) = r(3, 3) = w.real();
    r(2, 3) = w.imag();
    r(3, 2) = -w.imag();
    return r;
}

/// The Mueller matrix of one field map E_s -> a E_s, E_p -> b E_p (incoherentSumMueller of
/// one term).
template <std::floating_point T>
MuellerMatrix<T> amplitudeMueller(std::complex<T> a, std::complex<T> b) {
    return incoherentSumMueller(std::norm(a), std::norm(b), a * std::conj(b));
}

/// An ideal linear retarder with its fast axis at `theta` from x: the slow (perpendicular)
/// component's phase lags by `delta`, E_y -> E_y exp(i delta) in the element's frame, so S3
/// gains sin(delta) S2.
template <std::floating_point T>
MuellerMatrix<T> linearRetarder(T theta, T delta) {
    return rotatedElement(amplitudeMueller(std::complex<T>(T(1)), std::polar(T(1), delta)), theta);
}

/// Fresnel reflection in the s/p frames of the incident and reflected rays (x = s on both).
/// Its [0][0] is the unpolarised reflectance of fresnel_equations.h.
template <std::floating_point T>
MuellerMatrix<T> fresnelReflectionMueller(const FresnelAmplitudes<T>& f) {
    return amplitudeMueller(f.rs, f.rp);
}

/// Fresnel transmission in the s/p frames of the incident and transmitted rays, as power per
/// unit interface area (the factor Re(n2 cos_t) / (n1 cos_i)); its [0][0] is 1 minus the
/// reflectance for a lossless interface. A radiance transport adds the 1/eta^2 of the
/// solid-angle compression outside this matrix, as the unpolarised BSDFs do.
template <std::floating_point T>
MuellerMatrix<T> fresnelTransmissionMueller(const FresnelAmplitudes<T>& f) {
    return amplitudeMueller(f.ts, f.tp) * f.transmittedPowerFactor;
}

}  // namespace lamina
