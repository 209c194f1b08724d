// Robust ray origins (Waechter and Binder 2019) at large and tiny scales: a ray leaving a
// surface towards the outside never hits that surface again, and a ray entering a closed
// sphere reaches its far side, not its own starting point.
#include <gtest/gtest.h>

#include "lamina/core/pcg32.h"
#include "lamina/core/warp.h"
#include "lamina/geometry/geometry.h"
#include "lamina/geometry/ray_offset.h"
#include "render_helpers.h"

namespace lamina {
namespace {

using render::Vec3f;

struct ScaleCase {
    double scale;   // size of the shapes
    double offset;  // distance of the shapes from the origin
};

class RayOffset : public ::testing::TestWithParam<ScaleCase> {};

// Geometry numbers meshes first, then spheres (SceneDesc::shapes is ordered by kind).
constexpr int kTriangle = 0, kSphere = 1;

TEST_P(RayOffset, NoSelfIntersectionOnSpheresAndTriangles) {
    const double s = GetParam().scale, c = GetParam().offset;
    char json[1024];
    std::snprintf(json, sizeof json, R"({
      "materials": {"m": {"type": "lambert"}},
      "shapes": [
        {"type": "sphere", "center": [%.17g, %.17g, %.17g], "radius": %.17g, "material": "m"},
        {"type": "mesh", "material": "m",
         "positions": [[%.17g, %.17g, %.17g], [%.17g, %.17g, %.17g], [%.17g, %.17g, %.17g]],
         "faces": [[0, 1, 2]], "emission": {"radiance": 1}}
      ]})",
                  c, c, c, s, c + 3 * s, c - 2 * s, c - 2 * s, c + 3 * s, c + 2 * s, c - 2 * s,
                  c + 3 * s, c, c + 2 * s);
    const auto scene = testing::sceneFromText(json);
    const render::Geometry geometry(scene);
    Pcg32 rng(17);
    int sphereHits = 0, triangleHits = 0, failures = 0;
    for (int i = 0; i < 20000; ++i) {
        // Aim at a random point of the sphere from outside, then leave it.
        const Vec3<double> dir =
            Vec3<double>(squareToUniformSphere(Vec2<double>(rng.nextDouble(), rng.nextDouble())));
        const Vec3f origin = Vec3f(Vec3<double>(c) + 10 * s * dir);
        const auto target =
            Vec3f(Vec3<double>(c) + 0.5 * s *
                                        Vec3<double>(squareToUniformSphere(
                                            Vec2<double>(rng.nextDouble(), rng.nextDouble()))));
        const auto hit = geometry.intersect(origin, glm::normalize(target - origin));
        if (!hit || hit->shape != kSphere) continue;
        ++sphereHits;
        // Outwards (reflection): must escape the convex sphere.
        const Vec3f out = render::offsetRayOrigin(hit->p, hit->ng, geometry.rayOffsetScale());
        Vec3f w = squareToCosineHemisphere(Vec2f(rng.nextFloat(), rng.nextFloat()));
        w = Frame<float>::fromNormal(hit->ng).toWorld(w);
        if (const auto again = geometry.intersect(out, w); again && again->shape == kSphere)
            ++failures;
        // Inwards (refraction): must reach the far side, at least a little away.
        const Vec3f in = render::offsetRayOrigin(hit->p, -hit->ng, geometry.rayOffsetScale());
        const auto far = geometry.intersect(in, -hit->ng);
        if (!far || far->shape != kSphere || far->t < 1.0f * float(s)) ++failures;
    }
    for (int i = 0; i < 5000; ++i) {
        const Vec2f b = squareToUniformTriangle(Vec2f(rng.nextFloat(), rng.nextFloat()));
        const auto& m = std::get<render::MeshDesc>(scene.shapes[0]);
        const Vec3f p =
            b.x * m.positions[0] + b.y * m.positions[1] + (1 - b.x - b.y) * m.positions[2];
        const Vec3f n = glm::normalize(
            glm::cross(m.positions[1] - m.positions[0], m.positions[2] - m.positions[0]));
        const Vec3f origin = p + 5.0f * float(s) * n;
        const auto hit = geometry.intersect(origin, glm::normalize(p - origin));
        if (!hit || hit->shape != kTriangle) continue;
        ++triangleHits;
        const Vec3f w = Frame<float>::fromNormal(hit->ng).toWorld(
            squareToCosineHemisphere(Vec2f(rng.nextFloat(), rng.nextFloat())));
        if (const auto again = geometry.intersect(
                render::offsetRayOrigin(hit->p, hit->ng, geometry.rayOffsetScale()), w);
            again && again->shape == kTriangle)
            ++failures;
    }
    EXPECT_GT(sphereHits, 15000);
    EXPECT_GT(triangleHits, 4000);
    EXPECT_EQ(failures, 0);
}

