// Mesh files: an OBJ, an ASCII PLY and a binary PLY of the same geometry load to the same
// triangles as the inline mesh and render the same image bit for bit; bad files are named.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <bit>
#include <filesystem>
#include <fstream>

#include "lamina/scene/mesh_files.h"
#include "render_helpers.h"

namespace lamina {
namespace {

namespace fs = std::filesystem;

class MeshFiles : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("lamina-mesh-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path write(const std::string& name, const std::string& bytes) {
        std::ofstream(dir_ / name, std::ios::binary) << bytes;
        return dir_ / name;
    }
    fs::path dir_;
};

// A unit quad in z = 0 facing +z, as two triangles of a 4-vertex polygon.
const char* kPositions = "[[-1,-1,0],[1,-1,0],[1,1,0],[-1,1,0]]";

std::string binaryPly() {
    std::string header =
        "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
        "property float y\nproperty float z\nelement face 1\n"
        "property list uchar int vertex_indices\nend_header\n";
    const float v[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    std::string data(reinterpret_cast<const char*>(v), sizeof v);
    data += char(4);
    for (std::int32_t i : {0, 1, 2, 3})
        data.append(reinterpret_cast<const char*>(&i), 4);
    static_assert(std::endian::native == std::endian::little);
    return header + data;
}

std::string sceneWith(const std::string& shape) {
    return R"({
      "camera": {"position": [0.3, 0.2, 3], "look_at": [0, 0, 0], "fov": 60},
      "film": {"resolution": [16, 16]},
      "materials": {"m": {"type": "lambert", "reflectance": 0.7}},
      "shapes": [)" +
           shape + R"(],
      "lights": [{"type": "environment", "radiance": 1}]
    })";
}

TEST_F(MeshFiles, ObjAndPlyMatchTheInlineMesh) {
    const auto obj = write("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
    const auto ascii = write("quad.ply",
                             "ply\nformat ascii 1.0\ncomment a quad\nelement vertex 4\n"
                             "property float x\nproperty float y\nproperty float z\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                             "-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n4 0 1 2 3\n");
    const auto binary = write("quad_binary.ply", binaryPly());
    render::RenderOptions o;
    o.spp = 4;
    auto render = [&](const std::string& shape) {
        return render::renderScene(testing::sceneFromText(sceneWith(shape)), o);
    };
    const auto reference =
        render(std::string(R"({"type": "mesh", "material": "m", "positions": )") + kPositions +
               R"(, "faces": [[0, 1, 2, 3]]})");
    for (const auto& file : {obj, ascii, binary}) {
        const std::string type = file.extension() == ".obj" ? "obj" : "ply";
        const auto r = render(R"({"type": ")" + type + R"(", "material": "m", "file": ")" +
                              file.string() + R"("})");
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x)
                ASSERT_EQ(r.film->pixel(x, y)[1], reference.film->pixel(x, y)[1]) << file;
    }
}

// Face corners with a trailing slash and nothing after it ("1/1/", "2//"), as one of Mitsuba
// 3's own test meshes writes them, mean no normal (and no uv): the same triangles and uvs as
// the corners written without the slash.
TEST_F(MeshFiles, ObjCornersWithATrailingSlashHaveNoNormal) {
    const std::string vertices =
        "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
    const auto slashes = write("slashes.obj", vertices + "f 1/1/ 2/2/ 3/3/\nf 1/1/ 3/3/ 4/4/\n");
    const auto plain = write("plain.obj", vertices + "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n");
    const auto positionsOnly = write("positions.obj", vertices + "f 1// 2// 3//\r\nf 1 3 4//");
    render::MeshDesc withSlashes, withoutSlashes, noUvs;
    render::readObj(slashes, withSlashes);
    render::readObj(plain, withoutSlashes);
    render::readObj(positionsOnly, noUvs);
    EXPECT_EQ(withSlashes.triangles, withoutSlashes.triangles);
    EXPECT_EQ(withSlashes.uvs, withoutSlashes.uvs);
    EXPECT_EQ(withSlashes.positions, withoutSlashes.positions);
    EXPECT_TRUE(withSlashes.normals.empty());
    EXPECT_EQ(withSlashes.uvs.size(), 4u);
    EXPECT_EQ(noUvs.triangles.size(), 2u);
    EXPECT_TRUE(noUvs.uvs.empty());
}

TEST_F(MeshFiles, BadPlyFilesAreNamed) {
    const auto truncated =
        write("truncated.ply",
              "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
              "property float y\nproperty float z\nelement face 1\n"
              "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n");
    const auto outOfRange = write("range.ply",
                                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                  "property float y\nproperty float z\nelement face 1\n"
                                  "property list uchar int vertex_indices\nend_header\n"
                                  "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
    const auto notPly = write("text.ply", "hello\n");
    for (const auto& [file, what] : {std::pair{truncated, "unexpected end of data"},
                                     std::pair{outOfRange, "face index 7 is out of range"},
                                     std::pair{notPly, "not a PLY file"}}) {
        render::MeshDesc mesh;
        try {
            render::readPly(file, mesh);
            FAIL() << "accepted " << file;
        } catch (const InputError& e) {
            EXPECT_THAT(e.what(), ::testing::HasSubstr(file.filename().string()));
            EXPECT_THAT(e.what(), ::testing::HasSubstr(what));
        }
    }
}

}  // namespace
}  // namespace lamina
