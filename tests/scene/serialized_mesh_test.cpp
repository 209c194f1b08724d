// Mitsuba's serialized meshes (mesh_files.h, serialized_reader.cpp): files written here in the
// layout of mitsuba3 src/shapes/serialized.cpp (versions 3 and 4, one or several meshes, single
// and double precision) read back to exactly the numbers written; a scene's `serialized` shape
// takes the mesh its shape_index names; bad files are refused naming the file and the part.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <zlib.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "lamina/interchange/scene_import.h"
#include "lamina/scene/mesh_files.h"
#include "lamina/scene/scene_readers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using lamina::testing::errorOf;
using ::testing::HasSubstr;

// One mesh as Mitsuba writes it: the header, then the zlib stream of its data.
struct SerializedMesh {
    std::uint16_t version = 4;
    bool doubles = false;
    std::vector<float> positions, normals, uvs, colors;
    std::vector<std::uint32_t> triangles;
};

template <typename T>
void put(std::string& out, T value) {
    for (std::size_t i = 0; i < sizeof(T); ++i)
        out += char((std::uint64_t(value) >> (8 * i)) & 0xff);
}
void putNumbers(std::string& out, const std::vector<float>& values, bool doubles) {
    for (float v : values) {
        if (doubles) {
            std::uint64_t bits;
            const double d = v;
            std::memcpy(&bits, &d, 8);
            put(out, bits);
        } else {
            std::uint32_t bits;
            std::memcpy(&bits, &v, 4);
            put(out, bits);
        }
    }
}

std::string encode(const SerializedMesh& m, std::size_t cutStream = 0) {
    std::string data;
    const std::uint32_t flags = (m.normals.empty() ? 0 : 0x1) | (m.uvs.empty() ? 0 : 0x2) |
                                (m.colors.empty() ? 0 : 0x8) | (m.doubles ? 0x2000 : 0x1000);
    put(data, flags);
    if (m.version == 4) data += std::string("mesh name") + '\0';
    put(data, std::uint64_t(m.positions.size() / 3));
    put(data, std::uint64_t(m.triangles.size() / 3));
    putNumbers(data, m.positions, m.doubles);
    putNumbers(data, m.normals, m.doubles);
    putNumbers(data, m.uvs, m.doubles);
    putNumbers(data, m.colors, m.doubles);
    for (std::uint32_t i : m.triangles)
        put(data, i);
    if (cutStream) data.resize(data.size() - cutStream);
    uLongf size = compressBound(uLong(data.size()));
    std::string compressed(size, '\0');
    compress2(reinterpret_cast<Bytef*>(compressed.data()), &size,
              reinterpret_cast<const Bytef*>(data.data()), uLong(data.size()), 9);
    compressed.resize(size);
    std::string out;
    put(out, std::uint16_t(0x041C));
    put(out, m.version);
    return out + compressed;
}

// Several meshes and the table of their offsets (uint64 in version 4, uint32 in version 3).
std::string encodeAll(const std::vector<SerializedMesh>& meshes) {
    std::string out;
    std::vector<std::uint64_t> offsets;
    for (const SerializedMesh& m : meshes) {
        offsets.push_back(out.size());
        out += encode(m);
    }
    for (std::uint64_t o : offsets)
        meshes[0].version == 4 ? put(out, o) : put(out, std::uint32_t(o));
    put(out, std::uint32_t(meshes.size()));
    return out;
}

SerializedMesh quad() {
    SerializedMesh m;
    m.positions = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    m.normals = {0, 0, 1, 0, 0, 1, 0, 0.6f, 0.8f, 0, 0, 1};
    m.uvs = {0, 0, 1, 0, 1, 1, 0, 1};
    m.triangles = {0, 1, 2, 0, 2, 3};
    return m;
}

SerializedMesh triangle(float z) {
    SerializedMesh m;
    m.positions = {0, 0, z, 1, 0, z, 0, 1, z};
    m.triangles = {0, 1, 2};
    return m;
}

class SerializedMeshFile : public lamina::testing::ScratchDirectoryTest {
  protected:
    MeshDesc read(const std::string& bytes, std::uint32_t index = 0) {
        MeshDesc mesh;
        readSerialized(write("m.serialized", bytes), index, mesh);
        return mesh;
    }
    std::string readError(const std::string& bytes, std::uint32_t index = 0) {
        return errorOf([&] { read(bytes, index); });
    }
    std::string file() const { return (dir_ / "m.serialized").string(); }
};

TEST_F(SerializedMeshFile, ReadsWhatWasWritten) {
    const MeshDesc m = read(encode(quad()));
    ASSERT_EQ(m.positions.size(), 4u);
    EXPECT_EQ(m.positions[2], Vec3<float>(1, 1, 0));
    ASSERT_EQ(m.normals.size(), 4u);
    EXPECT_EQ(m.normals[2], Vec3<float>(0, 0.6f, 0.8f));
    ASSERT_EQ(m.uvs.size(), 4u);
    EXPECT_EQ(m.uvs[3], Vec2<float>(0, 1));
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.triangles[1], (std::array<std::uint32_t, 3>{0, 2, 3}));
}

TEST_F(SerializedMeshFile, DoublePrecisionAndColoursVersion3) {
    SerializedMesh m = quad();
    m.version = 3;
    m.doubles = true;
    m.colors = std::vector<float>(12, 0.5f);
    const MeshDesc d = read(encode(m));
    EXPECT_EQ(d.positions, read(encode(quad())).positions);
    EXPECT_EQ(d.uvs, read(encode(quad())).uvs);
}

