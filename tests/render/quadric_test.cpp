// pbrt-v4's quadrics in the geometry (quadric.h, Embree user geometry): rays hit a cylinder, a
// clipped sphere and a clipped disk where the closed forms say, with pbrt-v4's uv and the normal
// facing out; phi_max, z_min / z_max and the inner radius clip them; they are placed by their
// transform, inside instances too, and cut out by alpha; whole spheres and disks stay Embree's
// own primitives. The scene reader refuses hostile parameters naming the JSON path.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/core/pcg32.h"
#include "lamina/core/warp.h"
#include "lamina/geometry/geometry.h"
#include "lamina/geometry/quadric.h"
#include "render_helpers.h"
#include "scratch_directory.h"

namespace lamina::render {
namespace {

using ::testing::HasSubstr;

constexpr double kTwoPi = 2 * kPi<double>;

// A scene of the one shape `shape` (its JSON object without the material).
SceneDesc sceneWith(const std::string& shape) {
    return testing::sceneFromText(R"({
      "materials": {"m": {"type": "lambert", "reflectance": 0.5}},
      "lights": [{"type": "point", "position": [0, 0, 100], "intensity": 1}],
      "shapes": [{"material": "m", )" +
                                  shape + "}]}");
}

// The hit of the ray (o, d) in `scene`, or nullopt.
std::optional<SurfaceHit> hitOf(const SceneDesc& scene, const Vec3f& o, const Vec3f& d) {
    const Geometry g(scene);
    const auto hit = g.intersect(o, glm::normalize(d));
    // The shadow ray agrees with the closest hit.
    EXPECT_EQ(g.occluded(o, glm::normalize(d), std::numeric_limits<float>::infinity()),
              hit.has_value());
    return hit;
}

void expectNear(const Vec3f& a, const Vec3f& b, float tolerance = 2e-6f) {
    EXPECT_NEAR(a.x, b.x, tolerance);
    EXPECT_NEAR(a.y, b.y, tolerance);
    EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(QuadricHits, ARayThroughTheCylindersAxisHitsAtItsRadius) {
    // Radius 2 about z, z in [-1, 1]: from outside the near wall at x = -2 (phi = pi: u = 1/2,
    // v = (z - z_min) / (z_max - z_min)), the normal facing out of the axis, towards the ray.
    const SceneDesc scene = sceneWith(R"("type": "cylinder", "radius": 2)");
    ASSERT_TRUE(std::holds_alternative<QuadricDesc>(scene.shapes[0]));
    auto hit = hitOf(scene, Vec3f(-5, 0, 0.3f), Vec3f(1, 0, 0));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 3.0f, 1e-6f);
    expectNear(hit->p, Vec3f(-2, 0, 0.3f));
    expectNear(hit->ng, Vec3f(-1, 0, 0));
    EXPECT_NEAR(hit->uv.x, 0.5f, 1e-6f);
    EXPECT_NEAR(hit->uv.y, 0.65f, 1e-6f);
    // From the axis, the far wall, seen from inside: the normal still faces out.
    hit = hitOf(scene, Vec3f(0, 0, -0.5f), Vec3f(0, 1, 0));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 2.0f, 1e-6f);
    expectNear(hit->ng, Vec3f(0, 1, 0));
    EXPECT_NEAR(hit->uv.x, 0.25f, 1e-6f);  // phi = pi / 2
    EXPECT_NEAR(hit->uv.y, 0.25f, 1e-6f);
    // An oblique ray: |o + t d|_xy = r at the smaller root.
    const Vec3f o(-3, 1, 0.2f), d = glm::normalize(Vec3f(1, -0.2f, 0.1f));
    hit = hitOf(scene, o, d);
    ASSERT_TRUE(hit);
    const double a = double(d.x) * d.x + double(d.y) * d.y,
                 b = double(o.x) * d.x + double(o.y) * d.y,
                 c = double(o.x) * o.x + double(o.y) * o.y - 4;
    EXPECT_NEAR(hit->t, float((-b - std::sqrt(b * b - a * c)) / a), 2e-6f);
    EXPECT_NEAR(std::hypot(hit->p.x, hit->p.y), 2.0f, 1e-6f);
    // Along the axis, and outside z_min..z_max: no hit (the cylinder is open).
    EXPECT_FALSE(hitOf(scene, Vec3f(0, 0, -5), Vec3f(0, 0, 1)));
    EXPECT_FALSE(hitOf(scene, Vec3f(-5, 0, 1.01f), Vec3f(1, 0, 0)));
    EXPECT_FALSE(hitOf(scene, Vec3f(0, 0, 0), Vec3f(1, 0, 1)));  // leaves through the top
}

TEST(QuadricHits, PhiMaxClipsTheCylinderFromPlusXTowardsPlusY) {
    // phi_max 90: only the quarter x >= 0, y >= 0. A ray along +x at y = 0.5 crosses the
    // wall at phi ~ 165 degrees (clipped) and then at phi ~ 14.5 degrees.
    const SceneDesc scene = sceneWith(R"("type": "cylinder", "radius": 2, "phi_max": 90)");
    auto hit = hitOf(scene, Vec3f(-5, 0.5f, 0), Vec3f(1, 0, 0));
    ASSERT_TRUE(hit);
    const double x = std::sqrt(4 - 0.25);
    EXPECT_NEAR(hit->t, float(5 + x), 2e-6f);
    EXPECT_NEAR(hit->uv.x, float(std::atan2(0.5, x) / (kPi<double> / 2)), 1e-6f);
    expectNear(hit->ng, Vec3f(float(x / 2), 0.25f, 0));
    EXPECT_FALSE(hitOf(scene, Vec3f(-5, -0.5f, 0), Vec3f(1, 0, 0)));  // phi 195 and 345
    EXPECT_FALSE(hitOf(scene, Vec3f(-1, -5, 0), Vec3f(0, 1, 0)));     // phi 240 and 120
}

TEST(QuadricHits, ZMinAndZMaxClipTheSphereAndPhiMaxTurnsFromX) {
    // A unit sphere without its cap above z = 0.5: from above the ray passes through the
    // opening and hits the bottom's inside at z = -1, whose normal faces out (down).
    const SceneDesc cap = sceneWith(R"("type": "sphere", "z_max": 0.5)");
    ASSERT_TRUE(std::holds_alternative<QuadricDesc>(cap.shapes[0]));
    auto hit = hitOf(cap, Vec3f(0, 0, 5), Vec3f(0, 0, -1));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 6.0f, 1e-6f);
    expectNear(hit->ng, Vec3f(0, 0, -1));
    // A ray below the cut hits the outside; v runs from z_min (0) to z_max (1) in theta.
    hit = hitOf(cap, Vec3f(-5, 0, 0), Vec3f(1, 0, 0));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 4.0f, 1e-6f);
    const double thetaMin = kPi<double>, thetaMax = std::acos(0.5);
    EXPECT_NEAR(hit->uv.y, float((kPi<double> / 2 - thetaMin) / (thetaMax - thetaMin)), 1e-6f);
    // z_min cuts the bottom as z_max the top.
    const SceneDesc band = sceneWith(R"("type": "sphere", "radius": 2, "z_min": -1, "z_max": 1)");
    EXPECT_FALSE(hitOf(band, Vec3f(0, 0, -5), Vec3f(0, 0, 1)));
    hit = hitOf(band, Vec3f(0.5f, 0, -5), Vec3f(0, 0, 1));
    EXPECT_FALSE(hit);  // |z| = sqrt(4 - 0.25) > 1 at both crossings
    hit = hitOf(band, Vec3f(0, -5, 0.5f), Vec3f(0, 1, 0));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->p.y, -float(std::sqrt(4 - 0.25)), 2e-6f);
    // phi_max 180: the half y >= 0. Along +y the near crossing (phi = 270) is clipped, the
    // far one (phi = 90, u = 1/2) is hit from inside.
    const SceneDesc half = sceneWith(R"("type": "sphere", "phi_max": 180)");
    hit = hitOf(half, Vec3f(0, -5, 0), Vec3f(0, 1, 0));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 6.0f, 1e-6f);
    EXPECT_NEAR(hit->uv.x, 0.5f, 1e-6f);
    EXPECT_NEAR(hit->uv.y, 0.5f, 1e-6f);
    expectNear(hit->ng, Vec3f(0, 1, 0));
}

