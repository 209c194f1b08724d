// pbrt-v4 shapes and area lights -> lamina shapes (pbrt_shapes.cpp).
#pragma once

#include <optional>

#include "pbrt_translation.h"

namespace lamina::render::pbrt {

/// A 4x4 transform as lamina's row-major "matrix" list.
Json rowMajor(const glm::dmat4& m);
/// The lamina shape, or nullopt when it is omitted (pbrt's "interface" material), with its
/// warning written. `inObject`: the shape is part of an object (an ObjectBegin block, or a
/// moving shape's own object): its quadrics must then stay round, as they cannot be placed by
/// an instance of their own.
std::optional<Json> translateShape(TranslationContext& context, const ShapeDef& shape,
                                   bool inObject);
/// The lamina `curves` shape of a `Shape "curve"` (one strand, in its object space;
/// pbrt_curves.cpp).
Json curveShape(TranslationContext& context, const Entity& curve);
/// A JSON array of shapes being written: a shape appended to it becomes more strands of the
/// last one when both are `curves` alike in every key but their strands (pbrt_curves.cpp).
class ShapeList {
  public:
    explicit ShapeList(Json& shapes) : shapes_(shapes) {}
    void append(Json shape);

  private:
    Json& shapes_;
    std::size_t lastPoints_ = 0;  ///< control points of the last shape (curves)
};
/// The `emission` of a shape under AreaLightSource `light`; `areas`: the shape's face areas
/// after its transform (empty when unknown), for pbrt's `power`.
Json areaEmission(TranslationContext& context, const Entity& light,
                  const std::vector<double>& areas);

}  // namespace lamina::render::pbrt
