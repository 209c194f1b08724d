// The layered stack seen from inside a transmitting material (bsdf/layered.h): a layer whose
// base is all transmission (weight 1) through an interface of the exact dielectric Fresnel is
// Walter et al.'s rough dielectric, so it must evaluate, sample and weigh as lamina's
// `dielectric` of the same index and roughness from both sides. From inside the interface's
// reflection is the Fresnel seen from inside (total internal reflection past the critical
// angle): with the outside Fresnel there instead, the light the interface cannot transmit was
// lost (a smooth layer reflected 0.09 of it at 60 degrees, index 1.5, and transmitted none).
#include <gtest/gtest.h>

#include <cmath>

#include "lamina/bsdf/dielectric.h"
#include "lamina/bsdf/layered.h"
#include "lamina/core/pcg32.h"
#include "lamina/core/warp.h"

namespace lamina {
namespace {

using S = Rgb<double>;
using V3 = Vec3<double>;

std::shared_ptr<LayeredBxdf<S>> allTransmission(double alpha, double eta) {
    typename LayeredBxdf<S>::Layers l;
    const MicrofacetDistribution<double> d(NdfKind::Ggx, alpha, alpha);
    l.interface.emplace(d, Fresnel<S>::dielectric(S(eta)));
    l.transmission.emplace(eta, d);
    l.transmissionWeight = 1.0;
    return std::make_shared<LayeredBxdf<S>>(l);
}

V3 randomDirection(Pcg32& rng) {
    return squareToUniformSphere(Vec2<double>(rng.nextDouble(), rng.nextDouble()));
}

TEST(LayeredInside, AnAllTransmittingLayerIsTheRoughDielectricFromBothSides) {
    for (double alpha : {0.1, 0.4}) {
        const auto layered = allTransmission(alpha, 1.5);
        const DielectricBxdf<S> glass(1.5,
                                      MicrofacetDistribution<double>(NdfKind::Ggx, alpha, alpha));
        Pcg32 rng(11);
        int inside = 0;
        for (int i = 0; i < 4000; ++i) {
            const V3 wo = randomDirection(rng), wi = randomDirection(rng);
            if (wo.z < 0 && wi.z < 0) ++inside;
            for (TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
                const S a = layered->eval(wo, wi, mode), b = glass.eval(wo, wi, mode);
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(a[c], b[c], 1e-9 * (1.0 + b[c]))
                        << "alpha " << alpha << " wo " << wo.x << " " << wo.y << " " << wo.z
                        << " wi " << wi.x << " " << wi.y << " " << wi.z;
            }
        }
        EXPECT_GT(inside, 500);
    }
}

// A smooth layer from inside: what it reflects and what it transmits add to 1 at every angle,
// past the critical angle too (sampled weights are exact for a smooth interface).
TEST(LayeredInside, ASmoothLayerFromInsideReflectsWhatItDoesNotTransmit) {
    const auto layered = allTransmission(0.0, 1.5);
    for (double cosTheta : {0.2, 0.5, 0.7, 0.745, 0.9, 1.0}) {
        const V3 wo(std::sqrt(1 - cosTheta * cosTheta), 0.0, -cosTheta);
        Pcg32 rng(3);
        const int n = 20000;
        double reflected = 0, transmitted = 0;
        for (int i = 0; i < n; ++i) {
            const auto s = layered->sample(wo, rng.nextDouble(),
                                           Vec2<double>(rng.nextDouble(), rng.nextDouble()),
                                           TransportMode::Importance);
            if (!s) continue;
            (s->wi.z < 0 ? reflected : transmitted) += s->weight.average() / n;
        }
        // Binomial lobe choice with exact weights: the sum's error is a few 1e-3 at most.
        EXPECT_NEAR(reflected + transmitted, 1.0, 0.01) << "cos theta " << cosTheta;
    }
}

}  // namespace
}  // namespace lamina
