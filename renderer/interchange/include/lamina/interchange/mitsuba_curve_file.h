// The control-point files of Mitsuba 3's `bsplinecurve` and `linearcurve` shapes (mitsuba3
// src/shapes/bsplinecurve.cpp, linearcurve.cpp): one control point a line, "x y z radius", the
// curves separated by blank lines. Read by the Mitsuba importer, which turns them into lamina
// `curves` shapes; bounded for fuzzing (the sizes below).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/vec3.hpp>

namespace lamina::render {

struct CurveControlPoint {
    glm::dvec3 position;
    double radius = 0;
};

/// The curves of a file, each its control points in file order.
using CurveFileCurves = std::vector<std::vector<CurveControlPoint>>;

/// The largest curve file read (bytes), and the most control points in one: each control point
/// becomes at most 3 Bezier control points, which must fit in the one lamina shape that holds
/// them (CurvesDesc::kMaxPoints, 2^22).
inline constexpr std::uintmax_t kMaxCurveFileBytes = std::uintmax_t(1) << 28;
inline constexpr std::size_t kMaxCurveFilePoints = (std::size_t(1) << 22) / 3;
/// The longest line (characters), Mitsuba's own limit.
inline constexpr std::size_t kMaxCurveFileLine = 1024;

/// Reads `file`; every curve must have at least `minPointsPerCurve` control points (4 for a
/// cubic B-spline, 2 for a polyline). Bad input is an InputError "FILE:LINE: what was expected".
CurveFileCurves readMitsubaCurveFile(const std::filesystem::path& file,
                                     std::size_t minPointsPerCurve);

}  // namespace lamina::render
