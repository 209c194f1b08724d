// pbrt-v4's `Shape "curve"` -> lamina's `curves` shape with one strand (pbrt-v4 shapes.cpp,
// CreateCurves, for the parameters and defaults). Every segment becomes a cubic Bezier one:
// quadratic segments are raised to cubics, uniform B-splines converted to Bezier control
// points (their segments then share end points, as a lamina strand's do).
#include <array>
#include <string>

#include <glm/vec3.hpp>

#include "cubic_bases.h"
#include "lamina/core/error.h"
#include "pbrt_shapes.h"

namespace lamina::render::pbrt {

namespace {

// The most control points one curve may have: lamina's CurvesDesc::kMaxPoints (a B-spline of
// n points becomes 3 (n - 3) + 1 Bezier points).
constexpr std::size_t kMaxCurvePoints = std::size_t(1) << 22;

using P3 = glm::dvec3;

}  // namespace

Json curveShape(TranslationContext& ctx, const Entity& e) {
    const ParamList& params = e.params;
    const auto P = params.numbers("P", {"point3"}, 3);
    if (!P) ctx.fail(e.location, "curve: no \"point3 P\" parameter");
    std::vector<P3> cp;
    for (std::size_t i = 0; i + 2 < P->size(); i += 3)
        cp.emplace_back((*P)[i], (*P)[i + 1], (*P)[i + 2]);
    if (cp.size() > kMaxCurvePoints)
        ctx.fail(e.location, "curve: more than " + std::to_string(kMaxCurvePoints) +
                                 " control points (split the curve)");
    const std::string basis = params.string("basis", "bezier");
    const int degree = params.integer("degree", 3);
    if (basis != "bezier" && basis != "bspline")
        ctx.fail(e.location, "curve: basis \"" + basis + "\" is not supported (bezier, bspline)");
    if (degree != 2 && degree != 3)
        ctx.fail(e.location, "curve: degree " + std::to_string(degree) + " (expected 2 or 3)");
    const std::size_t d = std::size_t(degree);
    std::vector<std::array<P3, 4>> segments;
    if (basis == "bezier") {
        if (cp.size() < d + 1 || (cp.size() - 1) % d != 0)
            ctx.fail(e.location, "curve: " + std::to_string(cp.size()) +
                                     " control points; a degree " + std::to_string(degree) +
                                     " Bezier curve takes " + std::to_string(d + 1) + " + n * " +
                                     std::to_string(d));
        for (std::size_t i = 0; i + d < cp.size(); i += d)
            segments.push_back(d == 3 ? std::array<P3, 4>{cp[i], cp[i + 1], cp[i + 2], cp[i + 3]}
                                      : raiseQuadratic(cp[i], cp[i + 1], cp[i + 2]));
    } else {
        if (cp.size() < d + 1)
            ctx.fail(e.location, "curve: a degree " + std::to_string(degree) +
                                     " B-spline takes at least " + std::to_string(d + 1) +
                                     " control points");
        for (std::size_t i = 0; i + d < cp.size(); ++i)
            segments.push_back(d == 3 ? bsplineToBezier(cp[i], cp[i + 1], cp[i + 2], cp[i + 3])
                                      : raiseQuadratic((cp[i] + cp[i + 1]) / 2.0, cp[i + 1],
                                                       (cp[i + 1] + cp[i + 2]) / 2.0));
    }
    Json strand = Json::array();
    for (std::size_t s = 0; s < segments.size(); ++s)
        for (std::size_t k = s == 0 ? 0 : 1; k < 4; ++k)
            strand.push_back(Json::array({segments[s][k].x, segments[s][k].y, segments[s][k].z}));
    const std::string type = params.string("type", "flat");
    Json shape{{"type", "curves"}, {"strands", Json::array({strand})}};
    if (type == "cylinder") {
        shape["curve"] = "cylinder";
        ctx.warnOnce(e.location,
                     "curve \"cylinder\" became a round tube (pbrt-v4 draws a ribbon "
                     "facing the ray with a tube's normal): the same look, and light "
                     "that crosses the fibre leaves it from the far side");
    } else if (type == "flat" || type == "ribbon") {
        shape["curve"] = "flat";
        if (type == "ribbon") {
            params.numbers("N", {"normal3"}, 3);
            ctx.warnOnce(e.location,
                         "curve \"ribbon\" became a flat ribbon facing the ray: its "
                         "normals \"N\" ignored");
        }
        ctx.warnOnce(e.location,
                     "curve \"flat\": lamina's ribbon facing the ray is shaded with a "
                     "tube's normal (pbrt-v4's with the ribbon's)");
    } else {
        ctx.fail(e.location, "curve: type \"" + type + "\" (expected flat, ribbon or cylinder)");
    }
    const double width = params.number("width", 1.0);
    const double width0 = params.number("width0", width), width1 = params.number("width1", width);
    if (!(width0 > 0) || !(width1 > 0)) ctx.fail(e.location, "curve: the widths must be > 0");
    if (width0 == width1) {
        shape["width"] = width0;
    } else {
        shape["width0"] = width0;
        shape["width1"] = width1;
    }
    if (params.has("splitdepth")) {
        params.integer("splitdepth", 3);
        ctx.warnOnce(e.location,
                     "curve: \"splitdepth\" ignored (Embree intersects the curve "
                     "itself, without splitting it)");
    }
    return shape;
}

namespace {

std::size_t controlPoints(const Json& curves) {
    std::size_t n = 0;
    for (const Json& strand : curves["strands"])
        n += strand.size();
    return n;
}

// Alike in every key but their strands (compared without copying the strands).
bool alikeButStrands(const Json& a, const Json& b) {
    if (a.size() != b.size()) return false;
    for (const auto& [key, value] : b.items())
        if (key != "strands" && (!a.contains(key) || a[key] != value)) return false;
    return true;
}

}  // namespace

void ShapeList::append(Json shape) {
    // A hair file is thousands of `Shape "curve"` lines of one material and width: one lamina
    // `curves` shape (one Embree geometry) holds them, where a shape each would cost a geometry
    // and its bounds per strand. The last shape's point count is kept, not recounted.
    const bool curves = shape.value("type", "") == "curves";
    const std::size_t points = curves ? controlPoints(shape) : 0;
    if (curves && !shapes_.empty() && shapes_.back().value("type", "") == "curves" &&
        alikeButStrands(shapes_.back(), shape) && lastPoints_ + points <= kMaxCurvePoints) {
        Json& strands = shapes_.back()["strands"];
        for (Json& strand : shape["strands"])
            strands.push_back(std::move(strand));
        lastPoints_ += points;
        return;
    }
    shapes_.push_back(std::move(shape));
    lastPoints_ = points;
}

}  // namespace lamina::render::pbrt
