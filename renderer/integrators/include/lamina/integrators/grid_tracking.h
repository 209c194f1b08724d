// Transport through grid media (docs/media.md, "Grid media"): delta tracking for free flights
// and ratio tracking for the transmittance of shadow rays and connections, both against the
// majorant grid (majorant_walk.h), in the null-scattering path integral formulation of Miller,
// Georgiev and Jarosz 2019 ("A null-scattering path integral formulation of light transport"),
// as pbrt-v4's VolPathIntegrator implements it.
//
// The majorant of a cell is its maximum density times the medium's sigma_t per unit density, per
// channel: sigma_maj. Tentative collisions are sampled with the hero channel's sigma_maj (the
// path's hero, medium_transport.h); at a collision at density rho the hero chooses a real
// collision with probability sigma_t,h(rho) / sigma_maj,h, else a null collision of
// sigma_n = sigma_maj - sigma_t. Every factor is the same ratio as in a homogeneous medium, an
// integrand over the hero's density, applied to whole spectra (Miller et al. 2019, section 5.2,
// spectral MIS over the channel strategies):
//   real collision   beta *= T_maj sigma_s / p,  rU *= T_maj sigma_t / p,    p = T_maj,h sigma_t,h
//   null collision   beta *= T_maj sigma_n / p,  rU *= T_maj sigma_n / p,
//                    rL *= T_maj sigma_maj / p,                            p = T_maj,h sigma_n,h
//   reaching tMax    beta, rU, rL *= T_maj / T_maj,h
// with T_maj the majorant transmittance since the previous collision. rL are the densities of
// the same null collisions had they been sampled by ratio tracking (a light sample's shadow ray,
// below), so that next-event estimation and scattering are weighted by the balance heuristic
// over strategies and channels on the same null-scattering paths (pbrt-v4's r_l). The channels
// with a null collision the hero could not have made (sigma_n,h = 0) are sampled by the other
// heroes: the average over the channels in the integrators' weights makes the estimator
// unbiased, not the hero's own density.
//
// Ratio tracking (Novak, Selle and Jarosz 2014, "Residual ratio tracking for estimating
// attenuation in participating media"; as a strategy of the null-scattering formulation, Miller
// et al. 2019, section 5.3) samples the same tentative collisions and multiplies at each
//   T *= T_maj sigma_n / p,  rU *= T_maj sigma_n / p,  rL *= T_maj sigma_maj / p,
//   p = T_maj,h sigma_maj,h,
// and T, rU, rL *= T_maj / T_maj,h at the end: T estimates the transmittance over the hero's
// density, rU is the density of a path's delta tracking passing the same null collisions, rL
// the tracking's own densities per channel. Both relative to p, as the path's ratios are.
//
// Random numbers: a flight draws one number from the pixel sampler, as a homogeneous flight
// does, and seeds the tracking's own generator with it and the ray (pbrt-v4 seeds its
// trackers' RNG with hashes of sampler numbers and of the ray); a shadow ray's tracking is
// seeded by the ray alone.
#pragma once

#include <cstdint>

#include "lamina/integrators/transport_ablations.h"
#include "lamina/render/medium_coefficients.h"

namespace lamina::render {

/// A seed for a tracking generator from a ray and a number that tells flights apart.
std::uint64_t trackingSeed(const Vec3f& o, const Vec3f& d, float u);

/// What a free flight ended in (delta-tracked in a grid, sampled exactly in a homogeneous
/// medium: MediumFlight::apply).
struct FlightOutcome {
    enum class Outcome { Passes, Scatters, Ends } outcome;
    float t;  ///< the real collision's distance (Scatters)
};

/// Delta tracking along o + t d, t in [0, tMax] (tMax infinite: to the end of the grid's box),
/// through the grid medium `m` with the hero channel `hero`: multiplies beta, rU and (if given)
/// rL by the factors above, and adds the medium's emission at every tentative collision to `L`
/// (if given; the collision estimator of pbrt-v4's VolPathIntegrator:
/// beta T_maj sigma_a Le / p over the average of rU sigma_maj T_maj / p, p = T_maj,h sigma_maj,h).
/// Ends when the hero's density of the outcome is 0 (the path ends, as a homogeneous flight
/// of pdf 0 does). `E`, if given, receives at a real collision the emission estimate of that
/// collision alone, before its weighting over the channels: beta T_maj sigma_a Le / p
/// (p = T_maj,h sigma_t,h; the collision's channel densities are rU after it): BDPT's camera
/// subpaths count a medium's emission at their real vertices (docs/media.md).
template <SpectrumType S>
FlightOutcome deltaTrack(const MediumCoefficients<S>& m, const Vec3f& o, const Vec3f& d, float tMax,
                         int hero, std::uint64_t seed, S& beta, S& rU, S* rL, S* L,
                         const TransportAblations& ablations, S* E = nullptr);

/// A medium's absorption and extinction at a point of the scene: a homogeneous medium's own,
/// a grid medium's at the point's density (0 outside its box) or its cells' colours.
template <SpectrumType S>
struct PointCoefficients {
    S sigmaA{0.0f}, sigmaT{0.0f};
};
template <SpectrumType S>
PointCoefficients<S> coefficientsAtPoint(const MediumCoefficients<S>& m, const Vec3f& p);

/// A transmittance through media, for a shadow ray or a connection (medium_transport.h).
template <SpectrumType S>
struct Transmittance {
    S T{1.0f};        ///< exact through homogeneous media, estimated by ratio tracking in grids
    S passing{1.0f};  ///< a path's density of passing the same media (free flights), per channel
    S rL{1.0f};       ///< the densities of the tracking itself per channel (1: exact)
};

/// Ratio tracking along o + t d, t in [0, tMax], through the grid medium `m` with the hero
/// channel `hero`, multiplied into `tr` (T and passing by the null factors, rL by the
/// tracking's). Russian roulette (pbrt-v4's) ends a tracking whose estimate has fallen below
/// 0.05 relative to its density with probability 0.75, and multiplies a survivor by 4.
template <SpectrumType S>
void ratioTrack(const MediumCoefficients<S>& m, const Vec3f& o, const Vec3f& d, float tMax,
                int hero, std::uint64_t seed, Transmittance<S>& tr);

}  // namespace lamina::render
