// Loop subdivision (loop_subdivision.h) and pbrt-v4's `loopsubdiv` shape that uses it: the
// counts of a refinement, the limit point of an old vertex at every level (the left eigenvector
// of the subdivision matrix: Loop 1987 with Warren's weights), affine invariance, flat meshes
// staying flat, the boundary rules, and the importer's translation and refusals.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "lamina/core/error.h"
#include "lamina/interchange/scene_import.h"
#include "lamina/scene/scene_readers.h"
#include "loop_subdivision.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::errorOf;
using pbrt::loopSubdivide;
using ::testing::HasSubstr;

// The regular octahedron: six points of valence 4, eight faces, wound outwards.
std::vector<glm::dvec3> octahedronPoints() {
    return {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
}
std::vector<std::array<int, 3>> octahedronFaces() {
    return {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
}

// A closed mesh of F triangles: each level quadruples the faces and adds one point per edge
// (3F/2 of them), so V - E + F stays 2.
TEST(LoopSubdivision, EachLevelQuadruplesTheFacesAndAddsAPointPerEdge) {
    std::size_t faces = 8, points = 6;
    for (int levels = 0; levels <= 4; ++levels) {
        const auto m = loopSubdivide(octahedronPoints(), octahedronFaces(), levels);
        EXPECT_EQ(m.triangles.size(), faces) << levels;
        EXPECT_EQ(m.positions.size(), points) << levels;
        EXPECT_EQ(m.normals.size(), points) << levels;
        points += 3 * faces / 2;
        faces *= 4;
    }
}

// The limit position of an old vertex does not depend on the level at which the limit mask is
// applied: the octahedron's (1, 0, 0) goes to 1/2 (1 - 4 g) + g * (sum of its ring, 0), g =
// 1 / (4 + 3 / (8 beta)) = 1/8 with beta = 3/32: (1/2, 0, 0), and its normal is (1, 0, 0) by
// symmetry. Every refined point lies between the inscribed and circumscribed spheres.
TEST(LoopSubdivision, AnOldVertexHasTheSameLimitPointAtEveryLevel) {
    for (int levels = 0; levels <= 5; ++levels) {
        const auto m = loopSubdivide(octahedronPoints(), octahedronFaces(), levels);
        for (std::size_t i = 0; i < 6; ++i) {
            const glm::dvec3 expected = 0.5 * octahedronPoints()[i];
            EXPECT_NEAR(glm::length(m.positions[i] - expected), 0.0, 1e-14)
                << "level " << levels << ", point " << i;
            EXPECT_NEAR(glm::length(m.normals[i] - octahedronPoints()[i]), 0.0, 1e-12);
        }
        for (const glm::dvec3& p : m.positions) {
            EXPECT_GT(glm::length(p), 0.3);
            EXPECT_LE(glm::length(p), 1.0);
        }
    }
}

// Every rule is an affine combination (weights summing to 1): subdividing a mesh moved by an
// affine map gives the subdivided mesh moved by it.
TEST(LoopSubdivision, IsAffinelyInvariant) {
    const glm::dmat3 a(1.5, 0.2, -0.3, 0.1, 0.7, 0.4, -0.2, 0.3, 2.0);
    const glm::dvec3 t(3, -1, 2);
    std::vector<glm::dvec3> moved;
    for (const glm::dvec3& p : octahedronPoints())
        moved.push_back(a * p + t);
    const auto m = loopSubdivide(octahedronPoints(), octahedronFaces(), 3);
    const auto mm = loopSubdivide(moved, octahedronFaces(), 3);
    ASSERT_EQ(m.positions.size(), mm.positions.size());
    for (std::size_t i = 0; i < m.positions.size(); ++i)
        EXPECT_NEAR(glm::length(mm.positions[i] - (a * m.positions[i] + t)), 0.0, 1e-12);
}

// An open flat mesh stays in its plane, its normals are the plane's, and a boundary corner's
// limit is 3/5 of it and 1/5 of each boundary neighbour: the square (0,0)-(1,1) of two
// triangles has corner (1, 0) at 3/5 (1,0) + 1/5 ((0,0) + (1,1)) = (0.8, 0.2).
TEST(LoopSubdivision, AFlatPatchStaysFlatWithTheBoundaryRules) {
    const std::vector<glm::dvec3> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    const std::vector<std::array<int, 3>> faces = {{0, 1, 2}, {0, 2, 3}};
    const auto once = loopSubdivide(square, faces, 0);
    EXPECT_NEAR(glm::length(once.positions[1] - glm::dvec3(0.8, 0.2, 0)), 0.0, 1e-15);
    for (int levels = 1; levels <= 3; ++levels) {
        const auto m = loopSubdivide(square, faces, levels);
        for (std::size_t i = 0; i < m.positions.size(); ++i) {
            EXPECT_EQ(m.positions[i].z, 0.0);
            EXPECT_NEAR(glm::length(m.normals[i] - glm::dvec3(0, 0, 1)), 0.0, 1e-12);
        }
        // Corner 1 stays in the corner's quarter of the square at every level.
        EXPECT_GT(m.positions[1].x, 0.5);
        EXPECT_LT(m.positions[1].y, 0.5);
    }
}

TEST(LoopSubdivision, RefusesWhatItCannotSubdivide) {
    auto faces = octahedronFaces();
    faces.push_back({0, 2, 1});  // a third triangle on the edge (0, 2)
    EXPECT_THAT(errorOf([&] { loopSubdivide(octahedronPoints(), faces, 1); }),
                HasSubstr("the edge between points 0 and 2 belongs to more than two triangles"));
    EXPECT_THAT(errorOf([&] {
                    loopSubdivide(octahedronPoints(), {{0, 0, 1}}, 1);
                }),
                HasSubstr("a triangle repeats point 0"));
    EXPECT_THAT(errorOf([&] { loopSubdivide(octahedronPoints(), octahedronFaces(), 12); }),
                HasSubstr("12 levels make more than 1048576 triangles of this mesh"));
}

class LoopSubdivImport : public lamina::testing::ScratchDirectoryTest {};

// pbrt-v4's `loopsubdiv` becomes the refined mesh (its limit points, its normals), with one
// warning; hostile parameters are refused at their line.
TEST_F(LoopSubdivImport, BecomesTheRefinedMesh) {
    const std::string prelude =
        "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
        "LightSource \"point\" \"rgb I\" [1 1 1] \"point3 from\" [0 0 -5]\n";
    const std::string octahedron =
        "Shape \"loopsubdiv\" \"integer levels\" 2\n"
        "  \"point3 P\" [1 0 0  -1 0 0  0 1 0  0 -1 0  0 0 1  0 0 -1]\n"
        "  \"integer indices\" [0 2 4  2 1 4  1 3 4  3 0 4  2 0 5  1 2 5  3 1 5  0 3 5]\n";
    const auto file = write("s.pbrt", prelude + octahedron);
    const ImportedScene s = importScene(file, dir_);
    const Json& shape = s.scene["shapes"][0];
    EXPECT_EQ(shape["type"], "mesh");
    EXPECT_EQ(shape["faces"].size(), 8u * 16u);
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(shape["positions"][0][k].get<double>(), k == 0 ? 0.5 : 0.0, 1e-14);
    EXPECT_EQ(shape["normals"].size(), shape["positions"].size());
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_THAT(s.warnings[0], HasSubstr(file.string() + ":5: loopsubdiv: 2 levels of Loop "
                                                         "subdivision became a mesh of 128 "
                                                         "triangles"));
    EXPECT_NO_THROW(loadScene(file));
    const auto bad = write("bad.pbrt", prelude +
                                           "Shape \"loopsubdiv\" \"integer levels\" 40\n"
                                           "  \"point3 P\" [0 0 0  1 0 0  0 1 0]\n");
    EXPECT_EQ(errorOf([&] { importScene(bad, dir_); }),
              bad.string() +
                  ":5: Shape \"loopsubdiv\": parameter \"integer levels\" must be in "
                  "[0, 12]");
    const auto nonManifold =
        write("nm.pbrt", prelude +
                             "Shape \"loopsubdiv\" \"point3 P\" [0 0 0  1 0 0  0 1 0  0 0 1]"
                             " \"integer indices\" [0 1 2  0 1 3  1 0 2]\n");
    EXPECT_THAT(errorOf([&] { importScene(nonManifold, dir_); }),
                HasSubstr(nonManifold.string() + ":5: Shape \"loopsubdiv\": the edge between "
                                                 "points 0 and 1 belongs to more than two"));
}

}  // namespace
}  // namespace lamina::render
