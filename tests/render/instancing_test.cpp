// Object instancing and alpha cut-outs in the geometry (geometry.h, alpha_filter.h): an
// instance's hit is the hit on the same shape written out in world space (position, normals,
// uv, material), within float rounding (Embree intersects the instance in object space, the
// copy in world space: the two differ by a few ULPs, not bit for bit); objects are stored once;
// the scene reader refuses what an object cannot hold; a cut-out lets the expected fraction of
// rays through, closest-hit and shadow rays alike.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "lamina/core/pcg32.h"
#include "lamina/core/warp.h"
#include "lamina/geometry/geometry.h"
#include "lamina/geometry/ray_offset.h"
#include "render_helpers.h"

namespace lamina {
namespace {

using render::Vec3f;
using ::testing::HasSubstr;

// One object (a mesh with normals and uvs, a sphere and a disk) placed three times: a
// translation, a rotation, a mirroring scale; OBJECTS_OR_COPIES is replaced by the object's
// shapes with each transform written out, or by the instances.
constexpr const char* kShapes = R"(
  {"type": "mesh", "material": "a", "positions": [[0, 0, 0], [1, 0, 0], [1, 1, 0.2], [0, 1, 0]],
   "normals": [[0, 0, 1], [0.2, 0, 1], [0, 0.3, 1], [-0.1, 0, 1]],
   "uvs": [[0, 0], [1, 0], [1, 1], [0, 1]], "faces": [[0, 1, 2, 3]]XFORM},
  {"type": "sphere", "material": "b", "center": [0.5, 0.5, 1], "radius": 0.4XFORM},
  {"type": "disk", "material": "a", "center": [0.5, -0.5, 0.5], "normal": [0, 1, 1],
   "radius": 0.3XFORM})";

const char* kTransforms[] = {
    R"([{"translate": [2, 0, 0]}])",
    R"([{"rotate": {"axis": [0.3, 1, 0.2], "angle": 40}}, {"translate": [-2, 0.5, 0]}])",
    R"([{"scale": [-1.5, 1.5, 1.5]}, {"translate": [0, -2, 0.5]}])"};

std::string replaceAll(std::string s, const std::string& what, const std::string& with) {
    for (std::size_t at = s.find(what); at != std::string::npos;
         at = s.find(what, at + with.size()))
        s.replace(at, what.size(), with);
    return s;
}

std::string sceneText(bool instanced) {
    std::string shapes;
    if (instanced) {
        for (const char* t : kTransforms)
            shapes += std::string(shapes.empty() ? "" : ",") +
                      R"({"type": "instance", "object": "thing", "transform": )" + t + "}";
    } else {
        for (const char* t : kTransforms)
            shapes += std::string(shapes.empty() ? "" : ",") +
                      replaceAll(kShapes, "XFORM", std::string(", \"transform\": ") + t);
    }
    return std::string(R"({
      "camera": {"position": [0, 0, -8], "look_at": [0, 0, 0]},
      "film": {"resolution": [24, 24]},
      "materials": {"a": {"type": "lambert", "reflectance": 0.5},
                    "b": {"type": "lambert", "reflectance": [0.2, 0.6, 0.3]}},
      )") +
           (instanced ? R"("objects": {"thing": [)" + replaceAll(kShapes, "XFORM", "") + "]},"
                      : "") +
           R"("shapes": [)" + shapes + R"(,
        {"type": "rectangle", "material": "a", "emission": {"radiance": 3},
         "transform": [{"scale": 0.5}, {"translate": [0, 0, -4]}]}
      ]})";
}

