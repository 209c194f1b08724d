#include "lamina/integrators/medium_transport.h"

#include <cmath>
#include <limits>

#include "lamina/geometry/ray_offset.h"
#include "lamina/integrators/visibility.h"

namespace lamina::render {

float freeFlightDistance(float sigma, float u) {
    if (!(sigma > 0.0f)) return std::numeric_limits<float>::infinity();
    return -std::log1p(-std::min(u, 1.0f - 0x1p-24f)) / sigma;
}

template <SpectrumType S>
S transmittance(const S& sigmaT, float d) {
    S T(1.0f);
    for (int i = 0; i < S::kSize; ++i)
        if (sigmaT[i] > 0.0f) T[i] = std::isinf(d) ? 0.0f : std::exp(-sigmaT[i] * d);
    return T;
}

template <SpectrumType S>
std::optional<S> shadowTransmittance(const Geometry& geometry, const RenderMode<S>& mode,
                                     typename RenderMode<S>::Path& path, Vec3f from,
                                     const Vec3f& direction, float distance, int medium,
                                     PathStatistics& stats) {
    S result(1.0f);
    const bool toInfinity = std::isinf(distance);
    const Vec3f to = toInfinity ? Vec3f(0.0f) : from + direction * distance;
    float remaining = distance;
    for (;;) {
        ++stats.rays;
        const auto hit = geometry.intersect(from, direction, remaining);
        if (medium >= 0) {
            result *= transmittance(mode.medium(medium, path).sigmaT(), hit ? hit->t : remaining);
            if (!(result.maxValue() > 0.0f)) return std::nullopt;
        }
        if (!hit) return result;
        const ShapeInfo& shape = geometry.shapes()[std::size_t(hit->shape)];
        if (!surface(*shape.desc).isInterface()) return std::nullopt;
        medium = mediumAfter(shape, medium, hit->ng, direction, direction);
        from = offsetRayOrigin(hit->p, facing(hit->ng, direction), geometry.rayOffsetScale());
        if (!toInfinity) {
            // Measured again from the new origin (the far end was already moved short of the
            // light, as segmentUnoccluded moves it).
            remaining = glm::dot(to - from, direction);
            if (!(remaining > 0.0f)) return result;
        }
    }
}

#define LAMINA_MEDIUM_TRANSPORT(S)                                                       \
    template S transmittance(const S&, float);                                           \
    template std::optional<S> shadowTransmittance(const Geometry&, const RenderMode<S>&, \
                                                  typename RenderMode<S>::Path&, Vec3f,  \
                                                  const Vec3f&, float, int, PathStatistics&);
LAMINA_MEDIUM_TRANSPORT(Rgb<float>)
LAMINA_MEDIUM_TRANSPORT(SampledSpectrum<float>)
#undef LAMINA_MEDIUM_TRANSPORT

}  // namespace lamina::render