TEST(QuadricHits, TheDisksInnerRadiusAndPhiMaxClipIt) {
    // Radius 1, inner radius 0.5, in z = 0 facing +z; v = (r - rho) / (r - r_inner).
    const SceneDesc annulus = sceneWith(R"("type": "disk", "inner_radius": 0.5)");
    ASSERT_TRUE(std::holds_alternative<QuadricDesc>(annulus.shapes[0]));
    EXPECT_FALSE(hitOf(annulus, Vec3f(0.25f, 0, 1), Vec3f(0, 0, -1)));
    EXPECT_FALSE(hitOf(annulus, Vec3f(0.49f, 0, 1), Vec3f(0, 0, -1)));
    EXPECT_FALSE(hitOf(annulus, Vec3f(0, 1.01f, 1), Vec3f(0, 0, -1)));
    auto hit = hitOf(annulus, Vec3f(0, 0.75f, 1), Vec3f(0, 0, -1));
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1.0f, 1e-6f);
    expectNear(hit->ng, Vec3f(0, 0, 1));
    EXPECT_NEAR(hit->uv.x, 0.25f, 1e-6f);
    EXPECT_NEAR(hit->uv.y, 0.5f, 1e-6f);
    // phi_max 90 keeps the quarter x, y >= 0; flip_normals turns it to face -z.
    const SceneDesc quarter =
        sceneWith(R"("type": "disk", "phi_max": 90, "radius": 2, "flip_normals": true)");
    hit = hitOf(quarter, Vec3f(1, 1, -1), Vec3f(0, 0, 1));
    ASSERT_TRUE(hit);
    expectNear(hit->ng, Vec3f(0, 0, -1));
    EXPECT_NEAR(hit->uv.x, 0.5f, 1e-6f);
    EXPECT_FALSE(hitOf(quarter, Vec3f(-1, 1, -1), Vec3f(0, 0, 1)));
    EXPECT_FALSE(hitOf(quarter, Vec3f(1, -1, -1), Vec3f(0, 0, 1)));
}