TEST(Instancing, HitsEqualTheCopiesWrittenOutAsShapes) {
    const auto instanced = testing::sceneFromText(sceneText(true));
    const auto copies = testing::sceneFromText(sceneText(false));
    ASSERT_EQ(instanced.instances.size(), 3u);
    ASSERT_EQ(render::countShapes<render::MeshDesc>(copies.shapes), 4u);
    const render::Geometry gi(instanced), gc(copies);
    Pcg32 rng(5);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3f o = Vec3f(0, 0, -8) + 0.5f * Vec3f(rng.nextFloat(), rng.nextFloat(), 0.0f);
        const Vec3f target(6 * rng.nextFloat() - 3, 6 * rng.nextFloat() - 3, 3 * rng.nextFloat());
        const Vec3f d = glm::normalize(target - o);
        const auto a = gi.intersect(o, d), b = gc.intersect(o, d);
        ASSERT_EQ(a.has_value(), b.has_value()) << i;
        if (!a) continue;
        // Rays that graze an edge may hit different primitives under rounding: skip those
        // whose hits lie apart by more than rounding (none expected in practice).
        ASSERT_NEAR(a->t, b->t, 1e-4f * b->t) << i;
        ++hits;
        EXPECT_EQ(gi.shapes()[std::size_t(a->shape)].material,
                  gc.shapes()[std::size_t(b->shape)].material);
        EXPECT_EQ(gi.shapes()[std::size_t(a->shape)].desc->index(),
                  gc.shapes()[std::size_t(b->shape)].desc->index());
        EXPECT_LT(glm::length(a->p - b->p), 1e-5f) << i;
        EXPECT_GT(glm::dot(a->ng, b->ng), 0.99999f) << i;
        EXPECT_GT(glm::dot(a->ns, b->ns), 0.99999f) << i;
        // A sphere's or disk's uv is in its own frame: an instance's turns with the instance, a
        // transformed shape's stays in world axes (the reader keeps only centre and normal).
        if (std::holds_alternative<render::MeshDesc>(*gc.shapes()[std::size_t(b->shape)].desc)) {
            EXPECT_NEAR(a->uv.x, b->uv.x, 1e-4f) << i;
            EXPECT_NEAR(a->uv.y, b->uv.y, 1e-4f) << i;
        }
        // The lamp is the copies' fourth mesh (three copied ones before it), a shape in both;
        // the meshes come first among the shapes, so its index there is 3 too.
        const bool lamp =
            std::holds_alternative<render::MeshDesc>(*gc.shapes()[std::size_t(b->shape)].desc) &&
            b->shape == 3;
        EXPECT_EQ(a->instance >= 0, !lamp) << i;
    }
    EXPECT_GT(hits, 3000);
}

TEST(Instancing, StoresOneCopyOfAnObjectPlacedOneThousandTimes) {
    // A 100k-triangle grid placed 1000 times: Embree holds it once.
    render::SceneDesc scene;
    render::ObjectDesc grid;
    grid.name = "grid";
    render::MeshDesc m;
    const int n = 224;  // 2 * 223 * 223 = 99458 triangles, with the rows below ~100k
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x)
            m.positions.push_back(Vec3f(float(x) / n, float(y) / n, 0.0f));
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const auto i = std::uint32_t(y * (n + 1) + x);
            m.triangles.push_back({i, i + 1, i + std::uint32_t(n) + 2});
            m.triangles.push_back({i, i + std::uint32_t(n) + 2, i + std::uint32_t(n) + 1});
        }
    m.material = 0;
    const std::size_t triangles = m.triangles.size();
    ASSERT_GE(triangles, 100000u);
    grid.shapes.push_back(std::move(m));
    scene.objects.push_back(std::move(grid));
    for (int i = 0; i < 1000; ++i) {
        render::InstanceDesc inst;
        inst.object = 0;
        inst.toWorld = glm::translate(glm::dmat4(1.0), Vec3<double>(i % 32, i / 32, 0.1 * i));
        scene.instances.push_back(inst);
    }
    const render::Geometry g(scene);
    EXPECT_EQ(g.counts().trianglesStored, triangles);
    EXPECT_EQ(g.counts().trianglesReferenced, 1000 * triangles);
    EXPECT_EQ(g.counts().instances, 1000u);
    EXPECT_EQ(g.counts().objectsBuilt, 1u);
    EXPECT_EQ(g.shapes().size(), 1u);  // the object's one mesh, not a thousand
    // The last instance is there: a ray down onto it hits it at its height.
    const auto hit = g.intersect(Vec3f(7.5f, 31.2f, 1000), Vec3f(0, 0, -1));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->instance, 999);
    EXPECT_NEAR(hit->p.z, 99.9f, 1e-4f);
    EXPECT_FLOAT_EQ(g.boundsHi().z, 99.9f);
}

