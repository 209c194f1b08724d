#include "lamina/render/light_bounds.h"

#include <algorithm>
#include <limits>

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
    const Vec3f fromCenter = p - center();
    const float d2 = glm::dot(fromCenter, fromCenter);
    const float r2 = 0.25f * lengthSquared(upper - lower);  // the bounding sphere's radius^2
    // theta_u: the half-angle of the cone from p that holds the cluster's bounding sphere (pi
    // when p is inside it, so every angle below clamps to 0).
    float cosU = -1.0f, sinU = 0.0f;
    if (d2 > r2) {
        const float sin2U = r2 / d2;
        cosU = safeSqrt(1.0f - sin2U);
        sinU = std::sqrt(sin2U);
    }
    const Vec3f w = d2 > 0.0f ? fromCenter / std::sqrt(d2) : Vec3f(0.0f);

    // theta' = max(0, theta - theta_o - theta_u), theta the angle between the axis and the
    // direction towards p (Conty Estevez and Kulla 2018, eq. 3); beyond theta_e no light of
    // the cluster can leave towards p.
    float cosTheta = glm::dot(axis, w);
    if (twoSided) cosTheta = std::abs(cosTheta);
    const float cosO = cosThetaO, sinO = sinFromCos(cosThetaO);
    const float sinTheta = sinFromCos(cosTheta);
    const float cosX = cosOfClampedDifference(cosTheta, sinTheta, cosO, sinO);
    const float sinX = sinOfClampedDifference(cosTheta, sinTheta, cosO, sinO);
    const float cosThetaP = cosOfClampedDifference(cosX, sinX, cosU, sinU);
    if (cosThetaP <= cosThetaE) return 0.0f;

    // The distance is the centre's, but no less than half the bounding radius: near the
    // centre of a cluster its distance says little, and a point on a light would weigh
    // infinitely. (A bound of the whole radius, measured on scenes/many-lights.json, gives
    // 4x the variance: it makes every cluster around the point look equally far.)
    float value =
        intensity * cosThetaP / std::max({d2, 0.25f * r2, std::numeric_limits<float>::min()});
    if (n != Vec3f(0.0f)) {
        // The receiver's cosine, |cos| so that transmission is not culled, at the smallest
        // angle a direction into the bounding sphere can make with n.
        const float cosI = std::abs(glm::dot(n, w));
        value *= cosOfClampedDifference(cosI, sinFromCos(cosI), cosU, sinU);
    }
    if (!(value > 0.0f)) return 0.0f;
    return std::min(value, std::numeric_limits<float>::max());
}

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
