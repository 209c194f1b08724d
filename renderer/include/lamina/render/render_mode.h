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
#include "lamina/spectral/cie.h"

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

/// Spectral mode: four hero wavelengths per path (Wilkie et al. 2014), colours upsampled
/// (reflectances) and emission upsampled as illuminants (so RGB (1, 1, 1) light is D65 and
/// stays white), the film accumulating CIE XYZ:
///   XYZ = 1/N sum_i L(lambda_i) xyz-bar(lambda_i) / (p(lambda_i) integral of y-bar),
/// which gives Y = 1 for a constant spectrum 1, as RGB mode gives luminance 1 for white 1.
template <>
class RenderMode<SampledSpectrum<float>> {
  public:
    using Spectrum = SampledSpectrum<float>;
    struct Path {
        SampledWavelengths<float> lambda;
        std::unique_ptr<Bxdf<Spectrum>> bsdf;  ///< the BSDF of the current vertex
    };

    explicit RenderMode(const SceneDesc& scene) : scene_(scene) {
        // Emission colours are few: upsample each once.
        auto add = [this](const Rgb<double>& rgb) {
            for (const auto& e : emissions_)
                if (e.first == Rgb<float>(rgb)) return;
            emissions_.emplace_back(Rgb<float>(rgb), RgbSpectrum(rgb, RgbSpectrumKind::Illuminant));
        };
        for (const auto& m : scene.meshes)
            if (m.emission) add(m.emission->radiance);
        for (const auto& s : scene.spheres)
            if (s.emission) add(s.emission->radiance);
        for (const auto& l : scene.lights)
            add(l.intensity);
    }

    static constexpr FilmSpace kFilmSpace = FilmSpace::Xyz;
    static constexpr const char* kName = "spectral";

    Path startPath(PixelSampler& sampler) const {
        return {SampledWavelengths<float>::sample(double(sampler.get1D())), nullptr};
    }

    Spectrum emission(const Rgb<float>& rgb, const Path& path) const {
        for (const auto& [key, spectrum] : emissions_)
            if (key == rgb) return evaluate(spectrum, path);
        return evaluate(RgbSpectrum(Rgb<double>(rgb), RgbSpectrumKind::Illuminant), path);
    }

    const Bxdf<Spectrum>& bsdf(int material, Path& path) const {
        const SpectrumContext<Spectrum> context{path.lambda};
        path.bsdf = buildBxdf(scene_.materials[std::size_t(material)], context);
        return *path.bsdf;
    }

    Rgb<double> filmValue(const Spectrum& L, const Path& path) const {
        Vec3d xyz(0.0);
        const Spectrum pdf = path.lambda.pdf();
        for (int i = 0; i < Spectrum::kSize; ++i)
            if (pdf[i] > 0.0f)
                xyz += cieXyz(double(path.lambda[i])) * (double(L[i]) / double(pdf[i]));
        xyz /= double(Spectrum::kSize) * cieYIntegral();
        return {xyz.x, xyz.y, xyz.z};
    }

  private:
    static Spectrum evaluate(const RgbSpectrum& s, const Path& path) {
        Spectrum out;
        for (int i = 0; i < Spectrum::kSize; ++i)
            out[i] = float(s(double(path.lambda[i])));
        return out;
    }

    const SceneDesc& scene_;
    std::vector<std::pair<Rgb<float>, RgbSpectrum>> emissions_;
};

}  // namespace lamina::render
