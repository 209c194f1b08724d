// The linear Rec.709 colour, under D65, of a fringe: for each channel c,
//   F_c(x) = integral s_c(lambda) exp(2 pi i x / lambda) d lambda,
// where s_c is the channel's sensitivity to a reflectance spectrum under D65 (the CIE 1931
// colour matching functions times D65, turned into Rec.709 and normalised so that a constant
// reflectance 1 is RGB (1, 1, 1): the weights of reflectanceColor()). So the colour of the
// reflectance cos(2 pi x / lambda + psi) is Re(exp(i psi) F_c(x)): what RGB mode needs to
// integrate a thin film's interference fringes in closed form (Belcour and Barla 2017,
// "A Practical Extension to Microfacet Theory for the Modeling of Varying Iridescence",
// section 4: the spectral integral of each Fourier term is the sensitivity's Fourier
// transform at the term's optical path difference). Belcour and Barla fit Gaussians to the
// transform; lamina tabulates the transform of its own CIE tables instead.
#pragma once

#include <array>
#include <complex>
#include <vector>

namespace lamina {

class FringeColors {
  public:
    /// The table of lamina's CIE tables and D65, computed on first use (some 20 ms).
    static const FringeColors& rec709();

    /// F_c(x) at the optical path difference x in nm (x >= 0); 0 beyond kMaxPathDifference,
    /// where the fringes of every channel have averaged out to below 1e-3.
    std::complex<double> operator()(int channel, double pathDifferenceNm) const;

    /// F_c(m x) for m = 1 .. count into out[0 .. count - 1]: the same values as operator(),
    /// with the carrier exp(2 pi i m x nu_c) turned by one multiplication per m instead of a
    /// sine and cosine each (a film's series needs a run of multiples).
    void atMultiples(int channel, double pathDifferenceNm, int count,
                     std::complex<double>* out) const;

    /// The channel's centre wavelength: 1 / the mean wavenumber of its sensitivity's positive
    /// part (596, 538 and 452 nm for red, green and blue).
    double meanWavelength(int channel) const { return 1.0 / meanWavenumber_[channel]; }

    static constexpr double kMaxPathDifference = 40000.0;  ///< nm
    static constexpr double kStep = 20.0;                  ///< nm between tabulated x

  private:
    FringeColors();
    // Tabulated is F_c(x) exp(-2 pi i x nu_c), demodulated by the channel's centre wavenumber
    // nu_c: it varies slowly in x and interpolates linearly.
    std::array<std::vector<std::complex<double>>, 3> envelope_;
    std::array<double, 3> meanWavenumber_{};
};

}  // namespace lamina