TEST(QuadricHits, TheTransformPlacesTheFrameAndMirroringTurnsOnlyTheDisk) {
    // Rotated so that the axis is +y, scaled by 2, moved by (1, 2, 3): the cylinder's radius 1
    // becomes 2 about the line x = 1, z = 3; its z in [0, 1] becomes y in [2, 4]; phi turns
    // from the frame's x (+x) towards its y (rotate -90 about x: -z).
    const SceneDesc scene = sceneWith(
        R"("type": "cylinder", "z_min": 0, "z_max": 1, "phi_max": 90, "transform": [
           {"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"scale": 2}, {"translate": [1, 2, 3]}])");
    const QuadricDesc& q = std::get<QuadricDesc>(scene.shapes[0]);
    EXPECT_NEAR(q.radius, 2.0, 1e-12);
    EXPECT_NEAR(q.area(), kPi<double> / 2 * 2 * 2, 1e-12);
    // From the axis at y = 3 (v = 1/2) out along phi = 45 degrees: the frame's x and y are
    // +x and -z there.
    auto hit = hitOf(scene, Vec3f(1, 3, 3), glm::normalize(Vec3f(1, 0, -1)));
    ASSERT_TRUE(hit);
    expectNear(hit->p, Vec3f(1 + float(std::sqrt(2.0)), 3, 3 - float(std::sqrt(2.0))), 4e-6f);
    EXPECT_NEAR(hit->uv.x, 0.5f, 1e-6f);
    EXPECT_NEAR(hit->uv.y, 0.5f, 1e-6f);
    expectNear(hit->ng, glm::normalize(Vec3f(1, 0, -1)), 4e-6f);
    EXPECT_FALSE(hitOf(scene, Vec3f(1, 3, 3), glm::normalize(Vec3f(1, 0, 1))));
    EXPECT_FALSE(hitOf(scene, Vec3f(1, 4.1f, 3), glm::normalize(Vec3f(1, 0, -1))));
    // A mirroring transform keeps the cylinder facing out and turns a disk's front over, as
    // it turns a whole disk's.
    const SceneDesc mirrored =
        sceneWith(R"("type": "cylinder", "phi_max": 180, "transform": [{"scale": [1, 1, -1]}])");
    hit = hitOf(mirrored, Vec3f(0, 5, 0), Vec3f(0, -1, 0));
    ASSERT_TRUE(hit);
    expectNear(hit->ng, Vec3f(0, 1, 0));
    const SceneDesc mirroredDisks = testing::sceneFromText(R"({
      "materials": {"m": {"type": "lambert"}}, "lights": [{"type": "point", "position": [0, 0, 9], "intensity": 1}],
      "shapes": [{"type": "disk", "material": "m", "inner_radius": 0.1,
                  "transform": [{"scale": [-1, 1, 1]}]},
                 {"type": "disk", "material": "m", "center": [3, 0, 0],
                  "transform": [{"scale": [-1, 1, 1]}]}]})");
    const Geometry g(mirroredDisks);
    expectNear(g.intersect(Vec3f(0.5f, 0, 1), Vec3f(0, 0, -1))->ng, Vec3f(0, 0, -1));
    expectNear(g.intersect(Vec3f(-3.5f, 0, 1), Vec3f(0, 0, -1))->ng, Vec3f(0, 0, -1));
}