TEST(Instancing, RaysLeavingInstancedHitsDoNotHitTheirSurfaceAgain) {
    // A closed sphere and a mesh in an object far from the origin and rotated: the offset of
    // the transformed hit point carries the new ray off the surface.
    const auto scene = testing::sceneFromText(R"({
      "materials": {"m": {"type": "lambert"}},
      "objects": {"o": [{"type": "sphere", "material": "m", "radius": 0.7},
                        {"type": "mesh", "material": "m", "positions": [[1, -1, 0], [3, -1, 0], [1, 2, 0.5]],
                         "faces": [[0, 1, 2]]}]},
      "shapes": [{"type": "instance", "object": "o", "transform": [
                   {"rotate": {"axis": [1, 2, 3], "angle": 33}}, {"scale": 3},
                   {"translate": [1000, -2000, 500]}]},
                 {"type": "sphere", "material": "m", "radius": 0.1, "emission": {"radiance": 1}}]})");
    const render::Geometry g(scene);
    Pcg32 rng(3);
    int tested = 0, failures = 0;
    const Vec3f centre(1000, -2000, 500);
    for (int i = 0; i < 20000; ++i) {
        const Vec3f dir(squareToUniformSphere(Vec2f(rng.nextFloat(), rng.nextFloat())));
        const auto hit = g.intersect(centre + 30.0f * dir, -dir);
        if (!hit || hit->instance != 0) continue;
        ++tested;
        Vec3f w = squareToCosineHemisphere(Vec2f(rng.nextFloat(), rng.nextFloat()));
        w = Frame<float>::fromNormal(hit->ng).toWorld(w);
        const Vec3f out = render::offsetRayOrigin(hit->p, hit->ng, g.rayOffsetScale());
        if (const auto again = g.intersect(out, w);
            again && again->shape == hit->shape && again->t < 1e-3f)
            ++failures;
    }
    EXPECT_GT(tested, 10000);
    EXPECT_EQ(failures, 0);
}

std::string errorOf(const std::string& json) {
    try {
        testing::sceneFromText(json);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

constexpr const char* kLight =
    R"({"type": "sphere", "material": "m", "center": [5, 5, 5], "radius": 0.1,
        "emission": {"radiance": 1}})";

std::string withObjects(const std::string& objects, const std::string& shapes) {
    return R"({"materials": {"m": {"type": "lambert"}}, "textures": {"c": {"type": "checkerboard", "scale": [4, 4], "a": 1, "b": 0}},
               "objects": )" +
           objects + R"(, "shapes": [)" + shapes + "," + kLight + "]}";
}

constexpr const char* kBox = R"({"type": "rectangle", "material": "m"})";

