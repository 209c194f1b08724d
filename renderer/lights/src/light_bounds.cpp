#include "lamina/lights/light_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace lamina::render {

namespace {

// cos(max(0, a - b)) and sin(max(0, a - b)) for angles a, b in [0, pi] given by their cosines
// and sines, without an acos.
float cosOfClampedDifference(float cosA, float sinA, float cosB, float sinB) {
    if (cosA >= cosB) return 1.0f;
    return cosA * cosB + sinA * sinB;
}

float sinOfClampedDifference(float cosA, float sinA, float cosB, float sinB) {
    if (cosA >= cosB) return 0.0f;
    return sinA * cosB - cosA * sinB;
}

float sinFromCos(float c) {
    return safeSqrt(1.0f - c * c);
}

}  // namespace

float LightBounds::importance(const Vec3f& p, const Vec3f& n) const {
    return ImportanceBounds(*this).importance(p, n);
}

ImportanceBounds::ImportanceBounds(const LightBounds& b)
    : center(b.center()),
      radius2(0.25f * lengthSquared(b.upper - b.lower)),
      axis(b.axis),
      cosThetaO(b.cosThetaO),
      sinThetaO(sinFromCos(b.cosThetaO)),
      cosThetaE(b.cosThetaE),
      intensity(b.intensity),
      twoSided(b.twoSided) {}

float ImportanceBounds::importance(const Vec3f& p, const Vec3f& n) const {
    const Vec3f fromCenter = p - center;
    const float d2 = glm::dot(fromCenter, fromCenter);
    // theta_u: the half-angle of the cone from p that holds the cluster's bounding sphere (pi
    // when p is inside it, so every angle below clamps to 0).
    float cosU = -1.0f, sinU = 0.0f;
    if (d2 > radius2) {
        const float sin2U = radius2 / d2;
        cosU = safeSqrt(1.0f - sin2U);
        sinU = std::sqrt(sin2U);
    }
    const Vec3f w = d2 > 0.0f ? fromCenter / std::sqrt(d2) : Vec3f(0.0f);

    // theta' = max(0, theta - theta_o - theta_u), theta the angle between the axis and the
    // direction towards p (Conty Estevez and Kulla 2018, eq. 3); beyond theta_e no light of
    // the cluster can leave towards p.
    float cosTheta = glm::dot(axis, w);
    if (twoSided) cosTheta = std::abs(cosTheta);
    const float sinTheta = sinFromCos(cosTheta);
    const float cosX = cosOfClampedDifference(cosTheta, sinTheta, cosThetaO, sinThetaO);
    const float sinX = sinOfClampedDifference(cosTheta, sinTheta, cosThetaO, sinThetaO);
    const float cosThetaP = cosOfClampedDifference(cosX, sinX, cosU, sinU);
    if (cosThetaP <= cosThetaE) return 0.0f;

    // The distance is the centre's, but no less than half the bounding radius: near the
    // centre of a cluster its distance says little, and a point on a light would weigh
    // infinitely. (A bound of the whole radius, measured on scenes/many-lights.json, gives
    // 4x the variance: it makes every cluster around the point look equally far.)
    float value =
        intensity * cosThetaP / std::max({d2, 0.25f * radius2, std::numeric_limits<float>::min()});
    if (n != Vec3f(0.0f)) {
        // The receiver's cosine, |cos| so that transmission is not culled, at the smallest
        // angle a direction into the bounding sphere can make with n.
        const float cosI = std::abs(glm::dot(n, w));
        value *= cosOfClampedDifference(cosI, sinFromCos(cosI), cosU, sinU);
    }
    if (!(value > 0.0f)) return 0.0f;
    return std::min(value, std::numeric_limits<float>::max());
}

ImportancePair::ImportancePair(const ImportanceBounds& a, const ImportanceBounds& b) {
    for (std::size_t k = 0; k < 2; ++k) {
        const ImportanceBounds& c = k == 0 ? a : b;
        cx_[k] = c.center.x;
        cy_[k] = c.center.y;
        cz_[k] = c.center.z;
        radius2_[k] = c.radius2;
        ax_[k] = c.axis.x;
        ay_[k] = c.axis.y;
        az_[k] = c.axis.z;
        cosO_[k] = c.cosThetaO;
        sinO_[k] = c.sinThetaO;
        cosE_[k] = c.cosThetaE;
        intensity_[k] = c.intensity;
        twoSided_[k] = c.twoSided;
    }
}

