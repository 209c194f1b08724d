// Microfacet normal distributions with their Smith masking functions and sampling strategies
// (the article, section 4). Directions are in the local frame; alpha is the NDF's roughness
// (alpha = roughness^2 in the `standard` material). Anisotropic alpha_x / alpha_y follow the
// tangent frame's x and y axes.
//
//   D(m)      GGX / Trowbridge-Reitz (Walter et al. 2007, eq. 33; anisotropic: Heitz 2014,
//             "Understanding the Masking-Shadowing Function", eq. 85), Beckmann (Walter eq. 25;
//             Heitz eq. 80), Blinn-Phong (Walter eq. 30, exponent e = 2 / alpha^2 - 2).
//   Lambda(w) Smith: GGX closed form (Heitz eq. 86), Beckmann exact with erf (Heitz eq. 83) or
//             Walter's rational approximation (Walter eq. 27); Blinn-Phong uses Beckmann's
//             at the same alpha (Walter's suggestion in section 5.2).
//   G1 = 1 / (1 + Lambda);  G2 height-correlated 1 / (1 + Lambda_o + Lambda_i) (Heitz eq. 99)
//   or separable G1(o) G1(i).
//   Sampling  one sample / pdf pair per strategy (MicrofacetSampling), the distribution holding
//             the one it is sampled by:
//             vndf    visible normals D_w(m) = G1(w) max(0, w.m) D(m) / w.z (Heitz 2014
//                     eq. 16): GGX by Heitz 2018 (JCGT 7(4)); Beckmann by inverting the
//                     visible-slope marginal numerically (the slope method of Heitz and d'Eon
//                     2014);
//             caps    the same density for GGX by the spherical caps of Dupuy and Benyoub 2023
//                     (CGF 42(8));
//             walter  the NDF itself, D(m) cos(m) (Walter 2007 eqs. 28-29, 35-36);
//             walter_widened  the NDF with Walter's widened alpha
//                     (1.2 - 0.2 sqrt|cos theta_o|) alpha (section 5.3).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "lamina/core/frame.h"
#include "lamina/core/name_table.h"
#include "lamina/core/special_functions.h"

namespace lamina {

enum class NdfKind { Ggx, Beckmann, BlinnPhong };
inline constexpr NameTable kNdfKindNames{std::array{NameEntry{NdfKind::Ggx, "ggx"},
                                                    NameEntry{NdfKind::Beckmann, "beckmann"},
                                                    NameEntry{NdfKind::BlinnPhong, "blinn_phong"}}};

enum class SmithLambda { Exact, WalterApproximation };

enum class G2Form { HeightCorrelated, Separable };
inline constexpr NameTable kG2FormNames{
    std::array{NameEntry{G2Form::HeightCorrelated, "height_correlated"},
               NameEntry{G2Form::Separable, "separable"}}};

enum class MicrofacetSampling { VisibleNormals, SphericalCaps, Walter, WalterWidened };
inline constexpr NameTable kMicrofacetSamplingNames{
    std::array{NameEntry{MicrofacetSampling::VisibleNormals, "vndf"},
               NameEntry{MicrofacetSampling::SphericalCaps, "caps"},
               NameEntry{MicrofacetSampling::Walter, "walter"},
               NameEntry{MicrofacetSampling::WalterWidened, "walter_widened"}}};

/// Below this alpha a surface is treated as smooth (a delta lobe), as pbrt-v4 does; float and
/// double agree on it because it is compared before any other arithmetic.
inline constexpr double kSmoothAlpha = 1e-3;

template <std::floating_point T>
class MicrofacetDistribution {
  public:
    using V3 = Vec3<T>;
    using V2 = Vec2<T>;

    MicrofacetDistribution(NdfKind kind, T alphaX, T alphaY,
                           SmithLambda lambda = SmithLambda::Exact)
        : kind_(kind), ax_(alphaX), ay_(alphaY), lambdaForm_(lambda) {
        if (!effectivelySmooth()) {
            // Smooth along one tangent axis and rough along the other (alpha_x 0, alpha_y 1):
            // D, Lambda and the samplers divide by each alpha, so the smooth axis takes the
            // narrowest lobe that is still rough, kSmoothAlpha (pbrt-v4 does the same with
            // 1e-4). The lobe is then a thin ridge whose eval, pdf and samples stay finite.
            ax_ = std::max(ax_, T(kSmoothAlpha));
            ay_ = std::max(ay_, T(kSmoothAlpha));
        }
        if (kind_ == NdfKind::BlinnPhong) {  // isotropic: the mean alpha sets the exponent
            const T a = std::clamp(T(0.5) * (ax_ + ay_), T(kSmoothAlpha), T(1));
            ax_ = ay_ = a;
            exponent_ = T(2) / (a * a) - T(2);
        }
    }

