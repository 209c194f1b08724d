#include "lamina/integrators/grid_tracking.h"

#include <bit>

#include "lamina/core/hash.h"
#include "lamina/core/pcg32.h"
#include "lamina/integrators/majorant_walk.h"
#include "lamina/integrators/medium_transport.h"

namespace lamina::render {

namespace {

/// Per channel max(a, 0): a null coefficient cannot be negative (the majorant is conservative
/// but a density may exceed it by rounding).
template <SpectrumType S>
S clampZero(S a) {
    for (int i = 0; i < S::kSize; ++i)
        a[i] = std::max(a[i], 0.0f);
    return a;
}

/// The tentative collisions of both trackings: in each piece of the majorant walk, distances
/// with the hero's majorant sigma_maj,h = maximum * sigma_t,h; `collide(t, maximum, tau)` is
/// called at each (tau: density times length since the previous collision, so that
/// T_maj = exp(-sigma_t tau) per channel) and returns false to stop. Returns the tau left
/// since the last collision when the walk reaches its end, or a negative value when stopped.
template <SpectrumType S, typename Collide>
float trackCollisions(const GridDensity& grid, const S& sigmaT, const Vec3f& o, const Vec3f& d,
                      float tMax, int hero, Pcg32& rng, Collide&& collide) {
    float tau = 0.0f;
    bool stopped = false;
    walkMajorants(grid, o, d, tMax, [&](float t0, float t1, float maximum) {
        const float rate = maximum * sigmaT[hero];
        for (float t = t0;;) {
            // Memorylessness: a distance sampled afresh in each piece has the density of one
            // sampled with the piecewise-constant majorant across them.
            const float dt = freeFlightDistance(rate, rng.nextFloat());
            if (!(dt < t1 - t)) {
                tau += maximum * (t1 - t);
                return true;
            }
            t += dt;
            tau += maximum * dt;
            const float since = tau;
            tau = 0.0f;
            if (!collide(t, maximum, since)) {
                stopped = true;
                return false;
            }
        }
    });
    return stopped ? -1.0f : tau;
}

}  // namespace

std::uint64_t trackingSeed(const Vec3f& o, const Vec3f& d, float u) {
    const auto bits = [](float v) { return std::uint64_t(std::bit_cast<std::uint32_t>(v)); };
    return hashValues({bits(o.x) | bits(o.y) << 32u, bits(o.z) | bits(d.x) << 32u,
                       bits(d.y) | bits(d.z) << 32u, bits(u)});
}

template <SpectrumType S>
FlightOutcome deltaTrack(const MediumCoefficients<S>& m, const Vec3f& o, const Vec3f& d, float tMax,
                         int hero, std::uint64_t seed, S& beta, S& rU, S* rL, S* L,
                         const TransportAblations& ablations) {
    const GridDensity& grid = *m.grid;
    const S sigmaT = m.sigmaT();
    Pcg32 rng(seed);
    FlightOutcome result{FlightOutcome::Outcome::Passes, tMax};
    const float tau = trackCollisions(
        grid, sigmaT, o, d, tMax, hero, rng, [&](float t, float maximum, float since) {
            const S Tmaj = transmittance(sigmaT, since);
            const S sigmaMaj = sigmaT * maximum;
            if (!(Tmaj[hero] > 0.0f)) {
                result.outcome = FlightOutcome::Outcome::Ends;
                return false;
            }
            const float density = grid.densityAt(o + d * t);
            if (L && m.emits && density > 0.0f) {
                // The emission at every tentative collision, weighted over the channels.
                const float pdf = Tmaj[hero] * sigmaMaj[hero];
                const S rE = rU * sigmaMaj * Tmaj / pdf;
                if (rE.maxValue() > 0.0f)
                    *L += beta * Tmaj * m.sigmaA * density * m.emission /
                          (pdf * ablations.channelDensity(rE, hero));
            }
            const S sigmaTHere = sigmaT * density;
            if (rng.nextFloat() * sigmaMaj[hero] < sigmaTHere[hero]) {
                // A real collision: the path scatters here (its absorption in the weight sigma_s).
                const float pdf = Tmaj[hero] * sigmaTHere[hero];
                beta *= Tmaj * m.sigmaS * density / pdf;
                rU *= Tmaj * sigmaTHere / pdf;
                result = {FlightOutcome::Outcome::Scatters, t};
                return false;
            }
            const S sigmaN = clampZero(sigmaMaj - sigmaTHere);
            const float pdf = Tmaj[hero] * sigmaN[hero];
            if (!(pdf > 0.0f)) {
                result.outcome = FlightOutcome::Outcome::Ends;
                return false;
            }
            beta *= Tmaj * sigmaN / pdf;
            rU *= Tmaj * sigmaN / pdf;
            if (rL) *rL *= Tmaj * sigmaMaj / pdf;
            if (!(beta.maxValue() > 0.0f)) {
                result.outcome = FlightOutcome::Outcome::Ends;
                return false;
            }
            return true;
        });
    if (result.outcome != FlightOutcome::Outcome::Passes) return result;
    const S Tmaj = transmittance(sigmaT, tau);
    if (!(Tmaj[hero] > 0.0f)) return {FlightOutcome::Outcome::Ends, tMax};
    beta *= Tmaj / Tmaj[hero];
    rU *= Tmaj / Tmaj[hero];
    if (rL) *rL *= Tmaj / Tmaj[hero];
    return result;
}

template <SpectrumType S>
void ratioTrack(const MediumCoefficients<S>& m, const Vec3f& o, const Vec3f& d, float tMax,
                int hero, std::uint64_t seed, Transmittance<S>& tr) {
    const GridDensity& grid = *m.grid;
    const S sigmaT = m.sigmaT();
    Pcg32 rng(seed);
    const float tau = trackCollisions(
        grid, sigmaT, o, d, tMax, hero, rng, [&](float t, float maximum, float since) {
            const S Tmaj = transmittance(sigmaT, since);
            const S sigmaMaj = sigmaT * maximum;
            const float pdf = Tmaj[hero] * sigmaMaj[hero];
            if (!(pdf > 0.0f)) {
                tr.T = S(0.0f);
                return false;
            }
            const S sigmaN = clampZero(sigmaMaj - sigmaT * grid.densityAt(o + d * t));
            tr.T *= Tmaj * sigmaN / pdf;
            tr.passing *= Tmaj * sigmaN / pdf;
            tr.rL *= Tmaj * sigmaMaj / pdf;
            // Russian roulette on the estimate relative to the tracking's density.
            if ((tr.T / tr.rL.average()).maxValue() < 0.05f) {
                if (rng.nextFloat() < 0.75f)
                    tr.T = S(0.0f);
                else
                    tr.T /= 0.25f;
            }
            return tr.T.maxValue() > 0.0f;
        });
    if (tau < 0.0f) return;
    const S Tmaj = transmittance(sigmaT, tau);
    if (!(Tmaj[hero] > 0.0f)) {
        tr.T = S(0.0f);
        return;
    }
    tr.T *= Tmaj / Tmaj[hero];
    tr.passing *= Tmaj / Tmaj[hero];
    tr.rL *= Tmaj / Tmaj[hero];
}

#define LAMINA_GRID_TRACKING(S)                                                                    \
    template FlightOutcome deltaTrack(const MediumCoefficients<S>&, const Vec3f&, const Vec3f&,    \
                                      float, int, std::uint64_t, S&, S&, S*, S*,                   \
                                      const TransportAblations&);                                  \
    template void ratioTrack(const MediumCoefficients<S>&, const Vec3f&, const Vec3f&, float, int, \
                             std::uint64_t, Transmittance<S>&);
LAMINA_GRID_TRACKING(Rgb<float>)
LAMINA_GRID_TRACKING(SampledSpectrum<float>)
#undef LAMINA_GRID_TRACKING

}  // namespace lamina::render
