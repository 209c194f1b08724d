#include "lamina/scene/colour_grid.h"

#include <algorithm>
#include <cmath>

#include "lamina/spectral/cie.h"
#include "lamina/spectral/rgb_to_spectrum.h"

namespace lamina::render {

namespace {

float sigmoid(float x) {
    if (std::isinf(x)) return x > 0 ? 1.0f : 0.0f;
    return 0.5f + x / (2.0f * std::sqrt(1.0f + x * x));
}

/// The largest value of the sigmoid polynomial over [kLambdaMin, kLambdaMax]: the sigmoid is
/// increasing, so it is the sigmoid of the quadratic's maximum, at an end or at its vertex.
double spectralMaximum(const SigmoidPolynomial& p) {
    const auto q = [&](double nm) { return (p.c0 * nm + p.c1) * nm + p.c2; };
    double m = std::max(q(kLambdaMin), q(kLambdaMax));
    if (p.c0 != 0.0) {
        const double vertex = -p.c1 / (2.0 * p.c0);
        if (vertex > kLambdaMin && vertex < kLambdaMax) m = std::max(m, q(vertex));
    }
    return SigmoidPolynomial::sigmoid(m);
}

}  // namespace

ColourGrid ColourGrid::fromGrid(const DensityGrid& g, const Rgb<double>& factor) {
    ColourGrid c;
    c.nx = g.nx;
    c.ny = g.ny;
    c.nz = g.nz;
    c.zeroOutside = g.zeroOutside;
    c.rgb.resize(g.count());
    for (std::size_t i = 0; i < c.rgb.size(); ++i)
        for (int ch = 0; ch < 3; ++ch)
            c.rgb[i][ch] = float(
                double(
                    g.values[i * std::size_t(g.channels) + std::size_t(g.channels == 3 ? ch : 0)]) *
                factor[ch]);
    c.finish();
    return c;
}

ColourGrid ColourGrid::constant(const Rgb<double>& value) {
    ColourGrid c;
    c.rgb = {Rgb<float>(value)};
    c.finish();
    return c;
}

void ColourGrid::finish() {
    // The unbounded spectrum of each cell, as RgbSpectrum(rgb, Unbounded) makes it.
    const RgbToSpectrumTable& table = RgbToSpectrumTable::rec709();
    spectral.resize(rgb.size());
    bounds_.resize(rgb.size());
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        const Rgb<double> v(rgb[i]);
        const double m = std::max({v[0], v[1], v[2], 0.0});
        const double scale = 2.0 * m;
        const SigmoidPolynomial p =
            scale > 0 ? table.lookup(v / scale) : SigmoidPolynomial::constant(0.0);
        spectral[i] = {float(p.c0), float(p.c1), float(p.c2), float(scale)};
        // A margin for the float evaluation against the double maximum.
        bounds_[i] = float(std::max(m, scale * spectralMaximum(p)) * (1.0 + 1e-5));
    }
}

Rgb<float> ColourGrid::lookupRgb(Vec3f u) const {
    const TrilinearCorners c = trilinearCorners(u, nx, ny, nz, zeroOutside);
    Rgb<float> out(0.0f);
    for (int k = 0; k < 8; ++k)
        if (c.index[k] >= 0 && c.weight[k] > 0.0f)
            out += rgb[std::size_t(c.index[k])] * c.weight[k];
    return out;
}

void ColourGrid::lookupSpectral(Vec3f u, const float* lambda, int n, float* out) const {
    const TrilinearCorners c = trilinearCorners(u, nx, ny, nz, zeroOutside);
    for (int w = 0; w < n; ++w)
        out[w] = 0.0f;
    for (int k = 0; k < 8; ++k) {
        if (c.index[k] < 0 || !(c.weight[k] > 0.0f)) continue;
        const std::array<float, 4>& s = spectral[std::size_t(c.index[k])];
        if (s[3] == 0.0f) continue;
        for (int w = 0; w < n; ++w)
            out[w] += c.weight[k] * s[3] * sigmoid((s[0] * lambda[w] + s[1]) * lambda[w] + s[2]);
    }
}

MajorantGrid ColourGrids::majorants() const {
    const auto bounds = [](const ColourGrid& c) {
        DensityGrid g;
        g.nx = c.nx;
        g.ny = c.ny;
        g.nz = c.nz;
        g.zeroOutside = c.zeroOutside;
        g.values.resize(g.count());
        for (std::size_t i = 0; i < g.values.size(); ++i)
            g.values[i] = c.bound(i);
        return g;
    };
    const DensityGrid a = bounds(sigmaA), s = bounds(sigmaS);
    const int r = MajorantGrid::kResolution;
    const int cx = std::min(r, std::max(a.nx, s.nx)), cy = std::min(r, std::max(a.ny, s.ny)),
              cz = std::min(r, std::max(a.nz, s.nz));
    MajorantGrid m = MajorantGrid::build(a, cx, cy, cz);
    const MajorantGrid ms = MajorantGrid::build(s, cx, cy, cz);
    for (std::size_t i = 0; i < m.maxima.size(); ++i)
        m.maxima[i] += ms.maxima[i];
    return m;
}

}  // namespace lamina::render
