// QuadricDesc shapes as Embree user geometry: one primitive whose bounds, intersection and
// occlusion callbacks are quadric.h's double-precision functions. Embree calls them with the
// ray in the shape's space (an object's, inside an instance). An alpha cut-out is tested in
// the callbacks themselves, with the hash every other shape's filter uses (alpha_filter.h):
// Embree runs no filter function of its own on user geometry.
#pragma once

#include <embree3/rtcore.h>

#include "lamina/geometry/alpha_filter.h"

namespace lamina::render {

/// What the callbacks read: the shape and its alpha (1: none).
struct QuadricGeometry {
    const QuadricDesc* shape = nullptr;
    float alpha = 1;
};

/// The Embree geometry of `data`, which must outlive it (its user data).
RTCGeometry newQuadricGeometry(RTCDevice device, QuadricGeometry& data);

}  // namespace lamina::render
