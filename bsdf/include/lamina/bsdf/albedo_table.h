// Directional albedo E(mu) = integral of f(wo, wi) |cos theta_i| over wi for wo at
// cos theta_o = mu, tabulated on 33 nodes in mu and interpolated linearly, with its cosine-
// weighted average E_avg = 2 integral_0^1 E(mu) mu dmu. Kulla and Conty 2017 ("Revisiting
// Physically Based Shading at Imageworks") build energy compensation from these two numbers.
// lamina computes each table from the same BSDF code it compensates, by a deterministic
// stratified estimate of the mean sample weight (64 x 64 strata per node).
#pragma once

#include <array>
#include <functional>
#include <optional>

#include "lamina/core/vector.h"

namespace lamina {

class AlbedoTable {
  public:
    static constexpr int kNodes = 33;

    /// `weight(wo, u1, u2, uc)` returns the sample weight (averaged over channels) of the
    /// BSDF for one sample, or 0 when the sample is absorbed.
    static AlbedoTable compute(
        const std::function<double(const Vec3<double>&, double, double, double)>& weight) {
        AlbedoTable t;
        constexpr int strata = 64;
        for (int k = 0; k < kNodes; ++k) {
            const double mu = std::max(1e-3, double(k) / (kNodes - 1));
            const Vec3<double> wo(std::sqrt(1 - mu * mu), 0.0, mu);
            double sum = 0;
            for (int i = 0; i < strata; ++i)
                for (int j = 0; j < strata; ++j) {
                    // A different lobe-choice number per stratum, decorrelated from (i, j).
                    const double uc = std::fmod((i * strata + j) * 0.6180339887498949, 1.0);
                    sum += weight(wo, (i + 0.5) / strata, (j + 0.5) / strata, uc);
                }
            t.e_[std::size_t(k)] = std::clamp(sum / (strata * strata), 0.0, 1.0);
        }
        // E_avg = 2 integral E(mu) mu dmu (trapezoid rule on the nodes).
        double avg = 0;
        for (int k = 0; k + 1 < kNodes; ++k) {
            const double m0 = double(k) / (kNodes - 1), m1 = double(k + 1) / (kNodes - 1);
            avg += (m1 - m0) * (t.e_[std::size_t(k)] * m0 + t.e_[std::size_t(k) + 1] * m1);
        }
        t.average_ = std::clamp(avg, 0.0, 1.0);
        return t;
    }

    template <typename T>
    T operator()(T mu) const {
        const double x = std::clamp(double(std::abs(mu)), 0.0, 1.0) * (kNodes - 1);
        const int i = std::min(int(x), kNodes - 2);
        const double f = x - i;
        return T((1 - f) * e_[std::size_t(i)] + f * e_[std::size_t(i) + 1]);
    }
    double average() const { return average_; }

  private:
    std::array<double, kNodes> e_{};
    double average_ = 0;
};

}  // namespace lamina