    NdfKind kind() const { return kind_; }
    T alphaX() const { return ax_; }
    T alphaY() const { return ay_; }
    bool effectivelySmooth() const { return std::max(ax_, ay_) < T(kSmoothAlpha); }

    /// The same distribution sampled by `strategy`. Blinn-Phong has no visible-normal sampler:
    /// the visible-normal strategies sample it by its NDF (Walter's) instead.
    MicrofacetDistribution sampledBy(MicrofacetSampling strategy) const {
        MicrofacetDistribution d = *this;
        const bool visible = strategy == MicrofacetSampling::VisibleNormals ||
                             strategy == MicrofacetSampling::SphericalCaps;
        d.sampling_ =
            kind_ == NdfKind::BlinnPhong && visible ? MicrofacetSampling::Walter : strategy;
        return d;
    }
    MicrofacetSampling sampling() const { return sampling_; }

    /// Microfacet normal density per unit solid angle (projected: integral of D cos = 1).
    T D(const V3& m) const {
        if (!(m.z > T(0))) return T(0);
        switch (kind_) {
            case NdfKind::Ggx: {
                const T e = sqr(m.x / ax_) + sqr(m.y / ay_) + sqr(m.z);
                return T(1) / (kPi<T> * ax_ * ay_ * sqr(e));
            }
            case NdfKind::Beckmann: {
                const T cos2 = sqr(m.z);
                const T tan2 = (sqr(m.x / ax_) + sqr(m.y / ay_)) / cos2;
                return std::exp(-tan2) / (kPi<T> * ax_ * ay_ * sqr(cos2));
            }
            case NdfKind::BlinnPhong:
                return (exponent_ + T(2)) * kInv2Pi<T> * std::pow(m.z, exponent_);
        }
        return T(0);
    }

    /// Smith's Lambda(w); symmetric in the sign of w.z.
    T lambda(const V3& w) const {
        const T cos2 = sqr(w.z);
        const T a2sin2 = sqr(ax_ * w.x) + sqr(ay_ * w.y);  // alpha_0^2 sin^2 theta
        if (a2sin2 == T(0)) return T(0);
        if (cos2 == T(0)) return std::numeric_limits<T>::infinity();
        if (kind_ == NdfKind::Ggx) {
            const T x = a2sin2 / cos2;                         // alpha_0^2 tan^2 theta
            return x / (T(2) * (std::sqrt(T(1) + x) + T(1)));  // (sqrt(1 + x) - 1) / 2, stable
        }
        const T a = std::abs(w.z) / std::sqrt(a2sin2);  // 1 / (alpha_0 tan theta)
        if (lambdaForm_ == SmithLambda::WalterApproximation) {
            if (a >= T(1.6)) return T(0);
            return (T(1) - T(1.259) * a + T(0.396) * a * a) / (T(3.535) * a + T(2.181) * a * a);
        }
        return T(0.5) * (std::exp(-a * a) / (a * std::sqrt(kPi<T>)) - std::erfc(a));
    }

    T G1(const V3& w) const { return T(1) / (T(1) + lambda(w)); }

    T G2(const V3& wo, const V3& wi, G2Form form = G2Form::HeightCorrelated) const {
        if (form == G2Form::Separable) return G1(wo) * G1(wi);
        return T(1) / (T(1) + lambda(wo) + lambda(wi));
    }

    /// A microfacet normal for w (w.z > 0) drawn by this distribution's strategy.
    V3 sampleNormal(const V3& w, const V2& u) const {
        switch (sampling_) {
            case MicrofacetSampling::VisibleNormals:
                return sampleVisibleNormal(w, u);
            case MicrofacetSampling::SphericalCaps:
                return sampleSphericalCaps(w, u);
            case MicrofacetSampling::Walter:
                return sampleWalter(u);
            case MicrofacetSampling::WalterWidened:
                return sampleWalterWidened(w, u);
        }
        return V3(0, 0, 1);
    }

    /// Density of sampleNormal(w, .) at m.
    T normalPdf(const V3& w, const V3& m) const {
        switch (sampling_) {
            case MicrofacetSampling::VisibleNormals:
                return visibleNormalPdf(w, m);
            case MicrofacetSampling::SphericalCaps:
                return sphericalCapsPdf(w, m);
            case MicrofacetSampling::Walter:
                return walterPdf(m);
            case MicrofacetSampling::WalterWidened:
                return walterWidenedPdf(w, m);
        }
        return T(0);
    }

