// Mitsuba 3's `bsplinecurve` and `linearcurve` shapes (mitsuba3 src/shapes/bsplinecurve.cpp,
// linearcurve.cpp) -> a lamina `curves` shape: every curve of the file one strand of cubic
// Bezier segments, with a width per control point. Mitsuba moves the control points by
// to_world and leaves their radii as the file gives them ("the control points' radii are
// invariant to this transformation"), so the strands are written in world space, without a
// transform (which lamina would scale the widths by), and the widths are the file's diameters.
#include <array>
#include <string>

#include <glm/vec4.hpp>

#include "cubic_bases.h"
#include "lamina/interchange/mitsuba_curve_file.h"
#include "mitsuba_translation.h"

namespace lamina::render::mitsuba {

namespace {

// A control point with its radius as a fourth coordinate: the basis changes carry both.
using P4 = glm::dvec4;

// One curve's segments as Bezier control points, consecutive segments sharing an end point
// (the B-spline's shared end point is the same expression in both segments: bit-identical).
std::vector<P4> bezierPoints(const std::vector<P4>& cp, bool bspline) {
    std::vector<P4> out;
    const std::size_t span = bspline ? 3 : 1;
    for (std::size_t i = 0; i + span < cp.size(); ++i) {
        const std::array<P4, 4> b = bspline
                                        ? bsplineToBezier(cp[i], cp[i + 1], cp[i + 2], cp[i + 3])
                                        : raiseLinear(cp[i], cp[i + 1]);
        for (std::size_t k = out.empty() ? 0 : 1; k < 4; ++k)
            out.push_back(b[k]);
    }
    return out;
}

bool namesTexture(const Json& v) {
    if (v.is_object()) {
        if (v.contains("texture")) return true;
        for (const auto& [key, value] : v.items())
            if (namesTexture(value)) return true;
    } else if (v.is_array()) {
        for (const Json& e : v)
            if (namesTexture(e)) return true;
    }
    return false;
}

}  // namespace

void warnCurveTextures(Translation& t, Plugin& p, const Json& material) {
    const Json* m = &material;
    if (material.is_string() && t.scene.contains("materials") &&
        t.scene["materials"].contains(material.get<std::string>()))
        m = &t.scene["materials"][material.get<std::string>()];
    if (namesTexture(*m))
        p.warn(
            "a texture on the curves lands elsewhere: Mitsuba's uv on curves is (the angle "
            "around the tube, the position along all the file's segments), lamina's (the "
            "position along each segment, 0.5)");
}

Json curveShape(Translation& t, Plugin& p) {
    const bool bspline = p.type() == "bsplinecurve";
    const auto file = p.file("filename");
    if (!file) p.fail("needs a filename (the curve file: \"x y z radius\" lines)");
    const auto transform = p.transform("to_world");
    const glm::dmat4 toWorld = transform ? transform->matrix : glm::dmat4(1.0);
    // A cubic B-spline needs four control points a curve, a polyline two (as Mitsuba refuses).
    const CurveFileCurves curves = readMitsubaCurveFile(*file, bspline ? 4 : 2);
    t.diagnostics.files.push_back(*file);
    Json strands = Json::array(), widths = Json::array();
    for (const auto& curve : curves) {
        std::vector<P4> cp;
        cp.reserve(curve.size());
        for (const CurveControlPoint& c : curve)
            cp.emplace_back(glm::dvec3(toWorld * glm::dvec4(c.position, 1.0)), c.radius);
        Json strand = Json::array(), strandWidths = Json::array();
        for (const P4& b : bezierPoints(cp, bspline)) {
            strand.push_back(Json::array({b.x, b.y, b.z}));
            strandWidths.push_back(2.0 * b.w);
        }
        strands.push_back(std::move(strand));
        widths.push_back(std::move(strandWidths));
    }
    if (!bspline)
        p.warn(
            "linearcurve became straight Bezier tubes: Mitsuba's spherical joints and end caps "
            "are not drawn (a strand's ends are open, and where it bends, its segments leave a "
            "wedge-shaped gap on the outside of the bend)");
    p.ignore("silhouette_sampling_weight", "lamina renders no derivatives");
    return {{"type", "curves"}, {"curve", "cylinder"}, {"strands", strands}, {"widths", widths}};
}

}  // namespace lamina::render::mitsuba
