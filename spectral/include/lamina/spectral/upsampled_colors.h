// Colours upsampled in advance: a set of (RGB, kind) with their RgbSpectrum, so that code
// which upsamples the same colours again and again (spectral mode builds a material at the
// wavelengths of every path) finds the coefficients here instead of in the table (a search
// over its 64 brightness levels and a trilinear interpolation of three coefficients, as
// costly as the rest of a diffuse material's build).
#pragma once

#include <cstddef>
#include <vector>

#include "lamina/spectral/rgb_to_spectrum.h"

namespace lamina {

class UpsampledColors {
  public:
    /// More than any material upsamples; a set that is full keeps nothing more (so a caller
    /// that keeps ever new colours cannot make it grow).
    static constexpr std::size_t kCapacity = 16;

    /// The spectrum of `rgb` as `kind`: the one kept here, or else looked up in the table now.
    RgbSpectrum spectrum(const Rgb<double>& rgb, RgbSpectrumKind kind) const {
        if (const Entry* e = find(rgb, kind)) return e->spectrum;
        return RgbSpectrum(rgb, kind);
    }

    /// Upsamples `rgb` as `kind` and keeps it (unless it is already here or the set is full).
    void keep(const Rgb<double>& rgb, RgbSpectrumKind kind) {
        if (entries_.size() < kCapacity && !find(rgb, kind))
            entries_.push_back({rgb, kind, RgbSpectrum(rgb, kind)});
    }

    std::size_t size() const { return entries_.size(); }

  private:
    struct Entry {
        Rgb<double> rgb;
        RgbSpectrumKind kind;
        RgbSpectrum spectrum;
    };

    const Entry* find(const Rgb<double>& rgb, RgbSpectrumKind kind) const {
        for (const Entry& e : entries_)
            if (e.kind == kind && e.rgb == rgb) return &e;
        return nullptr;
    }

    std::vector<Entry> entries_;
};

}  // namespace lamina