    /// The reflection lobe's sample weight without F, D G2 / (4 cos_o pdf), for wi = wo
    /// reflected about m = sampleNormal(wo, .), in closed form where the strategy's density
    /// cancels D; nullopt where nothing cancels (walter_widened: its alpha is not the NDF's)
    /// and the lobe divides eval by the pdf.
    std::optional<T> reflectionWeight(const V3& wo, const V3& wi, const V3& m, G2Form g2) const {
        switch (sampling_) {
            case MicrofacetSampling::VisibleNormals:
            case MicrofacetSampling::SphericalCaps:
                // D and G1(wo) cancel: weight = G2 / G1(wo) (Heitz 2018, eq. 19).
                return G2(wo, wi, g2) / G1(wo);
            case MicrofacetSampling::Walter:
                // D cancels: weight = G2 (wo.m) / (cos_o cos_m) (Walter 2007, eq. 41).
                return G2(wo, wi, g2) * glm::dot(wo, m) / (wo.z * m.z);
            case MicrofacetSampling::WalterWidened:
                return std::nullopt;
        }
        return std::nullopt;
    }

    // The strategies, one sample / pdf pair each.

    /// vndf: a visible normal for w (w.z > 0); Blinn-Phong, which has no visible-normal
    /// sampler, falls back to its NDF (sampledBy() never pairs it with this density).
    V3 sampleVisibleNormal(const V3& w, const V2& u) const {
        if (kind_ == NdfKind::Ggx) return sampleGgxVisible(w, u);
        if (kind_ == NdfKind::Beckmann) return sampleBeckmannVisible(w, u);
        return sampleWalter(u);
    }
    /// Density of visible normals seen from w (w.z > 0): G1(w) max(0, w.m) D(m) / w.z.
    T visibleNormalPdf(const V3& w, const V3& m) const {
        if (!(w.z > T(0))) return T(0);
        return G1(w) / w.z * D(m) * std::max(T(0), glm::dot(w, m));
    }

    /// caps: the visible normals of GGX by spherical caps (other NDFs: their vndf sampler).
    V3 sampleSphericalCaps(const V3& w, const V2& u) const {
        return kind_ == NdfKind::Ggx ? sampleGgxCaps(w, u) : sampleVisibleNormal(w, u);
    }
    T sphericalCapsPdf(const V3& w, const V3& m) const { return visibleNormalPdf(w, m); }

    /// walter: a normal distributed as D(m) cos(theta_m) (Walter 2007).
    V3 sampleWalter(const V2& u) const {
        const T phi = T(2) * kPi<T> * u.y;
        if (kind_ == NdfKind::BlinnPhong) {
            const T cosTheta = std::pow(u.x, T(1) / (exponent_ + T(2)));
            return sphericalDirection(safeSqrt(T(1) - cosTheta * cosTheta), cosTheta, phi);
        }
        // Sample the slope of the unit-roughness distribution, then stretch it by alpha.
        const T r =
            kind_ == NdfKind::Ggx ? std::sqrt(u.x / (T(1) - u.x)) : std::sqrt(-std::log1p(-u.x));
        const T sx = r * std::cos(phi) * ax_, sy = r * std::sin(phi) * ay_;
        if (!std::isfinite(sx) || !std::isfinite(sy))
            return safeNormalize(V3(-std::cos(phi), -std::sin(phi), T(0)));
        return glm::normalize(V3(-sx, -sy, T(1)));
    }
    T walterPdf(const V3& m) const { return D(m) * std::max(T(0), m.z); }

    /// walter_widened: Walter's NDF sampling with alpha widened for w.
    V3 sampleWalterWidened(const V3& w, const V2& u) const { return widened(w).sampleWalter(u); }
    T walterWidenedPdf(const V3& w, const V3& m) const { return widened(w).walterPdf(m); }

  private:
    // Walter 2007, section 5.3: the sampling lobe widened by (1.2 - 0.2 sqrt|cos theta_o|).
    MicrofacetDistribution widened(const V3& w) const {
        const T s = T(1.2) - T(0.2) * std::sqrt(std::abs(w.z));
        return MicrofacetDistribution(kind_, ax_ * s, ay_ * s, lambdaForm_);
    }

