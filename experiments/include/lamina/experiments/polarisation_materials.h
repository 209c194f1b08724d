// `lamina polarisation MATERIAL...`: the Mueller matrix of specular reflection from air on a
// material (a metal or glass by name, or an n/k file; material_names.h) against the angle of
// incidence, per wavelength, in lamina's convention (docs/polarisation.md: x = s on the incident
// and reflected rays, fresnelReflectionMueller of the complex amplitudes r_s, r_p).
//
// Per wavelength and angle (0 to 90 degrees in kMuellerAngleStep): the 16 elements M_ij, of
// which a reader looks at M00 = (Rs + Rp) / 2 (the unpolarised reflectance the other modes use)
// and the normalised M_ij / M00; and the derived quantities, Rs = |r_s|^2, Rp = |r_p|^2, the
// diattenuation (Rs - Rp) / (Rs + Rp) = M01 / M00 and the retardance, the phase of
// r_s conj(r_p) = atan2(M23, M22). The retardance is reported in [-90, 270) degrees: from air
// onto any passive medium it lies in [0, 180] (180 at normal incidence, where r_p = -r_s; 0 at
// grazing, where r_s = r_p = -1), so that range is never cut by the wrap.
//
// Found from the data per wavelength: the principal angle, where M22 = Re(r_s conj(r_p))
// changes sign (the retardance is 90 degrees on a metal; on a dielectric, where r_s conj(r_p) is
// real, it is Brewster's angle, where r_p = 0 and the retardance jumps from 180 to 0), located
// as the sign change of the tabulated M22 and refined by bisection of the same function; and
// the angle of the minimum of Rp (Brewster's angle of a dielectric, the pseudo-Brewster angle
// of a metal), located on the table and refined by golden-section search.
#pragma once

#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "lamina/core/mueller_matrix.h"
#include "lamina/experiments/report.h"

namespace lamina::experiments {

inline constexpr double kMuellerAngleStep = 0.5;  ///< degrees: 181 angles from 0 to 90

struct PolarisationMaterialsInputs {
    std::vector<std::string> materials;
    std::vector<double> wavelengths{450, 550, 650};  ///< nm
};

/// The specular reflection Mueller matrix of an interface from air onto the relative index
/// `index` (n + i k) at `degrees` of incidence.
MuellerMatrix<double> specularReflectionMueller(std::complex<double> index, double degrees);

/// The reflection of one wavelength against angle.
struct MuellerCurve {
    double nm = 0;
    std::complex<double> index;                  ///< n + i k at nm
    std::vector<MuellerMatrix<double>> mueller;  ///< per angle (degrees())
    std::vector<double> rs, rp;                  ///< |r_s|^2, |r_p|^2 per angle
    std::vector<double> diattenuation;           ///< (Rs - Rp) / (Rs + Rp) per angle
    std::vector<double> retardance;              ///< degrees, in [-90, 270), per angle
    /// Degrees of incidence where M22 changes sign: Brewster's angle of a dielectric, the
    /// principal angle (retardance 90 degrees) of a metal; none if M22 keeps its sign.
    std::optional<double> principalAngle;
    double minimumRpAngle = 0;  ///< degrees where Rp is least
    double minimumRp = 0;
};

struct PolarisationMaterial {
    std::string stem;  ///< the argument's file-name stem: the report's file names
    std::string name;  ///< the n/k data's own name (titles)
    bool conductor = false;
    std::vector<MuellerCurve> curves;  ///< per wavelength of the inputs
};

struct PolarisationMaterialsResult {
    std::vector<double> degrees;  ///< the angles of incidence: 0, kMuellerAngleStep, ..., 90
    std::vector<PolarisationMaterial> materials;
};

PolarisationMaterialsResult runPolarisationMaterials(const PolarisationMaterialsInputs& inputs);

/// Per material STEM_mueller.csv (every number), the figures STEM_mueller (the 4x4 elements),
/// STEM_reflectance (Rs, Rp, their mean), STEM_diattenuation and STEM_retardance, and summary.md
/// with the principal and minimum-Rp angles per wavelength.
void writePolarisationMaterialsReport(const PolarisationMaterialsResult& result, Report& report);

}  // namespace lamina::experiments