// pbrt-v4's quadrics (Embree user geometry, hits refined in double precision): a ray leaving a
// cylinder's or a clipped sphere's hit never hits that surface again at once, and a ray
// entering the cylinder towards its axis reaches its far side.
TEST_P(RayOffset, NoSelfIntersectionOnQuadrics) {
    const double s = GetParam().scale, c = GetParam().offset;
    char json[1024];
    std::snprintf(json, sizeof json, R"({
      "materials": {"m": {"type": "lambert"}},
      "lights": [{"type": "point", "position": [0, 0, 0], "intensity": 1}],
      "shapes": [
        {"type": "cylinder", "radius": %.17g, "z_min": %.17g, "z_max": %.17g, "material": "m",
         "transform": [{"rotate": {"axis": [1, 2, 3], "angle": 50}},
                       {"translate": [%.17g, %.17g, %.17g]}]},
        {"type": "sphere", "radius": %.17g, "z_max": %.17g, "phi_max": 300, "material": "m",
         "center": [%.17g, %.17g, %.17g]}
      ]})",
                  s, -3 * s, 3 * s, c, c, c, s, 0.8 * s, c + 6 * s, c, c);
    const auto scene = testing::sceneFromText(json);
    const render::Geometry geometry(scene);
    Pcg32 rng(19);
    int hits[2] = {0, 0}, failures = 0;
    const Vec3<double> centres[2] = {Vec3<double>(c), Vec3<double>(c + 6 * s, c, c)};
    for (int i = 0; i < 20000; ++i) {
        const int target = i % 2;
        const Vec3<double> dir =
            Vec3<double>(squareToUniformSphere(Vec2<double>(rng.nextDouble(), rng.nextDouble())));
        const Vec3f origin = Vec3f(centres[target] + 10 * s * dir);
        const auto aim =
            Vec3f(centres[target] + 0.5 * s *
                                        Vec3<double>(squareToUniformSphere(
                                            Vec2<double>(rng.nextDouble(), rng.nextDouble()))));
        const auto hit = geometry.intersect(origin, glm::normalize(aim - origin));
        if (!hit) continue;
        ++hits[hit->shape];
        // Leaving on either side: never the same surface again within a hundredth of its size.
        for (const float side : {1.0f, -1.0f}) {
            const Vec3f n = side * hit->ng;
            const Vec3f out = render::offsetRayOrigin(hit->p, n, geometry.rayOffsetScale());
            const Vec3f w = Frame<float>::fromNormal(n).toWorld(
                squareToCosineHemisphere(Vec2f(rng.nextFloat(), rng.nextFloat())));
            if (const auto again = geometry.intersect(out, w);
                again && again->shape == hit->shape && again->t < 0.01f * float(s))
                ++failures;
        }
        // Into the cylinder towards its axis: the far side, about a diameter away.
        if (hit->shape == 0 && glm::dot(hit->ng, glm::normalize(aim - origin)) < 0) {
            const Vec3f in = render::offsetRayOrigin(hit->p, -hit->ng, geometry.rayOffsetScale());
            const auto far = geometry.intersect(in, -hit->ng);
            if (!far || far->shape != 0 || far->t < 1.0f * float(s)) ++failures;
        }
    }
    EXPECT_GT(hits[0], 5000);
    EXPECT_GT(hits[1], 5000);
    EXPECT_EQ(failures, 0);
}

INSTANTIATE_TEST_SUITE_P(Scales, RayOffset,
                         ::testing::Values(ScaleCase{1e-4, 0}, ScaleCase{1e-4, 1.0},
                                           ScaleCase{1, 0}, ScaleCase{1, 1e3}, ScaleCase{1e4, 0},
                                           ScaleCase{1e4, 1e5}),
                         [](const auto& paramInfo) {
                             return "case" + std::to_string(paramInfo.index);
                         });

}  // namespace
}  // namespace lamina
