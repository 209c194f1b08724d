// Transport through media (docs/media.md): which medium a path is in after it crosses a
// surface, free-flight distances, and the transmittance of a shadow ray through every medium
// and index-matched interface on its way. Grid media are tracked (grid_tracking.h); this file
// holds the homogeneous media's exact steps and what both kinds share.
//
// Spectral MIS (Miller, Georgiev and Jarosz 2019, "A null-scattering path integral
// formulation of light transport", section 5.2; pbrt-v4's VolPathIntegrator): a path samples
// every free flight with the extinction of one channel, its hero, chosen uniformly once per
// path, and its estimate is divided by the average over the channels of the densities with
// which each channel would have sampled the same path: the one-sample balance heuristic over
// the channel strategies, applied to whole paths. The integrator carries those densities as
// ratios to the hero's (pbrt-v4's r_u and r_l), so a channel whose extinction differs from the
// hero's gets no firefly: its weight is at most the number of channels. (Averaging per flight
// instead would multiply a factor of up to N at every scattering event: heavy-tailed in a
// dense chromatic medium.) The hero is drawn explicitly: spectral mode's wavelengths are a
// random rotation, but RGB mode's channels are fixed, and always sampling with red would not
// be the balance heuristic's estimator. A homogeneous medium's transmittance exp(-sigma_t d)
// is exact: no tracking.
#pragma once

#include <limits>
#include <optional>

#include "lamina/geometry/geometry.h"
#include "lamina/integrators/grid_tracking.h"
#include "lamina/integrators/integrator.h"

namespace lamina::render {

/// The medium a path is in after it leaves `shape`'s surface along `direction`, having
/// arrived along `arrival` (geometric normal `ng`): the medium of the side it goes to when
/// it crosses a shape that bounds media, else `current` (a reflection, or a shape that names
/// no media).
inline int mediumAfter(const ShapeInfo& shape, int current, const Vec3f& ng, const Vec3f& arrival,
                       const Vec3f& direction) {
    const auto& media = surface(*shape.desc).media;
    if (!media) return current;
    const float before = glm::dot(arrival, ng), after = glm::dot(direction, ng);
    // Crossing keeps the sign of the cosine with the normal; a reflection flips it.
    if ((before > 0.0f) != (after > 0.0f)) return current;
    return media->sideOf(after);
}

/// Index-matched interfaces a path may cross between two scattering events (or a walk from the
/// camera to a point, mediumAt) before it is given up: only coincident interfaces that the ray
/// offset cannot separate get near it.
inline constexpr int kMaxInterfaceCrossings = 1024;

/// The path's hero channel for distance sampling, uniform over the channels.
template <SpectrumType S>
int heroChannel(float u) {
    return std::min(int(u * float(S::kSize)), S::kSize - 1);
}

/// A free-flight distance with density sigma exp(-sigma t) (infinity for sigma = 0).
float freeFlightDistance(float sigma, float u);

/// exp(-sigma_t d) per channel; d may be infinite (then 0 where sigma_t > 0, 1 where it is 0).
template <SpectrumType S>
S transmittance(const S& sigmaT, float d);

/// One free flight towards a surface at `tMax` (infinity: none) in a medium of extinction
/// `sigmaT`, sampled with the hero channel's density sigma_t,h exp(-sigma_t,h t).
template <SpectrumType S>
struct FreeFlight {
    bool scatters;  ///< a medium vertex at `t` before the surface; else the flight passes
    float t;        ///< the distance flown (tMax when it passes)
    S T;            ///< exp(-sigma_t t) per channel
    /// The hero's density of this outcome: sigma_t,h T_h(t) at a medium vertex, the
    /// probability T_h(tMax) of passing; 0 (the path ends) when the outcome had none.
    float pdf;
};

template <SpectrumType S>
FreeFlight<S> sampleFreeFlight(const S& sigmaT, int hero, float u, float tMax) {
    const float t = freeFlightDistance(sigmaT[hero], u);
    if (!(t < tMax)) {
        const S T = transmittance(sigmaT, tMax);
        return {false, tMax, T, T[hero]};
    }
    const S T = transmittance(sigmaT, t);
    return {true, t, T, sigmaT[hero] * T[hero]};
}

/// A free flight of a path through the medium it is in: the medium's coefficients, its
/// extinction, and the flight sampled towards the surface the path's ray hit. A grid medium's
/// flight is not sampled here: `track` delta-tracks it (`flight` is unused).
template <SpectrumType S>
struct MediumFlight {
    MediumCoefficients<S> coefficients;
    S sigmaT;
    FreeFlight<S> flight;
    float u;     ///< the flight's number from the pixel sampler
    float tMax;  ///< the distance to the surface (infinity: none)

    bool tracked() const { return coefficients.grid != nullptr; }

