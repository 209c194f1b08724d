// Loop subdivision of a triangle mesh, as pbrt-v4's `loopsubdiv` shape refines its control mesh
// before rendering it (pbrt-v4's file-format documentation: "integer levels" 3, "integer
// indices", "point3 P"). The rules are Loop's (C. Loop 1987, "Smooth Subdivision Surfaces Based
// on Triangles", M.S. thesis, University of Utah) with Warren's simplified vertex weight
// beta(n) = 3 / (8 n), 3 / 16 for n = 3 (J. Warren 1995, "Subdivision methods for geometric
// design"), the weights the pbrt book gives (Pharr, Jakob and Humphreys, "Physically Based
// Rendering", 3rd ed., section 3.8):
//   an old vertex of valence n inside:   (1 - n beta) v + beta (sum of its ring)
//   an old vertex on the boundary:       3/4 v + 1/8 (its two boundary neighbours)
//   a new vertex on an inner edge (a b): 3/8 (a + b) + 1/8 (c + d), c, d the opposite corners
//   a new vertex on a boundary edge:     1/2 (a + b)
// Each triangle becomes four, with its winding. After the last level every vertex moves to its
// limit position, the subdivision matrix's left eigenvector of eigenvalue 1:
//   inside: (1 - n g) v + g (sum of its ring), g = 1 / (n + 3 / (8 beta))
//   boundary: 3/5 v + 1/5 (its two boundary neighbours)
// so an old vertex's limit point is the same whatever the number of levels. The normals are
// the area-weighted average of the refined faces' normals around each vertex (pbrt-v4 evaluates
// the limit surface's tangents; the two agree as the mesh is refined). A vertex with other than
// 0 or 2 boundary edges (where two fans touch) keeps its position, as a corner.
#pragma once

#include <array>
#include <vector>

#include <glm/vec3.hpp>

namespace lamina::render::pbrt {

struct SubdividedMesh {
    std::vector<glm::dvec3> positions, normals;
    std::vector<std::array<int, 3>> triangles;
};

/// The most triangles a subdivision may make (4^levels times the control mesh's): the result
/// becomes an inline mesh of the scene document, about 150 bytes a triangle there.
inline constexpr std::size_t kMaxSubdividedTriangles = std::size_t(1) << 20;

/// `levels` rounds of Loop subdivision of the triangles (indices into `positions`), then the
/// limit positions and normals. Throws InputError (a message without a location) for an edge of
/// more than two triangles, a triangle with a repeated corner, or a result above
/// kMaxSubdividedTriangles.
SubdividedMesh loopSubdivide(std::vector<glm::dvec3> positions,
                             std::vector<std::array<int, 3>> triangles, int levels);

}  // namespace lamina::render::pbrt
