#include <gtest/gtest.h>

#include "lamina/bsdf/diffuse.h"

namespace lamina {
namespace {

TEST(Lambert, EvalIsReflectanceOverPiTimesCosine) {
    const DiffuseBxdf<Rgbd> bxdf(Rgbd(0.5, 0.25, 1.0));
    const Vec3d wo(0, 0, 1), wi = glm::normalize(Vec3d(1, 0, 1));
    const Rgbd f = bxdf.eval(wo, wi, TransportMode::Radiance);
    EXPECT_NEAR(f[0], 0.5 / kPi<double> * wi.z, 1e-15);
    EXPECT_NEAR(bxdf.pdf(wo, wi), wi.z / kPi<double>, 1e-15);
    EXPECT_TRUE(bxdf.eval(wo, -wi, TransportMode::Radiance).isZero());
    // Two-sided: mirrored to the side of wo.
    EXPECT_EQ(bxdf.eval(-wo, -wi, TransportMode::Radiance), f);
}

TEST(Lambert, SampleWeightIsReflectance) {
    const DiffuseBxdf<SampledSpectrum<float>> bxdf(SampledSpectrum<float>(0.1f, 0.2f, 0.3f, 0.4f));
    const auto s = bxdf.sample(Vec3f(0, 0, -1), 0.5f, Vec2f(0.3f, 0.6f), TransportMode::Radiance);
    ASSERT_TRUE(s);
    EXPECT_LT(s->wi.z, 0.0f);
    EXPECT_EQ(s->weight, bxdf.reflectance());
    EXPECT_NEAR(s->pdf, bxdf.pdf(Vec3f(0, 0, -1), s->wi), 1e-6f);
    // wo at the horizon: no sample.
    EXPECT_FALSE(bxdf.sample(Vec3f(1, 0, 0), 0.5f, Vec2f(0.3f, 0.6f), TransportMode::Radiance));
}

}  // namespace
}  // namespace lamina