ImportanceBounds ImportancePair::lane(std::size_t k) const {
    ImportanceBounds c;
    c.center = Vec3f(cx_[k], cy_[k], cz_[k]);
    c.radius2 = radius2_[k];
    c.axis = Vec3f(ax_[k], ay_[k], az_[k]);
    c.cosThetaO = cosO_[k];
    c.sinThetaO = sinO_[k];
    c.cosThetaE = cosE_[k];
    c.intensity = intensity_[k];
    c.twoSided = twoSided_[k];
    return c;
}

#if defined(__SSE2__)

namespace {

// ImportanceBounds::importance's operations on four lanes (two used; the other two hold
// zeros and are ignored). Every SSE arithmetic instruction rounds as its scalar form does,
// and the selections below reproduce the scalar comparisons exactly, NaN and signed zeros
// included: std::max(x, y) is (x < y) ? y : x, which is _mm_max_ps(y, x), and std::min(x, y)
// is (y < x) ? y : x, which is _mm_min_ps(y, x).
using Lanes = __m128;

Lanes load(const std::array<float, 2>& v) {
    return _mm_setr_ps(v[0], v[1], 0.0f, 0.0f);
}

Lanes all(float x) {
    return _mm_set1_ps(x);
}

/// mask ? a : b, lane by lane.
Lanes select(Lanes mask, Lanes a, Lanes b) {
    return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}

Lanes safeSqrtLanes(Lanes x) {
    return _mm_sqrt_ps(_mm_max_ps(_mm_setzero_ps(), x));
}

Lanes sinFromCosLanes(Lanes c) {
    return safeSqrtLanes(_mm_sub_ps(all(1.0f), _mm_mul_ps(c, c)));
}

Lanes absLanes(Lanes x) {
    return _mm_andnot_ps(all(-0.0f), x);
}

Lanes cosOfClampedDifferenceLanes(Lanes cosA, Lanes sinA, Lanes cosB, Lanes sinB) {
    return select(_mm_cmpge_ps(cosA, cosB), all(1.0f),
                  _mm_add_ps(_mm_mul_ps(cosA, cosB), _mm_mul_ps(sinA, sinB)));
}

Lanes sinOfClampedDifferenceLanes(Lanes cosA, Lanes sinA, Lanes cosB, Lanes sinB) {
    return select(_mm_cmpge_ps(cosA, cosB), _mm_setzero_ps(),
                  _mm_sub_ps(_mm_mul_ps(sinA, cosB), _mm_mul_ps(cosA, sinB)));
}

/// glm::dot of two vec3: (x + y) + z of the products.
Lanes dotLanes(Lanes ax, Lanes ay, Lanes az, Lanes bx, Lanes by, Lanes bz) {
    return _mm_add_ps(_mm_add_ps(_mm_mul_ps(ax, bx), _mm_mul_ps(ay, by)), _mm_mul_ps(az, bz));
}

}  // namespace

