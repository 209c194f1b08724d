// The film's sensor: what a sample's value becomes before the film adds it. pbrt-v4's camera
// sensor with its CIE 1931 curves (its default, "cie1931"): the sample's CIE XYZ times the
// imaging ratio exposure time x ISO / 100 (and lamina's `scale`), scaled down so that its
// largest XYZ component is at most the film's max_component_value (pbrt-v4's clamp, a biased
// estimator: it removes energy from bright samples), then the white balance: the Bradford
// adaptation from the white of CIE daylight at the given temperature to the image's white
// (white_balance.h). In spectral mode the film holds XYZ, which these act on directly; in RGB
// mode they act on the same XYZ of the Rec.709 colour the path carried, so the sensor is exact
// for RGB mode's colours, but the spectra it integrates are only spectral mode's.
#pragma once

#include <optional>

#include "lamina/core/spectrum.h"
#include "lamina/core/vector.h"

namespace lamina::render {

struct FilmDesc;  // scene_description.h

/// What the film accumulates: linear Rec.709 (RGB mode) or CIE XYZ (spectral mode).
enum class FilmSpace { Rec709, Xyz };

class FilmResponse {
  public:
    /// The identity: every value as it is.
    FilmResponse() = default;
    FilmResponse(const FilmDesc& film, FilmSpace space);

    bool isIdentity() const { return identity_; }
    /// The value (in the film's space) the film adds for a sample or splat of value `v`.
    Rgb<double> apply(const Rgb<double>& v) const;
    /// What the response makes of `other`, a quantity that travels with a sample of value `v`
    /// (a Stokes component S1..S3 of a polarised sample whose S0 is v): the same linear map,
    /// with the clamp's ratio of v, so that the pair keeps its proportion.
    Rgb<double> applyAlongside(const Rgb<double>& v, const Rgb<double>& other) const;
    /// The factor of the imaging ratio and the clamp for a sample of value `v` (1 for the
    /// identity): what the spectral film scales that sample's bins by. The white balance, a
    /// transform of XYZ, has no meaning for a spectrum and is not applied to them.
    double scaleAlongside(const Rgb<double>& v) const;

  private:
    /// The factor by which the clamp scales a value c (already times scale_): 1 unless its
    /// largest XYZ component exceeds maxComponent_.
    double clampRatio(const Vec3d& c) const;

    bool identity_ = true;
    double scale_ = 1;
    std::optional<double> maxComponent_;
    /// film space -> XYZ (for the clamp) and the white balance in the film's space
    Mat3<double> toXyz_{1.0};
    std::optional<Mat3<double>> balance_;
};

}  // namespace lamina::render
