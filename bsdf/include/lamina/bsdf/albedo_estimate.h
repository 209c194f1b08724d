// The directional albedo of a BSDF by Monte Carlo (`lamina bsdf albedo`, lamina.Material.albedo):
// the mean sample weight for wo at cos theta_o, split by the side wi leaves on (reflection
// z > 0, transmission z < 0), with the standard error of the total per channel. The estimate
// is unbiased because weight = eval / pdf (docs/bsdf.md, "Interface"); absorbed samples
// count as zero.
#pragma once

#include <cmath>
#include <cstdint>

#include "lamina/bsdf/bxdf.h"
#include "lamina/core/math.h"
#include "lamina/core/pcg32.h"

namespace lamina {

template <SpectrumType S>
struct AlbedoEstimate {
    S reflection{0.0}, transmission{0.0};
    S standardError{0.0};  ///< of reflection + transmission
};

/// wo = (sin theta_o, 0, cos theta_o); the random numbers come from Pcg32(seed), three per
/// sample in this order: the lobe choice, then the direction's u.x and u.y.
template <SpectrumType S>
AlbedoEstimate<S> estimateAlbedo(const Bxdf<S>& bxdf, double cosThetaO, std::size_t samples,
                                 std::uint64_t seed, TransportMode mode) {
    using Float = typename S::Float;
    const double c = cosThetaO;
    const Vec3<Float> wo(Float(std::sqrt(std::max(0.0, 1 - c * c))), Float(0), Float(c));
    Pcg32 rng(seed);
    S reflection(0.0), transmission(0.0), sumSq(0.0);
    for (std::size_t n = 0; n < samples; ++n) {
        const Float uc = rng.next<Float>();
        const Float u1 = rng.next<Float>();
        const Vec2<Float> u(u1, rng.next<Float>());
        const auto s = bxdf.sample(wo, uc, u, mode);
        if (!s) continue;
        (s->wi.z > 0 ? reflection : transmission) += s->weight;
        sumSq += s->weight * s->weight;
    }
    const double count = double(samples);
    AlbedoEstimate<S> e;
    e.reflection = reflection / count;
    e.transmission = transmission / count;
    const S mean = (reflection + transmission) / count;
    for (int k = 0; k < S::kSize; ++k)
        e.standardError[k] = Float(
            std::sqrt(std::max(0.0, double(sumSq[k]) / count - sqr(double(mean[k]))) / count));
    return e;
}

}  // namespace lamina