TEST(QuadricHits, InstancesPlaceQuadricsAsTheirCopiesAreWritten) {
    // The same clipped shapes in an object under a rotation and a mirroring, and written out
    // with those transforms: every ray hits both at the same place with the same normal and uv.
    const char* shapes = R"(
      {"type": "cylinder", "material": "m", "radius": 0.5, "phi_max": 250XFORM},
      {"type": "sphere", "material": "m", "radius": 0.7, "z_min": -0.2, "phi_max": 300XFORM},
      {"type": "disk", "material": "m", "inner_radius": 0.3, "phi_max": 200XFORM})";
    const std::string transform =
        R"([{"rotate": {"axis": [0.3, 1, 0.2], "angle": 40}}, {"scale": [-1.5, 1.5, 1.5]},
            {"translate": [0.2, -0.1, 0.5]}])";
    const auto replace = [](std::string s, const std::string& with) {
        for (std::size_t at; (at = s.find("XFORM")) != std::string::npos;)
            s.replace(at, 5, with);
        return s;
    };
    const SceneDesc copies = testing::sceneFromText(
        std::string(R"({"materials": {"m": {"type": "lambert"}}, "lights": [{"type": "point",
        "position": [0, 0, 9], "intensity": 1}], "shapes": [)") +
        replace(shapes, ", \"transform\": " + transform) + "]}");
    const SceneDesc instanced = testing::sceneFromText(
        std::string(R"({"materials": {"m": {"type": "lambert"}}, "lights": [{"type": "point",
        "position": [0, 0, 9], "intensity": 1}], "objects": {"o": [)") +
        replace(shapes, "") + R"(]}, "shapes": [{"type": "instance", "object": "o",
        "transform": )" +
        transform + "}]}");
    const Geometry a(copies), b(instanced);
    Pcg32 rng(5);
    int hits = 0;
    for (int k = 0; k < 4000; ++k) {
        const Vec3f o = 4.0f * squareToUniformSphere(Vec2f(rng.nextFloat(), rng.nextFloat()));
        const Vec3f target =
            0.8f * (Vec3f(rng.nextFloat(), rng.nextFloat(), rng.nextFloat()) - Vec3f(0.5f)) +
            Vec3f(0.2f, -0.1f, 0.5f);
        const Vec3f d = glm::normalize(target - o);
        const auto ha = a.intersect(o, d), hb = b.intersect(o, d);
        ASSERT_EQ(ha.has_value(), hb.has_value()) << k;
        if (!ha) continue;
        ++hits;
        // Embree intersects the instance along the ray carried into the object in float: the
        // two agree to rounding, not bit for bit (as Instancing.HitsEqualTheCopiesWrittenOut).
        EXPECT_NEAR(ha->t, hb->t, 1e-4f * hb->t) << k;
        EXPECT_LT(glm::length(ha->p - hb->p), 1e-4f) << k;
        EXPECT_GT(glm::dot(ha->ng, hb->ng), 0.99999f) << k;
        EXPECT_NEAR(ha->uv.x, hb->uv.x, 1e-4f) << k;
        EXPECT_NEAR(ha->uv.y, hb->uv.y, 1e-4f) << k;
    }
    EXPECT_GT(hits, 1000);
}

