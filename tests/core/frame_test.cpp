#include <gtest/gtest.h>

#include "lamina/core/frame.h"
#include "lamina/core/pcg32.h"
#include "lamina/core/warp.h"

namespace lamina {
namespace {

void expectOrthonormal(const Frame<double>& f, double tol) {
    EXPECT_NEAR(glm::length(f.s), 1.0, tol);
    EXPECT_NEAR(glm::length(f.t), 1.0, tol);
    EXPECT_NEAR(glm::dot(f.s, f.t), 0.0, tol);
    EXPECT_NEAR(glm::dot(f.s, f.n), 0.0, tol);
    EXPECT_NEAR(glm::dot(f.t, f.n), 0.0, tol);
    // Right-handed: s x t = n.
    const Vec3d c = glm::cross(f.s, f.t);
    EXPECT_NEAR(glm::length(c - f.n), 0.0, tol);
}

TEST(Frame, DuffBasisIsOrthonormalForRandomNormals) {
    Pcg32 rng(1);
    for (int i = 0; i < 10000; ++i) {
        const Vec3d n = squareToUniformSphere(Vec2d(rng.nextDouble(), rng.nextDouble()));
        expectOrthonormal(Frame<double>::fromNormal(n), 1e-12);
    }
}

TEST(Frame, DuffBasisAtThePoles) {
    // The construction's singularity is at n.z = -1 in the naive version; Duff et al.'s
    // copysign form stays orthonormal there and just beside it.
    for (const Vec3d& n : {Vec3d(0, 0, 1), Vec3d(0, 0, -1), glm::normalize(Vec3d(1e-9, 0, -1)),
                           glm::normalize(Vec3d(0, 1e-12, -1)), Vec3d(1, 0, 0)})
        expectOrthonormal(Frame<double>::fromNormal(n), 1e-9);
}

TEST(Frame, LocalWorldRoundTrip) {
    const Vec3d n = glm::normalize(Vec3d(0.3, -0.5, 0.8));
    const auto f = Frame<double>::fromNormal(n);
    const Vec3d v(0.1, 0.7, -0.2);
    const Vec3d back = f.toWorld(f.toLocal(v));
    EXPECT_NEAR(glm::length(back - v), 0.0, 1e-14);
    EXPECT_NEAR(f.toLocal(n).z, 1.0, 1e-14);
}

TEST(Frame, TangentFrameFollowsTangent) {
    const Vec3d n(0, 0, 1);
    const auto f = Frame<double>::fromNormalTangent(n, Vec3d(1, 1, 0.5));
    expectOrthonormal(f, 1e-12);
    EXPECT_NEAR(f.s.x, std::sqrt(0.5), 1e-12);
    // A tangent parallel to the normal falls back to the default frame.
    expectOrthonormal(Frame<double>::fromNormalTangent(n, n), 1e-12);
}

TEST(Frame, SphericalHelpersAreClamped) {
    const Vec3d w(0.0, 0.0, 1.0 + 1e-9);
    EXPECT_EQ(sin2Theta(w), 0.0);
    EXPECT_EQ(cosPhi(w), 1.0);
    EXPECT_EQ(sinPhi(w), 0.0);
    EXPECT_TRUE(sameHemisphere(Vec3d(0, 0, 1), Vec3d(1, 0, 0.1)));
    EXPECT_FALSE(sameHemisphere(Vec3d(0, 0, 1), Vec3d(1, 0, 0.0)));
}

}  // namespace
}  // namespace lamina