// mitsuba3 serialized.cpp: shape_index finds its mesh through the table at the file's end.
TEST_F(SerializedMeshFile, ShapeIndexFindsItsMeshInEitherVersion) {
    for (const std::uint16_t version : {std::uint16_t(3), std::uint16_t(4)}) {
        std::vector<SerializedMesh> meshes = {triangle(0), triangle(1), triangle(2)};
        for (SerializedMesh& m : meshes)
            m.version = version;
        const std::string bytes = encodeAll(meshes);
        for (std::uint32_t i = 0; i < 3; ++i)
            EXPECT_EQ(read(bytes, i).positions[0].z, float(i)) << "version " << version;
        EXPECT_EQ(readError(bytes, 3),
                  file() + ": shape_index 3 is out of range (the file has 3 meshes)");
    }
}

TEST_F(SerializedMeshFile, BadFilesAreNamed) {
    EXPECT_EQ(readError("PK\3\4 not a mesh"),
              file() + ": not a Mitsuba serialized mesh (no 0x041C header)");
    SerializedMesh v5 = quad();
    v5.version = 5;
    EXPECT_EQ(readError(encode(v5)),
              file() + ": serialized format version 5 is not supported (versions 3 and 4)");
    EXPECT_EQ(readError(encode(quad(), 10)),
              file() + " (mesh 0): the data ends inside the triangles");
    std::string corrupt = encode(quad());
    corrupt[12] = char(corrupt[12] ^ 0x55);
    EXPECT_THAT(readError(corrupt), HasSubstr(file() + " (mesh 0): "));
    SerializedMesh outOfRange = quad();
    outOfRange.triangles[4] = 9;
    EXPECT_EQ(readError(encode(outOfRange)),
              file() + " (mesh 0): triangle 1 refers to vertex 9 of 4");
    SerializedMesh nan = quad();
    nan.positions[4] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THAT(readError(encode(nan)), HasSubstr(file() + " (mesh 0): vertex 1: position"));
    // A header that claims more than the reader takes, in a file of a few bytes.
    std::string huge;
    put(huge, std::uint32_t(0x1000));
    huge += std::string("x") + '\0';
    put(huge, std::uint64_t(1) << 40);
    put(huge, std::uint64_t(1));
    uLongf size = compressBound(uLong(huge.size()));
    std::string compressed(size, '\0');
    compress2(reinterpret_cast<Bytef*>(compressed.data()), &size,
              reinterpret_cast<const Bytef*>(huge.data()), uLong(huge.size()), 9);
    compressed.resize(size);
    std::string hugeFile;
    put(hugeFile, std::uint16_t(0x041C));
    put(hugeFile, std::uint16_t(4));
    EXPECT_THAT(readError(hugeFile + compressed),
                HasSubstr("1099511627776 vertices and 1 triangles are more than the reader takes"));
}

// An offset table entry near 2^64 must be refused, not wrap around the bounds check (found by
// the serialized_reader fuzz target; tests/fuzz/regressions/serialized_reader).
TEST_F(SerializedMeshFile, AnOffsetNearTwoToTheSixtyFourIsRefused) {
    std::string bytes = encodeAll({triangle(0), triangle(1)});
    // The table's second entry (mesh 1), just before the count.
    bytes.replace(bytes.size() - 12, 8, std::string(8, char(0xff)));
    EXPECT_EQ(readError(bytes, 1), file() +
                                       ": mesh 1 starts at 18446744073709551615, past the "
                                       "file's meshes");
}

// The scene's `serialized` shape and Mitsuba's `<shape type="serialized">` that becomes it.
TEST_F(SerializedMeshFile, SceneShapeAndMitsubaImport) {
    write("m.serialized", encodeAll({quad(), triangle(5)}));
    const auto scene = write("scene.json", R"j({
  "camera": {"position": [0, 0, 10], "look_at": [0, 0, 0]},
  "lights": [{"type": "point", "position": [0, 0, 10], "intensity": 1}],
  "shapes": [{"type": "serialized", "file": "m.serialized", "shape_index": 1,
              "material": {"type": "lambert"}}]
})j");
    const SceneDesc s = loadScene(scene);
    ASSERT_EQ(s.shapes.size(), 1u);
    const auto& mesh = std::get<MeshDesc>(s.shapes[0]);
    EXPECT_EQ(mesh.triangles.size(), 1u);
    EXPECT_EQ(mesh.positions[0].z, 5.0f);

    const auto xml = write("scene.xml", R"j(<scene version="3.0.0">
<shape type="serialized"><string name="filename" value="m.serialized"/>
  <integer name="shape_index" value="1"/></shape>
<shape type="serialized"><string name="filename" value="m.serialized"/></shape>
<emitter type="constant"/>
</scene>)j");
    const ImportedScene imported = importScene(xml, dir_);
    EXPECT_EQ(imported.scene["shapes"][0],
              Json::parse(R"j({"type": "serialized", "file": "m.serialized", "shape_index": 1,
                              "material": {"type": "lambert", "reflectance": 0.5}})j"));
    EXPECT_FALSE(imported.scene["shapes"][1].contains("shape_index"));
    const SceneDesc translated = loadScene(xml);
    EXPECT_EQ(translated.shapes.size(), 2u);
}

}  // namespace
}  // namespace lamina::render
