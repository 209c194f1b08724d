// Multiple-scattering compensation for a microfacet reflection lobe (Kulla and Conty 2017,
// "Revisiting Physically Based Shading at Imageworks", slides 16-19): the energy the
// single-scattering lobe loses, 1 - E(mu), is returned by an extra lobe
//   f_ms(wo, wi) = F_ms (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)),
//   F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)),
// where E is the single-scattering albedo with F = 1 and F_avg = 2 integral F(mu) mu dmu is
// the hemispherical average of the Fresnel model. With F = 1 the sum's albedo is exactly 1;
// with colour, F_ms tints the returned energy by repeated Fresnel reflections. The lobe is
// reciprocal and is sampled by the cosine hemisphere.
#pragma once

#include <memory>

#include "lamina/bsdf/albedo_table.h"
#include "lamina/bsdf/fresnel.h"
#include "lamina/core/warp.h"

namespace lamina {

template <SpectrumType S>
class MultiscatterLobe {
  public:
    using Float = typename S::Float;
    using V3 = Vec3<Float>;

    MultiscatterLobe(std::shared_ptr<const AlbedoTable> energyF1, const Fresnel<S>& fresnel)
        : table_(std::move(energyF1)) {
        // F_avg by 8-point Gauss-Legendre quadrature of 2 F(mu) mu on [0, 1] (the integrand
        // is a polynomial of degree 6 for Schlick, smooth for the exact models).
        static constexpr double x[8] = {0.0198550717512319, 0.1016667612931866, 0.2372337950418355,
                                        0.4082826787521751, 0.5917173212478249, 0.7627662049581645,
                                        0.8983332387068134, 0.9801449282487681};
        static constexpr double w[8] = {0.0506142681451881, 0.1111905172266872, 0.1568533229389436,
                                        0.1813418916891810, 0.1813418916891810, 0.1568533229389436,
                                        0.1111905172266872, 0.0506142681451881};
        S favg(Float(0));
        for (int k = 0; k < 8; ++k)
            favg += fresnel.evaluate(Float(x[k])) * Float(2 * w[k] * x[k]);
        const Float eavg = Float(table_->average());
        fms_ = favg * favg * eavg / (S(Float(1)) - favg * (Float(1) - eavg));
        norm_ = Float(1) / (kPi<Float> * std::max(Float(1e-6), Float(1) - eavg));
    }

    /// f_ms |cos theta_i| for wo, wi in the upper hemisphere.
    S eval(const V3& wo, const V3& wi) const {
        if (!(wo.z > Float(0)) || !(wi.z > Float(0))) return S(Float(0));
        return fms_ * ((Float(1) - (*table_)(wo.z)) * (Float(1) - (*table_)(wi.z)) * norm_ * wi.z);
    }

    /// Its directional albedo at mu_o: F_ms (1 - E(mu_o)).
    S albedo(Float muO) const { return fms_ * (Float(1) - (*table_)(muO)); }

    const AlbedoTable& table() const { return *table_; }

  private:
    std::shared_ptr<const AlbedoTable> table_;
    S fms_{};
    Float norm_ = 0;
};

}  // namespace lamina
