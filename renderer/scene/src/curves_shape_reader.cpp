// The `curves` shape (docs/scene-format.md, "curves"): strands of cubic Bezier segments with a
// width that runs linearly from each strand's root to its tip, or a width per control point
// (`widths`, interpolated by the segments' Bezier basis as the positions are), drawn as round
// tubes or as flat ribbons facing the ray. Bounded for fuzzing: CurvesDesc::kMaxPoints control
// points a shape.
#include <cmath>
#include <optional>

#include "shape_readers.h"

namespace lamina::render {

namespace {

// One strand's control points, 3k + 1 of them (k >= 1 segments), appended to `c`.
void readStrand(const JsonReader& strands, std::size_t index, CurvesDesc& c) {
    const Json& v = strands.value()[index];
    const std::string path = strands.indexPath(index);
    if (!v.is_array() || v.size() < 4 || (v.size() - 1) % 3 != 0)
        strands.fail("expected at index " + std::to_string(index) +
                     " a strand of 3k + 1 control points [x, y, z] (k >= 1 cubic Bezier "
                     "segments sharing their end points)");
    if (c.points.size() + v.size() > CurvesDesc::kMaxPoints)
        strands.fail("more than " + std::to_string(CurvesDesc::kMaxPoints) +
                     " control points in one curves shape (split it into several)");
    const auto first = std::uint32_t(c.points.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
        const Json& p = v[i];
        if (!p.is_array() || p.size() != 3)
            strands.fail("expected [x, y, z] at " + path + "[" + std::to_string(i) + "]");
        Vec3<float> q;
        for (int k = 0; k < 3; ++k)
            q[k] = float(strands.checkNumber(p[std::size_t(k)], path, Range::any()));
        c.points.push_back(q);
    }
    for (std::uint32_t s = 0; 3 * s + 3 < std::uint32_t(v.size()); ++s)
        c.segments.push_back(first + 3 * s);
}

// Strand `index`'s widths, one per control point (`count` of them), as radii appended to `c`.
void readStrandWidths(const JsonReader& widths, std::size_t index, std::size_t count,
                      double stretch, CurvesDesc& c) {
    const Json& v = widths.value()[index];
    const std::string path = widths.indexPath(index);
    if (!v.is_array() || v.size() != count)
        widths.fail("expected at index " + std::to_string(index) + " a list of " +
                    std::to_string(count) + " widths, one per control point of strand " +
                    std::to_string(index));
    for (std::size_t k = 0; k < count; ++k)
        c.radii.push_back(float(
            0.5 * stretch *
            widths.checkNumber(v[k], path + "[" + std::to_string(k) + "]", Range::nonNegative())));
}

}  // namespace

ShapeDesc readCurves(const JsonReader& r, const std::string& name, SceneMaterials& materials) {
    CurvesDesc c;
    c.name = name;
    c.material = materials.materialOf(r);
    if (r.has("emission"))
        r.failAt("emission", "curves do not emit (give the light to another shape)");
    c.alpha = readAlpha(r, materials);
    if (c.alpha.texture >= 0) r.failAt("alpha", "curves take a number alpha, not a texture");
    c.shape = r.choice("curve", CurveShape::Cylinder, kCurveShapeNames);
    const double width = r.number("width", 0.01, Range::positive());
    const double width0 = r.number("width0", width, Range::positive());
    const double width1 = r.number("width1", width, Range::positive());
    const bool perPoint = r.has("widths");
    if (perPoint && (r.has("width") || r.has("width0") || r.has("width1")))
        r.failAt("widths", "give widths per control point or width / width0 / width1, not both");
    const JsonReader strands = r.child("strands");
    if (!strands.value().is_array() || strands.value().empty())
        strands.fail("expected a non-empty array of strands");
    const std::optional<JsonReader> widths =
        perPoint ? std::optional<JsonReader>(r.child("widths")) : std::nullopt;
    if (widths && (!widths->value().is_array() || widths->value().size() != strands.value().size()))
        widths->fail("expected one list of widths per strand (" +
                     std::to_string(strands.value().size()) + " strands)");
    const Mat4 m = readTransform(r);
    // Widths scale with the transform's mean stretch (a curve stays round).
    const double stretch = std::cbrt(std::abs(glm::determinant(glm::dmat3(m))));
    if (!(stretch > 0) || !std::isfinite(stretch))
        r.failAt("transform", "expected an invertible transform");
    for (std::size_t i = 0; i < strands.value().size(); ++i) {
        const std::size_t first = c.points.size();
        readStrand(strands, i, c);
        const std::size_t n = c.points.size() - first;
        if (widths) {
            readStrandWidths(*widths, i, n, stretch, c);
            continue;
        }
        for (std::size_t k = 0; k < n; ++k) {
            const double t = double(k) / double(n - 1);
            c.radii.push_back(float(0.5 * stretch * ((1 - t) * width0 + t * width1)));
        }
    }
    r.finish();
    const char* key = r.has("transform") ? "transform" : "strands";
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        const Vec3d p = Vec3d(m * glm::dvec4(Vec3d(c.points[i]), 1.0));
        if (!(std::abs(p.x) <= kMaxSceneCoordinate && std::abs(p.y) <= kMaxSceneCoordinate &&
              std::abs(p.z) <= kMaxSceneCoordinate))
            checkCoordinates(r, key, p, "control point " + std::to_string(i) + " at");
        c.points[i] = Vec3<float>(p);
        if (!std::isfinite(c.radii[i]) || !(c.radii[i] > 0 || (perPoint && c.radii[i] == 0)))
            r.failAt(perPoint ? "widths" : "width",
                     "the width is out of float's range once transformed");
    }
    return c;
}

}  // namespace lamina::render