std::array<float, 2> ImportancePair::importances(const Vec3f& p, const Vec3f& n) const {
    const Lanes fx = _mm_sub_ps(all(p.x), load(cx_)), fy = _mm_sub_ps(all(p.y), load(cy_)),
                fz = _mm_sub_ps(all(p.z), load(cz_));
    const Lanes d2 = dotLanes(fx, fy, fz, fx, fy, fz);
    const Lanes radius2 = load(radius2_);

    const Lanes outside = _mm_cmpgt_ps(d2, radius2);
    const Lanes sin2U = _mm_div_ps(radius2, d2);
    const Lanes cosU = select(outside, safeSqrtLanes(_mm_sub_ps(all(1.0f), sin2U)), all(-1.0f));
    const Lanes sinU = select(outside, _mm_sqrt_ps(sin2U), _mm_setzero_ps());
    const Lanes apart = _mm_cmpgt_ps(d2, _mm_setzero_ps());
    const Lanes distance = _mm_sqrt_ps(d2);
    const Lanes wx = _mm_and_ps(apart, _mm_div_ps(fx, distance)),
                wy = _mm_and_ps(apart, _mm_div_ps(fy, distance)),
                wz = _mm_and_ps(apart, _mm_div_ps(fz, distance));

    Lanes cosTheta = dotLanes(load(ax_), load(ay_), load(az_), wx, wy, wz);
    const Lanes twoSided =
        _mm_castsi128_ps(_mm_setr_epi32(twoSided_[0] ? -1 : 0, twoSided_[1] ? -1 : 0, 0, 0));
    cosTheta = select(twoSided, absLanes(cosTheta), cosTheta);
    const Lanes sinTheta = sinFromCosLanes(cosTheta);
    const Lanes cosO = load(cosO_), sinO = load(sinO_);
    const Lanes cosX = cosOfClampedDifferenceLanes(cosTheta, sinTheta, cosO, sinO);
    const Lanes sinX = sinOfClampedDifferenceLanes(cosTheta, sinTheta, cosO, sinO);
    const Lanes cosThetaP = cosOfClampedDifferenceLanes(cosX, sinX, cosU, sinU);
    const Lanes reached = _mm_cmpnle_ps(cosThetaP, load(cosE_));  // !(cosThetaP <= cosThetaE)

    const Lanes nearest = _mm_max_ps(all(std::numeric_limits<float>::min()),
                                     _mm_max_ps(_mm_mul_ps(all(0.25f), radius2), d2));
    Lanes value = _mm_div_ps(_mm_mul_ps(load(intensity_), cosThetaP), nearest);
    if (n != Vec3f(0.0f)) {
        const Lanes cosI = absLanes(dotLanes(all(n.x), all(n.y), all(n.z), wx, wy, wz));
        value =
            _mm_mul_ps(value, cosOfClampedDifferenceLanes(cosI, sinFromCosLanes(cosI), cosU, sinU));
    }
    const Lanes positive = _mm_and_ps(reached, _mm_cmpgt_ps(value, _mm_setzero_ps()));
    const Lanes result =
        _mm_and_ps(positive, _mm_min_ps(all(std::numeric_limits<float>::max()), value));
    alignas(16) float out[4];
    _mm_store_ps(out, result);
    return {out[0], out[1]};
}

#else

std::array<float, 2> ImportancePair::importances(const Vec3f& p, const Vec3f& n) const {
    return {lane(0).importance(p, n), lane(1).importance(p, n)};
}

#endif

LightBounds unite(const LightBounds& a, const LightBounds& b) {
    LightBounds u;
    u.lower = glm::min(a.lower, b.lower);
    u.upper = glm::max(a.upper, b.upper);
    u.intensity = a.intensity + b.intensity;
    u.cosThetaE = std::min(a.cosThetaE, b.cosThetaE);
    u.twoSided = a.twoSided || b.twoSided;

    // The cone of normals (Conty Estevez and Kulla 2018, Algorithm 1): the wider cone if it
    // holds the other, else the cone whose edges touch both, rotated from the wider's axis.
    const LightBounds& wide = a.cosThetaO <= b.cosThetaO ? a : b;
    const LightBounds& narrow = a.cosThetaO <= b.cosThetaO ? b : a;
    const float thetaW = safeAcos(wide.cosThetaO), thetaN = safeAcos(narrow.cosThetaO);
    const float thetaD = safeAcos(glm::dot(wide.axis, narrow.axis));
    u.axis = wide.axis;
    if (std::min(thetaD + thetaN, kPi<float>) <= thetaW) {
        u.cosThetaO = wide.cosThetaO;
        return u;
    }
    const float thetaO = 0.5f * (thetaW + thetaD + thetaN);
    const Vec3f across = narrow.axis - glm::dot(narrow.axis, wide.axis) * wide.axis;
    const float acrossLength = glm::length(across);
    if (thetaO >= kPi<float> || !(acrossLength > 1e-6f)) {
        u.cosThetaO = -1.0f;
        return u;
    }
    const float thetaR = thetaO - thetaW;
    u.axis =
        glm::normalize(std::cos(thetaR) * wide.axis + std::sin(thetaR) * (across / acrossLength));
    u.cosThetaO = std::cos(thetaO);
    return u;
}

float orientationMeasure(const LightBounds& b) {
    const float thetaO = safeAcos(b.cosThetaO);
    const float thetaW = std::min(thetaO + safeAcos(b.cosThetaE), kPi<float>);
    const float sinO = std::sin(thetaO);
    return 2.0f * kPi<float> * (1.0f - b.cosThetaO) +
           0.5f * kPi<float> *
               (2.0f * thetaW * sinO - std::cos(thetaO - 2.0f * thetaW) - 2.0f * thetaO * sinO +
                b.cosThetaO);
}

}  // namespace lamina::render
