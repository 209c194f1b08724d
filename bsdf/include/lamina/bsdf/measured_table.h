// A measured BSDF in the adaptive parameterisation of Dupuy and Jakob 2018, "An Adaptive
// Parameterization for Efficient Material Acquisition and Rendering" (ACM TOG 37(6)), as the RGL
// material database stores it: the tables of one file, checked against each other, with the
// warps built from them. The bsdf library reads no file: the scene library reads the RGL file
// (renderer/scene, rgl_bsdf_file.h) into MeasuredBsdfFields and builds this table.
//
// Directions wo (the viewer's) and wi (the light's), both above the surface, map to the unit
// square as u(theta, phi) = (sqrt(2 theta / pi), (phi + pi) / 2 pi). Every table but ndf and
// sigma depends on the direction wo through its angles (phi_o, theta_o), tabulated on the grids
// phi_i and theta_i (the files name the viewer's direction "incident", as Mitsuba's wi):
//   ndf        D(wm) at u(wm): the microfacet distribution.
//   sigma      sigma(wo) at u(wo): its projected area, integral of D(m) max(0, wo.m) dm.
//   vndf       the density of u(wm) under the visible normals of wo (section 5.1): the warp
//              whose inverse takes u(wm) to the point `ui` of the unit square where the
//              measurement was tabulated.
//   luminance  the density of `ui` that sample() draws from (the luminance of the values).
//   spectra    fr at `ui` per wavelength (the grid `wavelengths`, nm), or `rgb` per channel.
// and eval = fr(ui) D(wm) / (4 sigma(wo)) (the factor only when `jacobian` is set; otherwise
// the stored values include it), which is f(wo, wi) |cos theta_i|. An isotropic file (at most
// two phi_i) stores u(wm) with phi measured from phi_o. An anisotropic one whose phi_i cover
// half or a quarter of the circle is symmetric: wo is folded into it (by a half turn, or by
// mirroring x and y) and wi with it, as Mitsuba 3's `measured` plugin does.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "lamina/core/marginal_warp_2d.h"
#include "lamina/core/vector.h"

namespace lamina {

/// One tensor of a file: its shape (slowest axis first) and its values.
struct MeasuredTensor {
    std::vector<std::size_t> shape;
    std::vector<float> values;
};

/// The fields of an RGL file, as the file holds them. Either spectra (with wavelengths) or rgb.
struct MeasuredBsdfFields {
    std::string description;
    MeasuredTensor thetaI, phiI, ndf, sigma, vndf, luminance;
    std::optional<MeasuredTensor> spectra, wavelengths, rgb;
    bool jacobian = true;
};

class MeasuredBsdfTable {
  public:
    /// Checks every shape against the others and every value (finite; ndf and sigma >= 0),
    /// and builds the warps; a problem is an std::invalid_argument naming the field and what
    /// was expected (the reader of the file adds its name).
    explicit MeasuredBsdfTable(MeasuredBsdfFields fields);

    const std::string& description() const { return description_; }
    /// Whether the file stores spectra (else RGB values).
    bool spectral() const { return !wavelengths_.empty(); }
    const std::vector<float>& wavelengths() const { return wavelengths_; }
    bool isotropic() const { return isotropic_; }
    /// The resolution of the values: (phi_i, theta_i, channels, rows, columns).
    std::vector<std::size_t> valueShape() const { return valueShape_; }

    /// What eval and pdf read for one pair of directions (in the upper hemisphere, folded).
    struct Lookup {
        Vec2d ui;          ///< where the values are tabulated
        double params[2];  ///< (phi_o, theta_o)
        double scale;      ///< D(wm) / (4 sigma(wo)), or 1 when the values include it
        double pdf;        ///< of sample() returning wi, per solid angle
    };
    /// The lookup of (wo, wi), or none when they are not both on one side of the surface (the
    /// material is two-sided: below it, wo and wi are mirrored to above).
    std::optional<Lookup> lookup(const Vec3d& wo, const Vec3d& wi) const;
    /// The stored value at a lookup: at a wavelength (nm) of a spectral file, or in channel 0, 1,
    /// 2 of an RGB file. Negative stored values count as 0.
    double value(const Lookup& l, double channel) const;
    /// The linear Rec.709 value of channel c (0, 1, 2) at a lookup: an RGB file's own, or the
    /// spectra reduced to RGB under D65 (CIE 1931 observer; reduced once, when the table is
    /// built). Negative values count as 0.
    double rgbValue(const Lookup& l, int c) const;
    /// A direction wi drawn for wo with the luminance warp and then the visible normals'
    /// (section 5): none when it leaves below the surface.
    std::optional<Vec3d> sample(const Vec3d& wo, const Vec2d& u) const;

  private:
    std::string description_;
    bool isotropic_ = true, jacobian_ = true;
    int reduction_ = 1;  ///< 1, or 2 or 4 when phi_i cover half or a quarter turn
    std::vector<float> wavelengths_;
    std::vector<std::size_t> valueShape_;
    MarginalWarp2D ndf_, sigma_, vndf_, luminance_, values_, rgb_;
};

}  // namespace lamina
