// The shapes of one kind in a list of shapes (SceneDesc::shapes, ObjectDesc::shapes), for tests
// that reach a mesh, sphere or disk by its place among its own kind.
#pragma once

#include <variant>
#include <vector>

#include "lamina/scene/shape_description.h"

namespace lamina::testing {

/// The shapes of the kind `Kind` (render::MeshDesc, SphereDesc, DiskDesc), in order, copied.
template <class Kind>
std::vector<Kind> shapesOf(const std::vector<render::ShapeDesc>& shapes) {
    std::vector<Kind> out;
    for (const render::ShapeDesc& shape : shapes)
        if (const auto* s = std::get_if<Kind>(&shape)) out.push_back(*s);
    return out;
}

}  // namespace lamina::testing