TEST(InstancingErrors, NameTheJsonPath) {
    EXPECT_THAT(errorOf(withObjects(std::string(R"({"a": [)") + kBox + "]}",
                                    R"({"type": "instance", "object": "b"})")),
                HasSubstr(R"(shapes[0].object: unknown object "b"; defined: a)"));
    EXPECT_THAT(errorOf(withObjects(
                    R"({"a": [{"type": "sphere", "material": "m", "emission": {"radiance": 1}}]})",
                    R"({"type": "instance", "object": "a"})")),
                HasSubstr("objects.a[0].emission: an emitting shape inside an object is refused"));
    EXPECT_THAT(errorOf(withObjects(std::string(R"({"a": [)") + kBox +
                                        R"(], "b": [{"type": "instance", "object": "a"}]})",
                                    R"({"type": "instance", "object": "b"})")),
                HasSubstr("objects.b[0].type: an instance inside an object is refused"));
    // Recursion is nesting too: refused the same way, before it could recurse.
    EXPECT_THAT(errorOf(withObjects(R"({"a": [{"type": "instance", "object": "a"}]})",
                                    R"({"type": "instance", "object": "a"})")),
                HasSubstr("objects.a[0].type: an instance inside an object is refused"));
    EXPECT_THAT(errorOf(withObjects(R"({"a": []})", R"({"type": "instance", "object": "a"})")),
                HasSubstr("objects.a: expected a non-empty array of shapes"));
    EXPECT_THAT(errorOf(withObjects(std::string(R"({"a": [)") + kBox + "]}",
                                    R"({"type": "instance", "object": "a", "material": "m"})")),
                HasSubstr("shapes[0]"));
    EXPECT_THAT(errorOf(withObjects(std::string(R"({"a": [)") + kBox + "]}",
                                    R"({"type": "instance", "object": "a",
                                        "transform": [{"translate": [1e16, 0, 0]}]})")),
                HasSubstr("shapes[0].transform: the instance's bounding box corner"));
}

TEST(AlphaErrors, NameTheJsonPath) {
    const auto shape = [](const std::string& s) { return errorOf(withObjects("{}", s)); };
    EXPECT_THAT(shape(R"({"type": "rectangle", "material": "m", "alpha": 0.5,
                          "emission": {"radiance": 1}})"),
                HasSubstr("shapes[0].alpha: an emitting shape cannot be cut out"));
    EXPECT_THAT(shape(R"({"type": "rectangle", "material": "m", "alpha": 1.5})"),
                HasSubstr("shapes[0].alpha"));
    EXPECT_THAT(shape(R"({"type": "rectangle", "material": "m", "alpha": "x"})"),
                HasSubstr("shapes[0].alpha: expected a number in [0, 1]"));
    EXPECT_THAT(shape(R"({"type": "rectangle", "material": "m", "alpha": {"texture": "d"}})"),
                HasSubstr(R"(shapes[0].alpha.texture: unknown texture "d")"));
    EXPECT_THAT(shape(R"({"type": "sphere", "material": "m", "alpha": {"texture": "c"}})"),
                HasSubstr("shapes[0].alpha: a texture alpha is read at a triangle shape's uv"));
}

TEST(Instancing, UnusedObjectsAreNeitherReadNorBuilt) {
    // "b" is broken, but no instance places it: it is listed, not read.
    const auto scene = testing::sceneFromText(
        withObjects(std::string(R"({"a": [)") + kBox + R"(], "b": [{"type": "nonsense"}]})",
                    R"({"type": "instance", "object": "a"}, {"type": "instance", "object": "a"})"));
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.instances.size(), 2u);
    EXPECT_EQ(scene.unusedObjectNames, std::vector<std::string>{"b"});
}

// A plane z = 0 of [-1, 1]^2 with `alpha`, seen from above along -z.
render::SceneDesc cutOutPlanes(const std::string& alpha, int planes = 1) {
    std::string shapes;
    for (int i = 0; i < planes; ++i)
        shapes += R"({"type": "rectangle", "material": "m", "alpha": )" + alpha +
                  R"(, "transform": [{"translate": [0, 0, )" + std::to_string(-i) + "]}]},";
    return testing::sceneFromText(
        R"({"materials": {"m": {"type": "lambert"}},
            "textures": {"c": {"type": "checkerboard", "scale": [4, 4], "a": 1, "b": 0}},
            "shapes": [)" +
        shapes + kLight + "]}");
}

struct Passed {
    int closest = 0, shadow = 0, n = 0;
};