    /// The flight of a path along o + t d (the ray it was sampled for), applied to the path's
    /// throughput `beta`, its densities per channel relative to the hero's `rU` and, if given,
    /// the path integrator's light-sampling densities `rL` and radiance `L` (the medium's
    /// emission): where the path goes on, or that it ends (the outcome had no density).
    /// Homogeneous: `weigh`, rL over the hero's probability of passing (a shadow ray's
    /// transmittance is exact: it has no density of its own), the emission by the collision
    /// estimator at a medium vertex. Grid: delta tracking (grid_tracking.h). The emission is
    /// weighted over the channels as `ablations` says (TransportAblations::channelDensity).
    /// `E`, if given, receives the emission estimate of the medium vertex itself (deltaTrack).
    FlightOutcome apply(const Vec3f& o, const Vec3f& d, int hero, S& beta, S& rU, S* rL, S* L,
                        const TransportAblations& ablations, S* E = nullptr) const {
        if (tracked())
            return deltaTrack(coefficients, o, d, tMax, hero, trackingSeed(o, d, u), beta, rU, rL,
                              L, ablations, E);
        if (!(flight.pdf > 0.0f)) return {FlightOutcome::Outcome::Ends, flight.t};
        if (!flight.scatters) {
            weigh(beta, rU);
            if (rL) *rL /= flight.pdf;
            return {FlightOutcome::Outcome::Passes, flight.t};
        }
        if (L && coefficients.emits) {
            // A scattering event at t, of density sigma_t T(t) per channel: the medium's
            // emission along the flight, by the collision estimator.
            const S rE = rU * sigmaT * flight.T / flight.pdf;
            *L += beta * flight.T * coefficients.sigmaA * coefficients.emission /
                  (flight.pdf * ablations.channelDensity(rE, hero));
        }
        if (E && coefficients.emits)
            *E = beta * flight.T * coefficients.sigmaA * coefficients.emission / flight.pdf;
        weigh(beta, rU);
        return {FlightOutcome::Outcome::Scatters, flight.t};
    }

    /// The flight's factors on a path's throughput `beta` and its densities per channel
    /// relative to the hero's `rU`: T / p_h when it passes, T sigma_s / p_h (the phase function
    /// is its own density) and sigma_t T / p_h at a medium vertex. Only for flight.pdf > 0.
    void weigh(S& beta, S& rU) const {
        if (!flight.scatters) {
            beta *= flight.T / flight.pdf;
            rU *= flight.T / flight.pdf;
        } else {
            beta *= flight.T * coefficients.sigmaS / flight.pdf;
            rU *= sigmaT * flight.T / flight.pdf;
        }
    }
};

/// The free flight of a path in `medium` (-1: vacuum) along a ray that hit `hit` (none: it
/// leaves the scene), sampled with the path's `hero` channel. In vacuum there is none, and the
/// flight's number is skipped so that the sampler's dimensions keep their meaning.
template <SpectrumType S>
std::optional<MediumFlight<S>> sampleMediumFlight(const RenderMode<S>& mode,
                                                  typename RenderMode<S>::Path& path, int medium,
                                                  int hero, PixelSampler& sampler,
                                                  const std::optional<SurfaceHit>& hit) {
    if (medium < 0) {
        sampler.skip();
        return std::nullopt;
    }
    const MediumCoefficients<S> m = mode.medium(medium, path);
    const S sigmaT = m.sigmaT();
    const float u = sampler.get1D(), tMax = hit ? hit->t : std::numeric_limits<float>::infinity();
    if (m.grid) return MediumFlight<S>{m, sigmaT, {false, tMax, S(1.0f), 1.0f}, u, tMax};
    return MediumFlight<S>{m, sigmaT, sampleFreeFlight(sigmaT, hero, u, tMax), u, tMax};
}

/// The transmittance from `from` (already off its surface) along the unit `direction` for
/// `distance` (infinity: out of the scene), starting in `medium`, through every index-matched
/// interface it crosses: the product over its segments of exp(-sigma_t d) in homogeneous media
/// and of ratio tracking's estimate (with the path's `hero`) in grid media, with the densities
/// of grid_tracking.h's Transmittance; nothing when another surface blocks it or no channel
/// gets through.
template <SpectrumType S>
std::optional<Transmittance<S>> shadowTransmittance(const Geometry& geometry,
                                                    const RenderMode<S>& mode,
                                                    typename RenderMode<S>::Path& path, Vec3f from,
                                                    const Vec3f& direction, float distance,
                                                    int medium, int hero, PathStatistics& stats);

/// The transmittance of the segment between two points, each moved off its surface along its
/// normal on the side facing the other as segmentUnoccluded moves them (a zero normal: a point
/// not on a surface, such as a lens or a medium vertex), starting in `medium` at `a`: a
/// camera connection of a light path (shadowTransmittance).
template <SpectrumType S>
std::optional<Transmittance<S>> segmentTransmittance(const Geometry& geometry,
                                                     const RenderMode<S>& mode,
                                                     typename RenderMode<S>::Path& path,
                                                     const Vec3f& a, const Vec3f& na,
                                                     const Vec3f& b, const Vec3f& nb, int medium,
                                                     int hero, PathStatistics& stats);

/// Light from infinity that reaches `origin` travelling along `d` through `medium`, a medium
/// that reaches infinity (a particle of an infinite light starting in it): beta times
/// exp(-sigma_t infinity) in a homogeneous medium (0 where the extinction is not); in a grid
/// medium, whose density is 0 outside its box, beta times ratio tracking's estimate along the
/// ray back from `origin` and rU times the tracking's densities (its null collisions are the
/// particle path's).
template <SpectrumType S>
void fromInfinity(const RenderMode<S>& mode, typename RenderMode<S>::Path& path, int medium,
                  int hero, const Vec3f& origin, const Vec3f& d, S& beta, S& rU);

/// The medium at `point`, found by following the segment from the camera (at `cameraPosition`,
/// in `cameraMedium`) to it and switching medium at every boundary it crosses (mediumAfter):
/// where a light particle that does not leave a surface bounding media starts.
int mediumAt(const Geometry& geometry, int cameraMedium, const Vec3f& cameraPosition,
             const Vec3f& point, PathStatistics& stats);

}  // namespace lamina::render