TEST(QuadricHits, AlphaCutsQuadricsOutForClosestHitAndShadowRaysAlike) {
    EXPECT_FALSE(
        hitOf(sceneWith(R"("type": "cylinder", "alpha": 0)"), Vec3f(-5, 0, 0), Vec3f(1, 0, 0)));
    // Alpha 0.5: about half of many rays stop at the first wall, half of the rest at the
    // second (each crossing is hashed on its own), and a shadow ray stops when a closest-hit
    // ray would.
    const SceneDesc scene = sceneWith(R"("type": "cylinder", "alpha": 0.5, "radius": 2)");
    const Geometry g(scene);
    Pcg32 rng(3);
    int near = 0, far = 0, disagree = 0;
    constexpr int kRays = 20000;
    for (int k = 0; k < kRays; ++k) {
        const Vec3f o(-5, 0.2f * rng.nextFloat(), rng.nextFloat() - 0.5f);
        const auto hit = g.intersect(o, Vec3f(1, 0, 0));
        if (hit && hit->p.x < 0) ++near;
        if (hit && hit->p.x > 0) ++far;
        disagree += hit.has_value() != g.occluded(o, Vec3f(1, 0, 0), 100.0f);
    }
    // Binomial: 4 standard deviations of 0.5 and 0.25 of the rays.
    EXPECT_NEAR(near, kRays / 2, 4 * std::sqrt(kRays * 0.25));
    EXPECT_NEAR(far, kRays / 4, 4 * std::sqrt(kRays * 0.25 * 0.75));
    EXPECT_EQ(disagree, 0);
}

TEST(QuadricShapes, WholeSpheresAndDisksStayEmbreesOwnPrimitives) {
    // Clipping keys at their whole-shape values change nothing: the same SphereDesc and
    // DiskDesc as without them.
    EXPECT_TRUE(std::holds_alternative<SphereDesc>(
        sceneWith(R"("type": "sphere", "radius": 2, "z_min": -2, "z_max": 2, "phi_max": 360)")
            .shapes[0]));
    EXPECT_TRUE(std::holds_alternative<DiskDesc>(
        sceneWith(R"("type": "disk", "inner_radius": 0, "phi_max": 360)").shapes[0]));
    const SceneDesc flipped = sceneWith(R"("type": "disk", "flip_normals": true)");
    EXPECT_EQ(std::get<DiskDesc>(flipped.shapes[0]).normal, Vec3d(0, 0, -1));
}

TEST(QuadricShapes, AreasAndBoxesAreTheClosedForms) {
    const auto quadric = [](const std::string& shape) {
        return std::get<QuadricDesc>(sceneWith(shape).shapes[0]);
    };
    // Archimedes: a sphere's zone has area 2 pi r h; phi_max takes its share.
    EXPECT_NEAR(
        quadric(R"("type": "sphere", "radius": 2, "z_min": -1, "z_max": 1.5, "phi_max": 90)")
            .area(),
        kPi<double> / 2 * 2 * 2.5, 1e-12);
    EXPECT_NEAR(quadric(R"("type": "cylinder", "radius": 0.5, "z_min": 1, "z_max": 4)").area(),
                kTwoPi * 0.5 * 3, 1e-12);
    EXPECT_NEAR(quadric(R"("type": "disk", "radius": 2, "inner_radius": 1, "phi_max": 180)").area(),
                kPi<double> / 2 * (4 - 1), 1e-12);
    EXPECT_NEAR(
        quadric(R"("type": "disk", "radius": 2, "phi_max": 90, "transform": [{"scale": 3}])")
            .area(),
        kPi<double> / 4 * 36, 1e-12);
    Vec3d lo, hi;
    quadric(R"("type": "cylinder", "radius": 0.5, "z_min": 1, "z_max": 4,
               "transform": [{"translate": [1, 0, 0]}])")
        .bounds(lo, hi);
    EXPECT_EQ(lo, Vec3d(0.5, -0.5, 1));
    EXPECT_EQ(hi, Vec3d(1.5, 0.5, 4));
}