    // Heitz 2018, "Sampling the GGX Distribution of Visible Normals", listing 1.
    V3 sampleGgxVisible(const V3& w, const V2& u) const {
        const V3 wh = glm::normalize(V3(ax_ * w.x, ay_ * w.y, w.z));  // hemisphere config.
        const T lensq = wh.x * wh.x + wh.y * wh.y;
        const V3 t1 = lensq > T(0) ? V3(-wh.y, wh.x, T(0)) / std::sqrt(lensq) : V3(1, 0, 0);
        const V3 t2 = glm::cross(wh, t1);
        const T r = std::sqrt(u.x), phi = T(2) * kPi<T> * u.y;
        const T p1 = r * std::cos(phi);
        const T s = T(0.5) * (T(1) + wh.z);
        const T p2 = (T(1) - s) * safeSqrt(T(1) - p1 * p1) + s * r * std::sin(phi);
        const V3 nh = p1 * t1 + p2 * t2 + safeSqrt(T(1) - p1 * p1 - p2 * p2) * wh;
        return unstretch(nh);
    }

    // Dupuy and Benyoub 2023, "Sampling Visible GGX Normals with Spherical Caps", listing 3:
    // a uniform point on the spherical cap z > -wh.z, offset by wh, is a visible normal.
    V3 sampleGgxCaps(const V3& w, const V2& u) const {
        const V3 wh = glm::normalize(V3(ax_ * w.x, ay_ * w.y, w.z));
        const T phi = T(2) * kPi<T> * u.x;
        const T z = (T(1) - u.y) * (T(1) + wh.z) - wh.z;
        const T sinTheta = safeSqrt(T(1) - z * z);
        return unstretch(V3(sinTheta * std::cos(phi), sinTheta * std::sin(phi), z) + wh);
    }

    V3 unstretch(const V3& nh) const {
        const V3 m = safeNormalize(V3(ax_ * nh.x, ay_ * nh.y, std::max(T(0), nh.z)));
        return m == V3(T(0)) ? V3(0, 0, 1) : m;
    }

    // Beckmann visible normals through slopes (Heitz and d'Eon 2014, section 4): in the
    // stretched configuration (alpha = 1) with w rotated into the xz-plane at polar angle
    // theta, the visible slope density factorises into
    //   p(x) ~ exp(-x^2) (1 - x tan(theta)), x < cot(theta)   and   y ~ N(0, 1/2).
    // x is drawn by inverting its CDF, C(x) ~ sqrt(pi)/2 (1 + erf x) + tan(theta)/2 exp(-x^2),
    // with safeguarded Newton iterations in double precision; y = erfinv(2u - 1).
    V3 sampleBeckmannVisible(const V3& w, const V2& u) const {
        const Vec3<double> ws =
            glm::normalize(Vec3<double>(double(ax_) * w.x, double(ay_) * w.y, double(w.z)));
        const double sinTheta = std::sqrt(std::max(0.0, 1.0 - ws.z * ws.z));
        const double tanTheta = sinTheta / ws.z;
        const double ux = std::clamp(double(u.x), 1e-12, 1.0 - 1e-12);
        const double uy = std::clamp(double(u.y), 1e-12, 1.0 - 1e-12);
        double x;
        if (tanTheta < 1e-8) {
            x = erfInv(2.0 * ux - 1.0);
        } else {
            const double sqrtPiHalf = 0.5 * std::sqrt(kPi<double>);
            auto cdf = [&](double v) {
                return sqrtPiHalf * (1.0 + std::erf(v)) + 0.5 * tanTheta * std::exp(-v * v);
            };
            double lo = -8.0, hi = std::min(8.0, 1.0 / tanTheta);
            const double target = ux * cdf(hi);
            x = std::clamp(erfInv(2.0 * ux - 1.0), lo, hi);
            for (int i = 0; i < 64; ++i) {
                const double f = cdf(x) - target;
                if (std::abs(f) < 1e-13) break;
                (f > 0.0 ? hi : lo) = x;
                const double density = std::exp(-x * x) * (1.0 - x * tanTheta);
                double next = density > 0.0 ? x - f / density : 0.5 * (lo + hi);
                if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
                x = next;
            }
        }
        const double y = erfInv(2.0 * uy - 1.0);
        // Rotate the slopes back from w's azimuth and unstretch them.
        const double phiLen = std::hypot(ws.x, ws.y);
        const double cosPhi = phiLen > 0.0 ? ws.x / phiLen : 1.0;
        const double sinPhi = phiLen > 0.0 ? ws.y / phiLen : 0.0;
        const double sx = (cosPhi * x - sinPhi * y) * ax_;
        const double sy = (sinPhi * x + cosPhi * y) * ay_;
        const Vec3<double> m = glm::normalize(Vec3<double>(-sx, -sy, 1.0));
        return V3(T(m.x), T(m.y), T(m.z));
    }

    NdfKind kind_;
    T ax_, ay_;
    SmithLambda lambdaForm_;
    T exponent_ = 0;
    MicrofacetSampling sampling_ = MicrofacetSampling::VisibleNormals;
};

}  // namespace lamina
