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
std::optional<Transmittance<S>> shadowTransmittance(const Geometry& geometry,
                                                    const RenderMode<S>& mode,
                                                    typename RenderMode<S>::Path& path, Vec3f from,
                                                    const Vec3f& direction, float distance,
                                                    int medium, int hero, PathStatistics& stats) {
    Transmittance<S> result;
    const bool toInfinity = std::isinf(distance);
    const Vec3f to = toInfinity ? Vec3f(0.0f) : from + direction * distance;
    float remaining = distance;
    for (;;) {
        ++stats.rays;
        const auto hit = geometry.intersect(from, direction, remaining);
        if (medium >= 0) {
            const MediumCoefficients<S> m = mode.medium(medium, path);
            const float length = hit ? hit->t : remaining;
            if (m.grid) {
                ratioTrack(m, from, direction, length, hero, trackingSeed(from, direction, length),
                           result);
            } else {
                const S T = transmittance(m.sigmaT(), length);
                result.T *= T;
                result.passing *= T;
            }
            if (!(result.T.maxValue() > 0.0f)) return std::nullopt;
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

template <SpectrumType S>
std::optional<Transmittance<S>> segmentTransmittance(const Geometry& geometry,
                                                     const RenderMode<S>& mode,
                                                     typename RenderMode<S>::Path& path,
                                                     const Vec3f& a, const Vec3f& na,
                                                     const Vec3f& b, const Vec3f& nb, int medium,
                                                     int hero, PathStatistics& stats) {
    const Vec3f ab = b - a;
    const float scale = geometry.rayOffsetScale();
    const Vec3f from = na == Vec3f(0.0f) ? a : offsetRayOrigin(a, facing(na, ab), scale);
    const Vec3f to = nb == Vec3f(0.0f) ? b : offsetRayOrigin(b, facing(nb, -ab), scale);
    const float length = glm::length(to - from);
    if (!(length > 0.0f)) return Transmittance<S>{};
    return shadowTransmittance(geometry, mode, path, from, (to - from) / length,
                               length * (1.0f - 1e-4f), medium, hero, stats);
}

template <SpectrumType S>
void fromInfinity(const RenderMode<S>& mode, typename RenderMode<S>::Path& path, int medium,
                  int hero, const Vec3f& origin, const Vec3f& d, S& beta, S& rU) {
    const MediumCoefficients<S> m = mode.medium(medium, path);
    if (!m.grid) {
        beta *= transmittance(m.sigmaT(), std::numeric_limits<float>::infinity());
        return;
    }
    Transmittance<S> tr;
    const float tMax = std::numeric_limits<float>::infinity();
    ratioTrack(m, origin, -d, tMax, hero, trackingSeed(origin, -d, tMax), tr);
    beta *= tr.T;
    rU *= tr.rL;
}

int mediumAt(const Geometry& geometry, int cameraMedium, const Vec3f& cameraPosition,
             const Vec3f& point, PathStatistics& stats) {
    int medium = cameraMedium;
    Vec3f from = cameraPosition;
    for (int crossings = 0; crossings < kMaxInterfaceCrossings; ++crossings) {
        const Vec3f toPoint = point - from;
        const float remaining = glm::length(toPoint);
        if (!(remaining > 0.0f)) break;
        const Vec3f direction = toPoint / remaining;
        ++stats.rays;
        const auto hit = geometry.intersect(from, direction, remaining);
        if (!hit) break;
        const ShapeInfo& shape = geometry.shapes()[std::size_t(hit->shape)];
        medium = mediumAfter(shape, medium, hit->ng, direction, direction);
        from = offsetRayOrigin(hit->p, facing(hit->ng, direction), geometry.rayOffsetScale());
        if (!(glm::dot(point - from, direction) > 0.0f)) break;
    }
    return medium;
}

#define LAMINA_MEDIUM_TRANSPORT(S)                                                                 \
    template S transmittance(const S&, float);                                                     \
    template std::optional<Transmittance<S>> shadowTransmittance(                                  \
        const Geometry&, const RenderMode<S>&, typename RenderMode<S>::Path&, Vec3f, const Vec3f&, \
        float, int, int, PathStatistics&);                                                         \
    template std::optional<Transmittance<S>> segmentTransmittance(                                 \
        const Geometry&, const RenderMode<S>&, typename RenderMode<S>::Path&, const Vec3f&,        \
        const Vec3f&, const Vec3f&, const Vec3f&, int, int, PathStatistics&);                      \
    template void fromInfinity(const RenderMode<S>&, typename RenderMode<S>::Path&, int, int,      \
                               const Vec3f&, const Vec3f&, S&, S&);
LAMINA_MEDIUM_TRANSPORT(Rgb<float>)
LAMINA_MEDIUM_TRANSPORT(SampledSpectrum<float>)
#undef LAMINA_MEDIUM_TRANSPORT

}  // namespace lamina::render
