// What differs between the render modes, and nothing else (DESIGN.md, "Dual mode"): how a
// path starts (spectral mode draws its wavelengths), how an RGB emission and a material become
// the mode's spectrum, and what the film receives (Rec.709 in RGB mode, XYZ in spectral mode).
// The integrators are templated on a RenderMode and contain no mode-specific code.
#pragma once

#include <memory>
#include <vector>

#include "lamina/bsdf/material_builder.h"
#include "lamina/render/film.h"
#include "lamina/render/sampler.h"

namespace lamina::render {

template <SpectrumType S>
class RenderMode;

/// RGB mode: three linear Rec.709 channels; BSDFs are built once per material.
template <>
class RenderMode<Rgb<float>> {
  public:
    using Spectrum = Rgb<float>;
    struct Path {};

    explicit RenderMode(const SceneDesc& scene) {
        const SpectrumContext<Spectrum> context;
        for (const MaterialDesc& m : scene.materials)
            bsdfs_.push_back(buildBxdf(m, context));
    }

    static constexpr FilmSpace kFilmSpace = FilmSpace::Rec709;
    static constexpr const char* kName = "rgb";

    Path startPath(PixelSampler&) const { return {}; }
    Spectrum emission(const Rgb<float>& rgb, const Path&) const { return rgb; }
    const Bxdf<Spectrum>& bsdf(int material, Path&) const {
        return *bsdfs_[std::size_t(material)];
    }
    Rgb<double> filmValue(const Spectrum& L, const Path&) const { return Rgb<double>(L); }

  private:
    std::vector<std::unique_ptr<Bxdf<Spectrum>>> bsdfs_;
};

}  // namespace lamina::render
