// The spectral film's layers in the spectral OpenEXR layout of Fichet, Pacanowski and Wilkie,
// "An OpenEXR Layout for Spectral Images", Journal of Computer Graphics Techniques 10(3), 2021.
// An emissive (radiance) image stores each Stokes component k at each wavelength as a channel
// "S<k>.<wavelength>nm", the number written with a comma for its decimal separator
// ("S0.550,000000nm"), S0 alone for unpolarised light; R, G, B stay beside them for viewers that
// read no spectra. Its header says spectralLayoutVersion "1.0", emissiveUnits "W.m^-2.sr^-1"
// and, for a polarised image, polarisationHandedness, the convention of the sign of S3.
// lamina names each bin by its centre; its values are the bins' mean spectral radiance, per nm
// (docs/scene-format.md, "Spectral film").
#pragma once

#include <map>
#include <string>
#include <vector>

#include "lamina/render/spectral_film.h"

namespace lamina::render {

/// "S<stokes>.<nm>nm" with six decimals and a decimal comma: "S0.550,000000nm".
std::string spectralChannelName(int stokes, double nm);
/// The channels of a spectral film, component by component, bin by bin: the order of
/// SpectralFilm's values.
std::vector<std::string> spectralChannelNames(const SpectralBins& bins, int components);
/// The header attributes of the layout, for a film of `components` Stokes components.
std::map<std::string, std::string> spectralLayoutAttributes(int components);

}  // namespace lamina::render
