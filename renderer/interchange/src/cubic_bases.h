// Segments of other curve bases written as cubic Bezier segments (the same curve), for the
// importers' curves: lamina's `curves` shape is cubic Bezier strands. Templates over the point
// type, so a control point may carry its radius as a fourth coordinate: Embree interpolates
// the radius with the same basis as the position, and so does every renderer whose curves
// these translate.
#pragma once

#include <array>

namespace lamina::render {

/// A uniform cubic B-spline segment's Bezier control points: the standard change of basis
/// (e.g. Farin, "Curves and Surfaces for CAGD", the B-spline to Bezier conversion of a uniform
/// knot vector), exact.
template <class P>
std::array<P, 4> bsplineToBezier(const P& p0, const P& p1, const P& p2, const P& p3) {
    return {(p0 + 4.0 * p1 + p2) / 6.0, (2.0 * p1 + p2) / 3.0, (p1 + 2.0 * p2) / 3.0,
            (p1 + 4.0 * p2 + p3) / 6.0};
}

/// A quadratic Bezier segment raised to a cubic (degree elevation: the same curve).
template <class P>
std::array<P, 4> raiseQuadratic(const P& q0, const P& q1, const P& q2) {
    return {q0, (q0 + 2.0 * q1) / 3.0, (2.0 * q1 + q2) / 3.0, q2};
}

/// A straight segment as a cubic Bezier one: control points at 1/3 and 2/3, so the point and
/// any quantity interpolated with it run linearly in the parameter, as on the segment.
template <class P>
std::array<P, 4> raiseLinear(const P& a, const P& b) {
    return {a, (2.0 * a + b) / 3.0, (a + 2.0 * b) / 3.0, b};
}

}  // namespace lamina::render