Passed raysThrough(const render::Geometry& g, int n, std::uint64_t seed = 9) {
    Pcg32 rng(seed);
    Passed p;
    p.n = n;
    for (int i = 0; i < n; ++i) {
        const Vec3f o(1.4f * rng.nextFloat() - 0.7f, 1.4f * rng.nextFloat() - 0.7f, 2.0f);
        const Vec3f d = glm::normalize(Vec3f(0.1f * rng.nextFloat(), 0.1f * rng.nextFloat(), -1));
        const auto hit = g.intersect(o, d, 10.0f);
        p.closest += !hit;
        p.shadow += !g.occluded(o, d, 10.0f);
    }
    return p;
}

TEST(Alpha, ZeroIsInvisibleAndOneIsOpaque) {
    const auto invisible = cutOutPlanes("0");
    const render::Geometry g0(invisible);
    const Passed zero = raysThrough(g0, 2000);
    EXPECT_EQ(zero.closest, 2000);
    EXPECT_EQ(zero.shadow, 2000);
    const auto opaque = cutOutPlanes("1");
    const render::Geometry g1(opaque);
    const Passed one = raysThrough(g1, 2000);
    EXPECT_EQ(one.closest, 0);
    EXPECT_EQ(one.shadow, 0);
}

// A fraction alpha of the rays stop at a cut-out plane, and two planes in a row are
// independent (alpha^2 stop at neither... (1 - alpha)^2 pass both). The counts are binomial:
// tolerance 4.5 standard deviations (two-sided p ~ 7e-6), with a fixed seed.
TEST(Alpha, AFractionAlphaOfTheRaysStopClosestHitAndShadowAlike) {
    const int n = 40000;
    const auto bound = [&](double p) { return 4.5 * std::sqrt(n * p * (1 - p)); };
    const auto one = cutOutPlanes("0.3");
    const render::Geometry g1(one);
    const Passed a = raysThrough(g1, n);
    EXPECT_NEAR(a.closest, 0.7 * n, bound(0.7));
    EXPECT_NEAR(a.shadow, 0.7 * n, bound(0.7));
    const auto two = cutOutPlanes("0.5", 2);
    const render::Geometry g2(two);
    const Passed b = raysThrough(g2, n);
    EXPECT_NEAR(b.closest, 0.25 * n, bound(0.25));
    EXPECT_NEAR(b.shadow, 0.25 * n, bound(0.25));
    // Deterministic: the same rays, the same answers.
    const Passed again = raysThrough(g2, n);
    EXPECT_EQ(again.closest, b.closest);
    EXPECT_EQ(again.shadow, b.shadow);
}

TEST(Alpha, ACheckerboardTextureCutsOutItsZeroCells) {
    // uv of the rectangle: x in [-1, 1] -> u in [0, 1]; 4 x 4 cells, a (1) where
    // floor(4u) + floor(4v) is even.
    const auto scene = cutOutPlanes(R"({"texture": "c"})");
    const render::Geometry g(scene);
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
            const float u = (float(i) + 0.5f) / 8, v = (float(j) + 0.5f) / 8;
            const Vec3f o(2 * u - 1, 2 * v - 1, 2.0f);
            const bool opaque = ((int(std::floor(4 * u)) + int(std::floor(4 * v))) & 1) == 0;
            EXPECT_EQ(g.intersect(o, Vec3f(0, 0, -1), 10.0f).has_value(), opaque) << i << j;
            EXPECT_EQ(g.occluded(o, Vec3f(0, 0, -1), 10.0f), opaque) << i << j;
        }
}

TEST(Alpha, CutsOutShapesInsideObjects) {
    const auto scene = testing::sceneFromText(withObjects(
        R"({"a": [{"type": "rectangle", "material": "m", "alpha": 0}]})",
        R"({"type": "instance", "object": "a", "transform": [{"translate": [0, 0, 0.5]}]})"));
    const render::Geometry g(scene);
    EXPECT_FALSE(g.intersect(Vec3f(0.2f, 0.3f, 2), Vec3f(0, 0, -1), 1.0f));
    EXPECT_FALSE(g.occluded(Vec3f(0.2f, 0.3f, 2), Vec3f(0, 0, -1), 1.0f));
}

}  // namespace
}  // namespace lamina
