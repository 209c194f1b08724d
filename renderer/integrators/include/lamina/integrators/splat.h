// Splatting a light-subpath contribution at a continuous film position: every pixel whose
// filter covers the position receives the value times the filter normalised to integral 1
// there, so a splat estimates the same filtered measurement as the camera samples do.
#pragma once

#include <cmath>

#include <optional>
#include <type_traits>

#include "lamina/render/film.h"
#include "lamina/render/pixel_filter.h"
#include "lamina/render/render_mode.h"

namespace lamina::render {

/// Calls add(x, y, weight) for every pixel of a width x height film whose filter covers
/// `raster`, with the filter normalised to integral 1 there.
template <typename Add>
void forEachFilteredPixel(const PixelFilter& filter, const Vec2<float>& raster, int width,
                          int height, Add&& add) {
    const float r = filter.radius();
    const int x0 = std::max(0, int(std::ceil(raster.x - 0.5f - r)));
    const int x1 = std::min(width - 1, int(std::floor(raster.x - 0.5f + r)));
    const int y0 = std::max(0, int(std::ceil(raster.y - 0.5f - r)));
    const int y1 = std::min(height - 1, int(std::floor(raster.y - 0.5f + r)));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const float w = filter.normalizedWeight(
                Vec2<float>(raster.x - (float(x) + 0.5f), raster.y - (float(y) + 0.5f)));
            if (w > 0.0f) add(x, y, double(w));
        }
}

inline void splatFiltered(Film& film, const PixelFilter& filter, const Vec2<float>& raster,
                          const Rgb<double>& value) {
    forEachFilteredPixel(filter, raster, film.fullWidth(), film.fullHeight(),
                         [&](int x, int y, double w) { film.addSplat(x, y, value, w); });
}

/// Splats a light-path contribution `value` that reaches the lens travelling along `toLens`:
/// the mode's film value, or in the polarised mode its Stokes vector in the image frame
/// (RenderMode<PolarisedSpectrum>::filmStokes) with the Stokes layers; with a spectral film,
/// its per-bin deposits too.
template <SpectrumType S>
void splatContribution(Film& film, const PixelFilter& filter, const Vec2<float>& raster,
                       const RenderMode<S>& mode, const S& value, const Vec3<float>& toLens,
                       const Vec3<float>& imageRight, const typename RenderMode<S>::Path& path) {
    const SpectralFilm* spectral = film.spectralFilm();
    if constexpr (std::is_same_v<S, PolarisedSpectrum>) {
        const auto image = mode.imageStokes(value, -toLens, imageRight);
        const std::array<Rgb<double>, 4> stokes = mode.filmStokes(image, path);
        std::optional<SpectralFilmSample> bins;
        if (spectral) bins = mode.filmSpectrum(image, path, spectral->bins());
        forEachFilteredPixel(filter, raster, film.fullWidth(), film.fullHeight(),
                             [&](int x, int y, double w) {
                                 film.addPolarisedSplat(x, y, stokes, w, bins ? &*bins : nullptr);
                             });
    } else if constexpr (std::is_same_v<S, SampledSpectrum<float>>) {
        if (!spectral) return splatFiltered(film, filter, raster, mode.filmValue(value, path));
        const Rgb<double> v = mode.filmValue(value, path);
        const SpectralFilmSample bins = mode.filmSpectrum(value, path, spectral->bins());
        forEachFilteredPixel(filter, raster, film.fullWidth(), film.fullHeight(),
                             [&](int x, int y, double w) { film.addSplat(x, y, v, w, &bins); });
    } else {
        splatFiltered(film, filter, raster, mode.filmValue(value, path));
    }
}

}  // namespace lamina::render
