#include "lamina/render/light_bounds.h"

namespace lamina::render {

float LightBounds::importance(const Vec3f& p, const Vec3f& n) const {
    return ImportanceBounds(*this).importance(p, n);
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
