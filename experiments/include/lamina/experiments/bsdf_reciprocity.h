// The BSDF-level half of the reciprocity experiment: on random pairs of directions,
//  - Helmholtz reciprocity of reflection, f(wo, wi) = f(wi, wo) (radiance mode), which a
//    physically based BRDF satisfies and some practical couplings do not;
//  - the adjoint identity f_importance(wo, wi) = f_radiance(wi, wo) for every pair (reflection
//    and transmission), which light tracing relies on: if it holds, light tracing converges to
//    the camera-traced image even for a non-reciprocal BSDF (Veach 1997, section 3.7).
// Errors are relative, |a - b| / max(|a|, |b|), over pairs where either value exceeds 1e-6.
#pragma once

#include <algorithm>
#include <cmath>

#include "lamina/bsdf/bxdf.h"
#include "lamina/core/pcg32.h"
#include "lamina/core/warp.h"

namespace lamina::experiments {

struct BsdfReciprocity {
    int reflectionPairs = 0, pairs = 0;
    double maxReciprocityError = 0;  ///< reflection, radiance mode
    double maxAdjointError = 0;      ///< all pairs
};

template <SpectrumType S>
BsdfReciprocity checkBsdfReciprocity(const Bxdf<S>& bsdf, int pairs, std::uint64_t seed) {
    using Float = typename S::Float;
    using V3 = Vec3<Float>;
    Pcg32 rng(seed, 0x726563u);
    const auto relative = [](const S& a, const S& b) {
        double worst = 0;
        for (int i = 0; i < S::kSize; ++i) {
            const double x = double(a[i]), y = double(b[i]);
            const double scale = std::max(std::abs(x), std::abs(y));
            if (scale > 1e-6) worst = std::max(worst, std::abs(x - y) / scale);
        }
        return worst;
    };
    BsdfReciprocity r;
    for (int k = 0; k < pairs; ++k) {
        const V3 wo(
            squareToUniformSphere(Vec2<Float>(Float(rng.nextDouble()), Float(rng.nextDouble()))));
        const V3 wi(
            squareToUniformSphere(Vec2<Float>(Float(rng.nextDouble()), Float(rng.nextDouble()))));
        if (std::abs(wo.z) < Float(1e-3) || std::abs(wi.z) < Float(1e-3)) continue;
        // f without the built-in cosine of its second argument.
        const S fRad = bsdf.eval(wo, wi, TransportMode::Radiance) / std::abs(wi.z);
        const S fRadSwapped = bsdf.eval(wi, wo, TransportMode::Radiance) / std::abs(wo.z);
        const S fImp = bsdf.eval(wo, wi, TransportMode::Importance) / std::abs(wi.z);
        ++r.pairs;
        r.maxAdjointError = std::max(r.maxAdjointError, relative(fImp, fRadSwapped));
        if (wo.z * wi.z > 0) {
            ++r.reflectionPairs;
            r.maxReciprocityError = std::max(r.maxReciprocityError, relative(fRad, fRadSwapped));
        }
    }
    return r;
}

}  // namespace lamina::experiments
