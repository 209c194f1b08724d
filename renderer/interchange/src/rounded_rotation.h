// Rotations as exported scene files write them: a rotation matrix rounded to 6-8 significant
// digits is not orthogonal to 1e-9, yet means a rotation. The importers take a matrix whose
// columns are orthogonal (and, for a rotation, of unit length) to within
// kRoundedRotationTolerance as the rotation it rounds, and say so in one warning.
#pragma once

#include <glm/mat3x3.hpp>
#include <string>

namespace lamina::render {

/// The largest deviation a rounded rotation may have: |cos| of the angle between two columns
/// and |length - 1| of a column. 1e-4 is a rotation written with 4 significant digits; a shear
/// or an uneven scale meant as such is far larger.
inline constexpr double kRoundedRotationTolerance = 1e-4;

/// How far `a`'s columns are from orthogonal: the largest |cos| of the angle between two.
double columnSkew(const glm::dmat3& a);
/// How far `a`'s columns are from unit length: the largest |length - 1|.
double columnScaleError(const glm::dmat3& a);
/// The rotation (or reflection, when det < 0) nearest `a` in the sense exported files round:
/// Gram-Schmidt on the columns, z first, then y, x completing the frame with `a`'s handedness.
glm::dmat3 orthonormalised(const glm::dmat3& a);
/// A deviation for a warning: "3.2e-07".
std::string deviationText(double deviation);

}  // namespace lamina::render