TEST(QuadricShapes, SampledPointsLieOnTheClippedSurface) {
    const char* shapes[] = {
        R"("type": "sphere", "radius": 2, "z_min": -0.5, "z_max": 1.5, "phi_max": 120)",
        R"("type": "cylinder", "radius": 0.5, "z_min": 1, "z_max": 4, "phi_max": 300)",
        R"("type": "disk", "radius": 2, "inner_radius": 1, "phi_max": 45)"};
    for (const char* shape : shapes) {
        const QuadricDesc q = std::get<QuadricDesc>(sceneWith(shape).shapes[0]);
        Pcg32 rng(11);
        for (int k = 0; k < 10000; ++k) {
            const Vec3d p = sampleQuadric(q, Vec2<double>(rng.nextDouble(), rng.nextDouble()));
            const double phi = std::fmod(std::atan2(p.y, p.x) + kTwoPi, kTwoPi);
            EXPECT_LE(phi, q.phiMax + 1e-12) << shape;
            if (q.kind == Quadric::Disk) {
                EXPECT_EQ(p.z, 0.0);
                EXPECT_GE(std::hypot(p.x, p.y), q.innerRadius - 1e-12) << shape;
                EXPECT_LE(std::hypot(p.x, p.y), q.radius + 1e-12) << shape;
            } else {
                EXPECT_GE(p.z, q.zMin - 1e-12) << shape;
                EXPECT_LE(p.z, q.zMax + 1e-12) << shape;
                EXPECT_NEAR(q.kind == Quadric::Sphere ? glm::length(p) : std::hypot(p.x, p.y),
                            q.radius, 1e-12)
                    << shape;
            }
        }
    }
}

// Each hostile value is one InputError naming the file, the JSON path and what was expected.
TEST(QuadricErrors, HostileParametersNameTheJsonPath) {
    const auto error = [](const std::string& shape) {
        return testing::errorOf([&] { sceneWith(shape); });
    };
    EXPECT_THAT(error(R"("type": "cylinder", "z_min": 1, "z_max": -1)"),
                HasSubstr("<test scene>: shapes[0].z_max: expected more than z_min (1)"));
    EXPECT_THAT(error(R"("type": "cylinder", "z_min": 1, "z_max": 1)"),
                HasSubstr("shapes[0].z_max: expected more than z_min (1)"));
    EXPECT_THAT(error(R"("type": "cylinder", "radius": -1)"), HasSubstr("shapes[0].radius:"));
    EXPECT_THAT(error(R"("type": "sphere", "z_max": 0.2, "z_min": 0.5)"),
                HasSubstr("shapes[0].z_max: expected more than z_min (0.5)"));
    EXPECT_THAT(error(R"("type": "sphere", "radius": 2, "z_min": -3)"),
                HasSubstr("shapes[0].z_min:"));
    EXPECT_THAT(error(R"("type": "cylinder", "phi_max": 0)"), HasSubstr("shapes[0].phi_max:"));
    EXPECT_THAT(error(R"("type": "sphere", "phi_max": 360.5)"), HasSubstr("shapes[0].phi_max:"));
    EXPECT_THAT(error(R"("type": "disk", "phi_max": -10)"), HasSubstr("shapes[0].phi_max:"));
    EXPECT_THAT(error(R"("type": "disk", "inner_radius": 1)"),
                HasSubstr("shapes[0].inner_radius:"));
    EXPECT_THAT(error(R"("type": "disk", "inner_radius": -0.1)"),
                HasSubstr("shapes[0].inner_radius:"));
    EXPECT_THAT(error(R"("type": "disk", "phi_max": 90, "normal": [1, 0, 0])"),
                HasSubstr("shapes[0].normal: a disk with phi_max is oriented by its transform"));
    EXPECT_THAT(error(R"("type": "cylinder", "z_max": "high")"), HasSubstr("shapes[0].z_max:"));
    EXPECT_THAT(error(R"("type": "cylinder", "z_max": 1e30, "transform": [{"scale": 1e10}])"),
                HasSubstr("too far out for float rays"));
    // A shear with columns of equal length is no similarity either.
    EXPECT_THAT(error(R"("type": "cylinder", "transform": [{"matrix":
                         [1, 0.6, 0, 0, 0, 0.8, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]}])"),
                HasSubstr("shapes[0].transform: a cylinder takes translate, rotate and uniform "
                          "scale only"));
    EXPECT_THAT(error(R"("type": "cylinder", "emission": {"radiance": 1}, "radius": 1e-30,
                         "z_min": 0, "z_max": 1e-30)"),
                HasSubstr("shapes[0].emission: the emitting shape has zero area in float"));
}

}  // namespace
}  // namespace lamina::render
