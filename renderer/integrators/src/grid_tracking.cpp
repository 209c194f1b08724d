#include "lamina/integrators/grid_tracking.h"

#include <bit>
#include <cmath>
#include <limits>
#include <type_traits>

#include "lamina/core/hash.h"
#include "lamina/core/pcg32.h"
#include "lamina/integrators/majorant_walk.h"
#include "lamina/integrators/medium_transport.h"
#include "lamina/scene/colour_grid.h"

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

/// A grid medium's coefficients at a point of medium space: sigma_a and sigma_s per unit
/// density and the density (a density grid), or the cells' own coefficients at density 1
/// (per-cell colour grids, in RGB or at the path's wavelengths).
template <SpectrumType S>
struct LocalCoefficients {
    S sigmaA, sigmaS;
    float density;
};

template <SpectrumType S>
LocalCoefficients<S> coefficientsAt(const MediumCoefficients<S>& m, const Vec3f& p) {
    const GridDensity& grid = *m.grid;
    if (!grid.colours) return {m.sigmaA, m.sigmaS, grid.densityAt(p)};
    const Vec3f u = grid.local(p);
    LocalCoefficients<S> c{S(0.0f), S(0.0f), 1.0f};
    if constexpr (std::is_same_v<S, Rgb<float>>) {
        c.sigmaA = grid.colours->sigmaA.lookupRgb(u);
        c.sigmaS = grid.colours->sigmaS.lookupRgb(u);
    } else {
        grid.colours->sigmaA.lookupSpectral(u, m.lambda.data(), S::kSize, &c.sigmaA[0]);
        grid.colours->sigmaS.lookupSpectral(u, m.lambda.data(), S::kSize, &c.sigmaS[0]);
    }
    return c;
}

/// What a majorant cell's maximum multiplies: sigma_t per unit density for a density grid;
/// 1 in every channel for colour grids, whose majorants bound sigma_t itself over the channels
/// and wavelengths (as pbrt-v4's RGBGridMedium's majorants are the same at every wavelength).
template <SpectrumType S>
S majorantUnit(const MediumCoefficients<S>& m) {
    return m.grid->colours ? S(1.0f) : m.sigmaT();
}

/// A uniform number on (0, 1] in steps of 2^-24, for exponential distances -log(v) / sigma:
/// every such v is a float, so logf's argument is exact (1 - u of a finer u is not), and logf
/// costs far less than the log1pf of -log1p(-u) (which took a tenth of the cloud's profile).
inline float unitLatticeUniform(Pcg32& rng) {
    return float((rng.nextUint32() >> 8) + 1u) * 0x1p-24f;
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
            const float dt = rate > 0.0f ? -std::log(unitLatticeUniform(rng)) / rate
                                         : std::numeric_limits<float>::infinity();
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
                         const TransportAblations& ablations, S* E) {
    const GridDensity& grid = *m.grid;
    const S sigmaT = majorantUnit(m);
    // The ray in medium space: the same t, so the distances stay the scene's.
    const Vec3f mo = grid.pointToMedium(o), md = grid.directionToMedium(d);
    Pcg32 rng(seed);
    FlightOutcome result{FlightOutcome::Outcome::Passes, tMax};
    const float tau = trackCollisions(
        grid, sigmaT, mo, md, tMax, hero, rng, [&](float t, float maximum, float since) {
            const S Tmaj = transmittance(sigmaT, since);
            const S sigmaMaj = sigmaT * maximum;
            if (!(Tmaj[hero] > 0.0f)) {
                result.outcome = FlightOutcome::Outcome::Ends;
                return false;
            }
            const LocalCoefficients<S> here = coefficientsAt(m, mo + md * t);
            const float density = here.density;
            if (L && m.emits && density > 0.0f) {
                // The emission at every tentative collision, weighted over the channels.
                const float pdf = Tmaj[hero] * sigmaMaj[hero];
                const S rE = rU * sigmaMaj * Tmaj / pdf;
                if (rE.maxValue() > 0.0f)
                    *L += beta * Tmaj * here.sigmaA * density * m.emission /
                          (pdf * ablations.channelDensity(rE, hero));
            }
            const S sigmaTHere = (here.sigmaA + here.sigmaS) * density;
            if (rng.nextFloat() * sigmaMaj[hero] < sigmaTHere[hero]) {
                // A real collision: the path scatters here (its absorption in the weight sigma_s).
                const float pdf = Tmaj[hero] * sigmaTHere[hero];
                if (E && m.emits) *E = beta * Tmaj * here.sigmaA * density * m.emission / pdf;
                beta *= Tmaj * here.sigmaS * density / pdf;
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
    const S sigmaT = majorantUnit(m);
    const Vec3f mo = grid.pointToMedium(o), md = grid.directionToMedium(d);
    Pcg32 rng(seed);
    const float tau = trackCollisions(
        grid, sigmaT, mo, md, tMax, hero, rng, [&](float t, float maximum, float since) {
            const S Tmaj = transmittance(sigmaT, since);
            const S sigmaMaj = sigmaT * maximum;
            const float pdf = Tmaj[hero] * sigmaMaj[hero];
            if (!(pdf > 0.0f)) {
                tr.T = S(0.0f);
                return false;
            }
            const LocalCoefficients<S> here = coefficientsAt(m, mo + md * t);
            const S sigmaN = clampZero(sigmaMaj - (here.sigmaA + here.sigmaS) * here.density);
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

template <SpectrumType S>
PointCoefficients<S> coefficientsAtPoint(const MediumCoefficients<S>& m, const Vec3f& p) {
    if (!m.grid) return {m.sigmaA, m.sigmaT()};
    const Vec3f mp = m.grid->pointToMedium(p), u = m.grid->local(mp);
    // Outside its box a grid's density is 0 (a lookup would clamp to the nearest cell).
    for (int i = 0; i < 3; ++i)
        if (!(u[i] >= 0.0f && u[i] <= 1.0f)) return {};
    const LocalCoefficients<S> here = coefficientsAt(m, mp);
    return {here.sigmaA * here.density, (here.sigmaA + here.sigmaS) * here.density};
}

#define LAMINA_GRID_TRACKING(S)                                                                    \
    template FlightOutcome deltaTrack(const MediumCoefficients<S>&, const Vec3f&, const Vec3f&,    \
                                      float, int, std::uint64_t, S&, S&, S*, S*,                   \
                                      const TransportAblations&, S*);                              \
    template PointCoefficients<S> coefficientsAtPoint(const MediumCoefficients<S>&, const Vec3f&); \
    template void ratioTrack(const MediumCoefficients<S>&, const Vec3f&, const Vec3f&, float, int, \
                             std::uint64_t, Transmittance<S>&);
LAMINA_GRID_TRACKING(Rgb<float>)
LAMINA_GRID_TRACKING(SampledSpectrum<float>)
#undef LAMINA_GRID_TRACKING

}  // namespace lamina::render
