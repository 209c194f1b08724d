// Perlin noise and its octave sums (perlin_noise.h, noise_sums.h): zero at the lattice points,
// bounded, continuous across the lattice cells' faces, periodic, and equal to values worked out
// by hand from Perlin's permutation table and the gradient choice (Perlin 2002).
// Broken once on purpose each: the fade's 15 t^4 written as 14 t^4 fails HandValuesOnTheXAxis,
// ValuesInsideCells and DifferencesOnTheXAxis (ContinuousAcrossCellFaces still passes: the
// blend clamped to its two ends still lands on the far corner's ramp); the ramp of corner
// (1, 0, 0) taken at offset dx instead of dx - 1 also fails ContinuousAcrossCellFaces.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lamina/core/noise_sums.h"
#include "lamina/core/perlin_noise.h"

namespace lamina {
namespace {

float fade(float t) {
    return 6 * std::pow(t, 5.0f) - 15 * std::pow(t, 4.0f) + 10 * std::pow(t, 3.0f);
}

TEST(PerlinNoise, ZeroAtEveryLatticePoint) {
    std::mt19937 rng(1);
    std::uniform_int_distribution<int> n(-100000, 100000);
    for (int i = 0; i < 5000; ++i) {
        const Vec3f p(float(n(rng)), float(n(rng)), float(n(rng)));
        ASSERT_EQ(perlinNoise(p), 0.0f) << p.x << " " << p.y << " " << p.z;
    }
}

// On the x axis only the corners (0, 0, 0) and (1, 0, 0) of the cell count (the y and z fades
// are 0). Their hashes through Perlin's table P: P[P[P[0]]] = P[P[151]] = P[17] = 36, low
// bits 4: gradient (1, 0, 1), ramp x; P[P[P[1]]] = P[P[160]] = P[119] = 86, low bits 6:
// gradient (1, 0, -1), ramp x - 1. So noise(x, 0, 0) = (1 - f) x + f (x - 1) = x - f, with f
// the fade: 0.25 - 0.103515625 at x = 1/4.
TEST(PerlinNoise, HandValuesOnTheXAxis) {
    EXPECT_FLOAT_EQ(perlinNoise(Vec3f(0.25f, 0.0f, 0.0f)), 0.146484375f);
    EXPECT_FLOAT_EQ(perlinNoise(Vec3f(0.75f, 0.0f, 0.0f)), -0.146484375f);
    for (float x = 0.05f; x < 1.0f; x += 0.1f)
        EXPECT_NEAR(perlinNoise(Vec3f(x, 0.0f, 0.0f)), x - fade(x), 1e-6f) << x;
    // Period 256 along each axis, negative coordinates included.
    EXPECT_NEAR(perlinNoise(Vec3f(0.25f - 256.0f, 0.0f, 512.0f)), 0.146484375f, 1e-5f);
}

// Points inside cells, against an independent evaluation of the same construction in double
// precision (a Python transcription of Perlin 2002 with pbrt-v4's gradients for hashes 12..15,
// run once when the test was written; the centre of the first cell is the average of its
// eight ramps at +-0.5: -1/8).
TEST(PerlinNoise, ValuesInsideCells) {
    EXPECT_NEAR(perlinNoise(Vec3f(0.5f, 0.5f, 0.5f)), -0.125f, 1e-6f);
    EXPECT_NEAR(perlinNoise(Vec3f(1.3f, 2.7f, -0.4f)), -0.11022378f, 1e-5f);
    EXPECT_NEAR(perlinNoise(Vec3f(-3.6f, 0.2f, 5.9f)), 0.05144436f, 1e-5f);
    EXPECT_NEAR(perlinNoise(Vec3f(100.25f, -7.5f, 3.125f)), -0.03791754f, 1e-5f);
}

TEST(PerlinNoise, BoundedAndNotTrivial) {
    std::mt19937 rng(2);
    std::uniform_real_distribution<float> u(-300.0f, 300.0f);
    float largest = 0.0f;
    for (int i = 0; i < 200000; ++i) {
        const float v = perlinNoise(Vec3f(u(rng), u(rng), u(rng)));
        ASSERT_LE(std::abs(v), kPerlinNoiseBound);
        largest = std::max(largest, std::abs(v));
    }
    EXPECT_GT(largest, 0.7f);  // it does vary
    EXPECT_EQ(perlinNoise(Vec3f(std::nanf(""), 0.0f, 0.0f)), 0.0f);
    EXPECT_EQ(perlinNoise(Vec3f(0.0f, INFINITY, 0.0f)), 0.0f);
    EXPECT_TRUE(std::isfinite(perlinNoise(Vec3f(3e9f, -1e20f, 7e37f))));
}

// The noise is Lipschitz: each ramp's gradient has length sqrt(2) and the fade's slope is at
// most 15/8, so across a step h it changes by less than about 8 h; in particular across the
// faces between lattice cells, where different corners take over.
TEST(PerlinNoise, ContinuousAcrossCellFaces) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(-20.0f, 20.0f);
    const float h = 1e-3f;
    for (int i = 0; i < 20000; ++i) {
        Vec3f p(u(rng), u(rng), u(rng));
        p[i % 3] = std::round(p[i % 3]);  // on a face
        Vec3f below = p, above = p;
        below[i % 3] -= h;
        above[i % 3] += h;
        ASSERT_LE(std::abs(perlinNoise(above) - perlinNoise(below)), 8.0f * 2.0f * h);
        const Vec3f q(u(rng), u(rng), u(rng));
        ASSERT_LE(std::abs(perlinNoise(q + Vec3f(h, -h, h)) - perlinNoise(q)), 8.0f * 1.8f * h);
    }
}

// pbrt-v4's DNoise: forward differences with step 0.01. On the x axis the x difference is that
// of x - fade(x).
TEST(PerlinNoise, DifferencesOnTheXAxis) {
    const float x = 0.3f;
    const Vec3f d = perlinNoiseDifferences(Vec3f(x, 0.0f, 0.0f));
    EXPECT_NEAR(d.x, ((x + 0.01f - fade(x + 0.01f)) - (x - fade(x))) / 0.01f, 1e-3f);
}

TEST(NoiseSums, OctavesFollowTheFootprint) {
    const Vec3f zero(0.0f);
    EXPECT_FLOAT_EQ(noiseOctaves(zero, zero, 8), 8.0f);
    EXPECT_FLOAT_EQ(noiseOctaves(Vec3f(0.125f, 0.0f, 0.0f), zero, 8), 2.0f);  // -1 - log2 1/8
    EXPECT_FLOAT_EQ(noiseOctaves(zero, Vec3f(0.0f, 0.0f, 1.0f / 64.0f), 4), 4.0f);
    EXPECT_FLOAT_EQ(noiseOctaves(Vec3f(1.0f, 0.0f, 0.0f), zero, 8), 0.0f);
    EXPECT_FLOAT_EQ(noiseOctaves(Vec3f(std::nanf(""), 0.0f, 0.0f), zero, 8), 0.0f);
}

// A footprint that resolves exactly two octaves: fbm is noise(p) + omega noise(1.99 p) (the
// partial octave has weight smoothstep(0) = 0); turbulence adds the fill-ins 0.2 omega^i of
// the octaves i = 2..maxOctaves - 1 and 0.2 omega^2 for the partial one.
TEST(NoiseSums, WholeOctavesByHand) {
    const Vec3f p(0.3f, 1.7f, -2.2f), dp(0.125f, 0.0f, 0.0f), zero(0.0f);
    const float omega = 0.5f;
    const float n0 = perlinNoise(p), n1 = perlinNoise(1.99f * p);
    EXPECT_NEAR(fbm(p, dp, zero, omega, 6), n0 + omega * n1, 1e-6f);
    const float fill = 0.2f * (0.25f + 0.25f + 0.125f + 0.0625f + 0.03125f);
    EXPECT_NEAR(turbulence(p, dp, zero, omega, 6), std::abs(n0) + omega * std::abs(n1) + fill,
                1e-6f);
}

TEST(NoiseSums, Bounded) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(-50.0f, 50.0f), scale(-12.0f, 2.0f);
    for (const float omega : {0.5f, 0.9f, 0.0f}) {
        const float bound = noiseSumBound(omega, 8);
        for (int i = 0; i < 20000; ++i) {
            const Vec3f p(u(rng), u(rng), u(rng));
            const Vec3f dp(std::exp2(scale(rng)), 0.0f, 0.0f);
            ASSERT_LE(std::abs(fbm(p, dp, Vec3f(0.0f), omega, 8)), bound);
            const float t = turbulence(p, dp, Vec3f(0.0f), omega, 8);
            ASSERT_GE(t, 0.0f);
            ASSERT_LE(t, bound);
        }
    }
}

}  // namespace
}  // namespace lamina
