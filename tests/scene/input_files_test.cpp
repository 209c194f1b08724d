// Hostile mesh and image files: PLY counts that lie, faces longer than the vertex
// array and indices beyond 2^31; OBJ faces with out-of-range indices; NaN (also spelled out
// in an OBJ), infinite and zero
// values in meshes and images; image paths that are not regular files. Each is an
// InputError naming the file and the first bad element, never a crash, a hang or a silent
// loss of geometry.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>

#include "lamina/core/error.h"
#include "lamina/lights/environment_map.h"
#include "lamina/output/image_output.h"
#include "lamina/scene/mesh_files.h"
#include "lamina/scene/texture.h"

#include "scratch_directory.h"

namespace lamina::render {
namespace {

namespace fs = std::filesystem;
using testing::errorOf;
using ::testing::HasSubstr;

class InputFiles : public testing::ScratchDirectoryTest {
  protected:
    std::string plyError(const std::string& name, const std::string& text) {
        return errorOf([&] {
            MeshDesc mesh;
            readPly(write(name, text), mesh);
        });
    }
    std::string objError(const std::string& name, const std::string& text) {
        return errorOf([&] {
            MeshDesc mesh;
            readObj(write(name, text), mesh);
        });
    }
};

const std::string kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
    "property float y\nproperty float z\n";
const std::string kPlyFace = "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

TEST_F(InputFiles, PlyCountsThatLieAreRefused) {
    // Thousands of elements claimed, three given: refused from the header, before reading.
    EXPECT_THAT(
        plyError("count.ply",
                 "ply\nformat binary_little_endian 1.0\n"
                 "element vertex 1000000\nproperty float x\nproperty "
                 "float y\nproperty float z\nend_header\n" +
                     std::string(36, '\0')),
        HasSubstr("count.ply: element vertex: unexpected end of data: the header says 1000000 "
                  "elements"));
    // "-1" is not 2^64 - 1 elements.
    EXPECT_THAT(plyError("negative.ply", "ply\nformat ascii 1.0\nelement vertex -1\nend_header\n"),
                HasSubstr("malformed element line"));
    // The fuzzer's input that looped forever over an element without properties.
    const fs::path regression = fs::path(LAMINA_SOURCE_DIR) / "tests" / "fuzz" / "regressions" /
                                "ply_reader" / "element-count-lies.ply";
    EXPECT_THAT(errorOf([&] {
                    MeshDesc mesh;
                    readPly(regression, mesh);
                }),
                HasSubstr("element-count-lies.ply: "));
}

TEST_F(InputFiles, PlyFaceIndicesAreCheckedAndPrintedWhole) {
    const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
    EXPECT_THAT(plyError("big.ply", kPlyHeader + kPlyFace + vertices + "3 0 1 99999999999\n"),
                HasSubstr("big.ply: face 0: face index 99999999999 is out of range [0, 3)"));
    EXPECT_THAT(plyError("small.ply", kPlyHeader + kPlyFace + vertices + "3 0 1 3\n"),
                HasSubstr("face 0: face index 3 is out of range [0, 3)"));
    EXPECT_THAT(plyError("long.ply", kPlyHeader + kPlyFace + vertices + "5 0 1 2 0 1\n"),
                HasSubstr("face 0: lists 5 vertices, more than the 3 of element vertex"));
}

TEST_F(InputFiles, PlyNonFiniteValuesAndZeroNormalsAreRefused) {
    EXPECT_THAT(plyError("nan.ply", kPlyHeader + kPlyFace + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"),
                HasSubstr("nan.ply: vertex 1: unexpected end of data or a non-number"));
    std::string binary =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
        "property float x\nproperty float y\nproperty float z\n" +
        kPlyFace;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float xyz[9] = {0, 0, 0, 1, 0, nan, 0, 1, 0};
    binary.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
    const unsigned char n = 3;
    const std::int32_t face[3] = {0, 1, 2};
    binary.append(reinterpret_cast<const char*>(&n), 1);
    binary.append(reinterpret_cast<const char*>(face), sizeof face);
    EXPECT_THAT(plyError("nan-binary.ply", binary),
                HasSubstr("nan-binary.ply: vertex 1: position (1, 0, nan) is not finite"));
    EXPECT_THAT(plyError("inf.ply", kPlyHeader + kPlyFace + "0 0 0\n1 1e39 0\n0 1 0\n3 0 1 2\n"),
                HasSubstr("inf.ply: vertex 1: position (1, inf, 0) is not finite"));
    const std::string withNormals =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
        "property float y\nproperty float z\nproperty float nx\n"
        "property float ny\nproperty float nz\n";
    EXPECT_THAT(plyError("zero-normal.ply", withNormals + kPlyFace +
                                                "0 0 0 0 0 1\n1 0 0 0 0 0\n0 1 0 0 0 1\n3 0 1 2\n"),
                HasSubstr("zero-normal.ply: vertex 1: normal (0, 0, 0) is zero"));
}

TEST_F(InputFiles, ObjIndicesAreCheckedAgainstTheArrays) {
    const std::string v = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    // A large index crashed, a small one read beyond the array: both name the triangle.
    EXPECT_THAT(objError("large.obj", v + "f 1 2 2000000000\n"),
                HasSubstr("large.obj: triangle 0: vertex index 2000000000 is out of range (the "
                          "file has 3)"));
    EXPECT_THAT(objError("small.obj", v + "o box\nf 1 2 4\n"),
                HasSubstr("small.obj: object \"box\", triangle 0: vertex index 4 is out of range"));
    EXPECT_THAT(
        objError("normal.obj", v + "vn 0 0 1\nf 1//1 2//1 3//2\n"),
        HasSubstr("normal.obj: triangle 0: normal index 2 is out of range (the file has 1)"));
    EXPECT_THAT(objError("uv.obj", v + "vt 0 0\nf 1/1 2/1 3/5\n"),
                HasSubstr("uv.obj: triangle 0: texture coordinate index 5 is out of range"));
    // A face tinyobjloader drops (it only warned) is an error, not missing geometry.
    EXPECT_THAT(objError("degenerate.obj", v + "f 1 2 3\nf 1 2\n"),
                HasSubstr("degenerate.obj: Degenerated face found"));
}

TEST_F(InputFiles, ObjNonFiniteValuesAndZeroNormalsAreRefused) {
    EXPECT_THAT(objError("inf.obj", "v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n"),
                HasSubstr("inf.obj: vertex position (v) 2 is not finite"));
    EXPECT_THAT(objError("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n"),
                HasSubstr("zero.obj: normal (vn) 1 is zero"));
    // Spelled NaN and infinity, which tinyobjloader would read as 0 (a vertex at the origin),
    // and a token that is no number at all, each named with its line.
    EXPECT_THAT(objError("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n"),
                HasSubstr("nan.obj: line 2: vertex position (v): \"nan\" is not a finite number"));
    EXPECT_THAT(objError("inf.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 -inf 0\r\nf 1 2 3\r\n"),
                HasSubstr("inf.obj: line 3: vertex position (v): \"-inf\" is not a finite number"));
    EXPECT_THAT(
        objError("vn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 Infinity\nf 1//1 2//1 3//1\n"),
        HasSubstr("vn.obj: line 4: normal (vn): \"Infinity\" is not a finite number"));
    EXPECT_THAT(objError("vt.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 x\nf 1/1 2/1 3/1\n"),
                HasSubstr("vt.obj: line 4: texture coordinate (vt): \"x\" is not a number"));
}

TEST_F(InputFiles, ImagesWithNonFiniteSamplesAreRefused) {
    const fs::path file = dir_ / "nan.exr";
    std::vector<float> pixels(4 * 2 * 3, 0.5f);
    pixels[(1 * 4 + 2) * 3 + 1] = std::numeric_limits<float>::quiet_NaN();
    writeFloatExr(file, 4, 2, {"R", "G", "B"}, pixels);
    // Spectral mode crashed in the RGB -> spectrum lookup on such a texel.
    EXPECT_THAT(errorOf([&] { ImageTexture(file, Vec2<float>(1.0f), false, false); }),
                HasSubstr("nan.exr: the texture has a sample that is not finite (NaN) at pixel "
                          "(2, 1), channel 1"));
    EXPECT_THAT(errorOf([&] { EnvironmentMap(file, EnvironmentLayout{}); }),
                HasSubstr("nan.exr: the environment map has a sample that is not finite"));
}

// A small file whose header claims 10^10 pixels must be refused before the allocation.
TEST_F(InputFiles, ImagesClaimingTooManyPixelsAreRefusedBeforeAllocating) {
    std::string header = "P6\n100000 100000\n255\n";
    header.append(30, 'x');  // (not literal + string: GCC 12 warns falsely on it, -Warray-bounds)
    const fs::path file = write("huge.ppm", header);
    EXPECT_THAT(errorOf([&] { ImageTexture(file, Vec2<float>(1.0f), true, false); }),
                HasSubstr("huge.ppm: cannot read the texture: 100000 x 100000 pixels, more than"));
    EXPECT_THAT(errorOf([&] { readRgbImage(file); }),
                HasSubstr("huge.ppm: 100000 x 100000 pixels, more than the limit"));
}

TEST_F(InputFiles, ImagePathsMustBeRegularFiles) {
    EXPECT_THAT(errorOf([&] { ImageTexture(dir_, Vec2<float>(1.0f), false, false); }),
                HasSubstr(": is a directory, not a regular file"));
    EXPECT_THAT(errorOf([&] { EnvironmentMap("/dev/zero", EnvironmentLayout{}); }),
                HasSubstr("/dev/zero: is a device, not a regular file"));
    const fs::path fifo = dir_ / "fifo.png";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_THAT(errorOf([&] { ImageTexture(fifo, Vec2<float>(1.0f), true, false); }),
                HasSubstr("fifo.png: is a FIFO, not a regular file"));
}

}  // namespace
}  // namespace lamina::render
