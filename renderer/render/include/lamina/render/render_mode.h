// What differs between the render modes, and nothing else (docs/spectral.md): how a
// path starts (spectral mode draws its wavelengths), how an RGB emission and a material become
// the mode's spectrum, and what the film receives (Rec.709 in RGB mode, XYZ in spectral mode).
// The integrators are templated on a RenderMode and contain no mode-specific code; they are
// compiled for each (src/integrators/*.cpp instantiate them for Rgb<float> and
// SampledSpectrum<float>; the polarised mode's PolarisedSpectrum has its own file). The mode's
// names are kRenderModeNames (renderer.h).
//
// Both modes build their materials with the render's seed as the seed of the `coated`
// material's random walks, so renders with different seeds get independent walk estimates
// (docs/bsdf.md, "Random numbers").
//
// bsdf(material, at, path) returns a reference valid until the next call to bsdf() from the
// same thread (at the path's next vertex, or for another path): a textured material's BSDF is
// rebuilt at every call, and in spectral mode a call for another path resets the per-thread
// cache of built BSDFs. Use the reference at one vertex, then ask again.
#pragma once

#include <memory>
#include <vector>

#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/material_kind.h"
#include "lamina/lights/emitter_color.h"
#include "lamina/render/film.h"
#include "lamina/render/medium_coefficients.h"
#include "lamina/render/polarised_bxdf.h"
#include "lamina/render/sampler.h"
#include "lamina/render/spectral_film.h"
#include "lamina/spectral/cie_xyz_table.h"

namespace lamina::render {

template <SpectrumType S>
class RenderMode;

/// RGB mode: three linear Rec.709 channels; BSDFs are built once per material.
template <>
class RenderMode<Rgb<float>> {
  public:
    using Spectrum = Rgb<float>;
    struct Path {};

    RenderMode(const SceneDesc& scene, std::uint64_t seed) : scene_(scene), seed_(seed) {
        const SpectrumContext<Spectrum> context;
        for (const MaterialDesc& m : scene.materials)
            bsdfs_.push_back(buildBxdf(m, context, seed));
        for (const MediumDesc& m : scene.media) {
            // A medium's emission spectrum, if given, is reduced to RGB as an emitter's is.
            const EmitterColor le(m.emission, m.emissionSpectrum);
            media_.push_back({Spectrum(m.sigmaA), Spectrum(m.sigmaS), le.rgb(), float(m.g),
                              m.emits(), m.grid.get()});
        }
    }

    static constexpr FilmSpace kFilmSpace = FilmSpace::Rec709;
    /// The path integrator renders media in this mode (docs/media.md).
    static constexpr bool kRendersMedia = true;

    Path startPath(PixelSampler&) const { return {}; }
    Spectrum emission(const Emission& e, Path&) const { return e.rgb(); }
    /// Valid until the next call from this thread (see the top of this file).
    const Bxdf<Spectrum>& bsdf(int material, const TexturePoint& at, Path&) const {
        if (!scene_.materialTextures[std::size_t(material)].any())
            return *bsdfs_[std::size_t(material)];
        // A textured material is built at every hit, with its parameters looked up there.
        thread_local std::unique_ptr<Bxdf<Spectrum>> textured;
        textured =
            buildBxdf(texturedMaterial(scene_, material, at), SpectrumContext<Spectrum>{}, seed_);
        return *textured;
    }
    /// The same: the unpolarised modes have no use for the shading frame.
    const Bxdf<Spectrum>& bsdf(int material, const TexturePoint& at, const Frame<float>&,
                               Path& path) const {
        return bsdf(material, at, path);
    }
    Rgb<double> filmValue(const Spectrum& L, const Path&) const { return Rgb<double>(L); }
    /// The coefficients of SceneDesc::media[index].
    const MediumCoefficients<Spectrum>& medium(int index, Path&) const {
        return media_[std::size_t(index)];
    }

  private:
    const SceneDesc& scene_;
    std::uint64_t seed_;
    std::vector<std::unique_ptr<Bxdf<Spectrum>>> bsdfs_;
    std::vector<MediumCoefficients<Spectrum>> media_;
};

/// Spectral mode: four hero wavelengths per path (Wilkie et al. 2014), colours upsampled
/// (reflectances) and emission upsampled as illuminants (so RGB (1, 1, 1) light is D65 and
/// stays white), the film accumulating CIE XYZ:
///   XYZ = 1/N sum_i L(lambda_i) xyz-bar(lambda_i) / (p(lambda_i) integral of y-bar),
/// which gives Y = 1 for a constant spectrum 1, as RGB mode gives luminance 1 for white 1.
/// What does not depend on the wavelengths is done once: each material's RGB colours are
/// upsampled when the mode is made (UpsampledColors), the emitters' spectra and the colour
/// matching functions are resampled at 1 nm (EmitterColor, CieXyzTable).
template <>
class RenderMode<SampledSpectrum<float>> {
  public:
    using Spectrum = SampledSpectrum<float>;
    struct Path {
        SampledWavelengths<float> lambda;
        /// Where lambda falls in the 1 nm tables (emitters, colour matching); a dispersive
        /// event changes only the densities, so it stays valid.
        ResampledSpectrum::Positions<Spectrum::kSize> at;
        std::uint64_t id = 0;  ///< distinguishes paths for the per-thread BSDF cache
    };

    // Every material is built once here, at arbitrary wavelengths, to collect the colours
    // its builds upsample: the paths' builds then find their coefficients in colors_. A
    // build that read no wavelength (grey colours, no spectra) is the BSDF of every path: it
    // is kept and shared, as in RGB mode.
    RenderMode(const SceneDesc& scene, std::uint64_t seed)
        : scene_(scene),
          seed_(seed),
          colors_(scene.materials.size()),
          shared_(scene.materials.size()) {
        for (std::size_t m = 0; m < scene.materials.size(); ++m) {
            SampledWavelengths<float> lambda = SampledWavelengths<float>::sample(0.5);
            bool readsWavelengths = false;
            auto bsdf = buildBxdf(
                scene.materials[m],
                SpectrumContext<Spectrum>{lambda, nullptr, &colors_[m], &readsWavelengths}, seed_);
            if (!readsWavelengths) shared_[m] = std::move(bsdf);
        }
        for (const MediumDesc& m : scene.media)
            media_.push_back(SpectralMedium{
                UnboundedSpectrum(m.sigmaA), UnboundedSpectrum(m.sigmaS),
                EmitterColor(m.emission, m.emissionSpectrum), float(m.g), m.emits(), m.grid.get()});
    }

    static constexpr FilmSpace kFilmSpace = FilmSpace::Xyz;
    /// The path integrator renders media in this mode (docs/media.md).
    static constexpr bool kRendersMedia = true;

    Path startPath(PixelSampler& sampler) const {
        const auto lambda = SampledWavelengths<float>::sample(double(sampler.getWavelength1D()));
        return {lambda, ResampledSpectrum::locate(lambda), ++cache().nextPathId};
    }

    Spectrum emission(const Emission& e, Path& path) const {
        if (!e.color) {  // a texel: upsample once for the four wavelengths
            Spectrum out;
            const RgbSpectrum s(Rgb<double>(e.texel), RgbSpectrumKind::Illuminant);
            for (int i = 0; i < Spectrum::kSize; ++i)
                out[i] = float(s(double(path.lambda[i]))) * e.scale;
            return out;
        }
        return e.color->spectral(path.at) * e.scale;
    }

    // A material's BSDF that depends on the path's wavelengths is built at the first hit on
    // that material along a path and reused at later hits of the same path (a per-thread
    // cache, reset when the path changes); one that does not is the one built at load. Valid
    // until the next call from this thread.
    const Bxdf<Spectrum>& bsdf(int material, const TexturePoint& at, Path& path) const {
        BsdfCache& c = cache();
        const UpsampledColors* colors = &colors_[std::size_t(material)];
        if (scene_.materialTextures[std::size_t(material)].any()) {
            // Colours the textures do not replace are among those collected at load.
            const SpectrumContext<Spectrum> context{path.lambda, colors};
            c.textured = buildBxdf(texturedMaterial(scene_, material, at), context, seed_);
            return *c.textured;
        }
        if (const auto& shared = shared_[std::size_t(material)]) return *shared;
        if (c.pathId != path.id) {
            c.pathId = path.id;
            c.bsdfs.resize(scene_.materials.size());
            for (auto& b : c.bsdfs)
                b.reset();
        }
        auto& slot = c.bsdfs[std::size_t(material)];
        if (!slot) {
            const SpectrumContext<Spectrum> context{path.lambda, colors};
            slot = buildBxdf(scene_.materials[std::size_t(material)], context, seed_);
        }
        return *slot;
    }

    /// The same: the unpolarised modes have no use for the shading frame.
    const Bxdf<Spectrum>& bsdf(int material, const TexturePoint& at, const Frame<float>&,
                               Path& path) const {
        return bsdf(material, at, path);
    }

    Rgb<double> filmValue(const Spectrum& L, const Path& path) const {
        // A wavelength of density 0 (terminated by dispersion) contributes nothing.
        using namespace simd;
        Spectrum w;
        const Spectrum pdf = path.lambda.pdf();
        const Float4 p = load(&pdf[0]);
        store(&w[0], select(p > splat(0.0f), load(&L[0]) / p, splat(0.0f)));
        const std::array<float, 3> xyz = cmf_.weightedSum(w, path.at);
        constexpr double kInverseN = 1.0 / Spectrum::kSize;
        return {double(xyz[0]) * kInverseN, double(xyz[1]) * kInverseN, double(xyz[2]) * kInverseN};
    }
    /// What the spectral film receives from a sample of value L (spectral_film.h).
    SpectralFilmSample filmSpectrum(const Spectrum& L, const Path& path,
                                    const SpectralBins& bins) const {
        return spectralFilmSample(bins, path.lambda, &L, 1);
    }

    /// The coefficients of SceneDesc::media[index] at the path's wavelengths: the RGB
    /// coefficients as unbounded spectra, the emission as an emitter's (an illuminant).
    MediumCoefficients<Spectrum> medium(int index, Path& path) const {
        const SpectralMedium& m = media_[std::size_t(index)];
        MediumCoefficients<Spectrum> out;
        out.sigmaA = m.sigmaA(path.lambda);
        out.sigmaS = m.sigmaS(path.lambda);
        out.emission = m.emission.spectral(path.at);
        out.g = m.g;
        out.emits = m.emits;
        out.grid = m.grid;
        for (int i = 0; i < Spectrum::kSize; ++i)
            out.lambda[std::size_t(i)] = path.lambda[i];
        return out;
    }

  private:
    /// An RGB coefficient upsampled once (RgbSpectrumKind::Unbounded, as SpectrumContext's
    /// unbounded() does for materials); a grey one is exactly its constant.
    struct UnboundedSpectrum {
        explicit UnboundedSpectrum(const Rgb<double>& c)
            : grey(c[0] == c[1] && c[1] == c[2]),
              constant(float(c[0])),
              spectrum(c, RgbSpectrumKind::Unbounded) {}
        Spectrum operator()(const SampledWavelengths<float>& lambda) const {
            if (grey) return Spectrum(constant);
            Spectrum s;
            for (int i = 0; i < Spectrum::kSize; ++i)
                s[i] = float(spectrum(double(lambda[i])));
            return s;
        }
        bool grey;
        float constant;
        RgbSpectrum spectrum;
    };
    struct SpectralMedium {
        UnboundedSpectrum sigmaA, sigmaS;
        EmitterColor emission;
        float g;
        bool emits;
        const GridDensity* grid;
    };

    struct BsdfCache {
        std::uint64_t pathId = 0, nextPathId = 0;
        std::vector<std::unique_ptr<Bxdf<Spectrum>>> bsdfs;
        std::unique_ptr<Bxdf<Spectrum>> textured;
    };
    static BsdfCache& cache() {
        thread_local BsdfCache c;
        return c;
    }

    const SceneDesc& scene_;
    std::uint64_t seed_;
    std::vector<UpsampledColors> colors_;  ///< per material
    /// per material: its BSDF if it does not depend on the wavelengths, else null
    std::vector<std::unique_ptr<Bxdf<Spectrum>>> shared_;
    const CieXyzTable& cmf_ = CieXyzTable::normalized();
    std::vector<SpectralMedium> media_;
};

/// Polarised mode (docs/polarisation.md): the spectral mode's wavelengths, colours, emission and
/// film, with a Mueller matrix per wavelength as the path's throughput (polarised_spectrum.h).
/// The BSDFs are the spectral mode's, seen at each shading point through PolarisedBxdf, which
/// turns their matrices into the world directions' canonical frames; the emitters are
/// unpolarised. The film receives S0, the radiance, as the spectral mode's XYZ. An optical
/// sheet (polariser, retarder) is built at each hit with its world axis in the hit's frame.
template <>
class RenderMode<PolarisedSpectrum> {
  public:
    using Spectrum = PolarisedSpectrum;
    using Path = RenderMode<SampledSpectrum<float>>::Path;

    RenderMode(const SceneDesc& scene, std::uint64_t seed)
        : scene_(scene),
          seed_(seed),
          spectral_(scene, seed),
          analyserDegrees_(scene.camera.analyserDegrees) {
        for (const MaterialDesc& m : scene.materials)
            oriented_.push_back(needsOrientation(m));
    }

    static constexpr FilmSpace kFilmSpace = FilmSpace::Xyz;
    /// Not yet (docs/media.md): the renderer refuses a scene with media in this mode.
    static constexpr bool kRendersMedia = false;

    Path startPath(PixelSampler& sampler) const { return spectral_.startPath(sampler); }
    Spectrum emission(const Emission& e, Path& path) const {
        return depolarising(spectral_.emission(e, path));
    }
    /// Valid until the next call from this thread, as in the spectral mode.
    const Bxdf<Spectrum>& bsdf(int material, const TexturePoint& at, const Frame<float>& frame,
                               Path& path) const {
        thread_local PolarisedBxdf view;
        if (oriented_[std::size_t(material)]) {
            // An optical sheet's axis is a world direction: built at every hit, in its frame.
            thread_local std::unique_ptr<Bxdf<SampledSpectrum<float>>> sheet;
            const Frame<double> f{Vec3d(frame.s), Vec3d(frame.t), Vec3d(frame.n)};
            sheet = buildBxdf(orientedMaterial(scene_.materials[std::size_t(material)], f),
                              SpectrumContext<SampledSpectrum<float>>{path.lambda}, seed_);
            view.bind(*sheet, frame);
            return view;
        }
        view.bind(spectral_.bsdf(material, at, path), frame);
        return view;
    }
    Rgb<double> filmValue(const Spectrum& L, const Path& path) const {
        return spectral_.filmValue(L.unpolarised(), path);
    }
    using Element = Spectrum::Element;
    /// The Stokes vector, at the path's wavelengths, of the light arriving against
    /// `rayDirection` (L's first column: the emitters are unpolarised), turned into the image
    /// frame (x the image's right, projected perpendicular to the light; y = d x x with d the
    /// light's direction, towards the lens) and through the camera's analyser if it has one
    /// (docs/polarisation.md, "Stokes images"). Defined in polarised_film_value.cpp.
    std::array<Element, 4> imageStokes(const Spectrum& L, const Vec3f& rayDirection,
                                       const Vec3f& imageRight) const;
    /// What a camera sample gives the film's Stokes layers (Film::addPolarisedSample): each
    /// component of imageStokes in the film's space, as filmValue converts S0.
    std::array<Rgb<double>, 4> filmStokes(const std::array<Element, 4>& s, const Path& path) const {
        std::array<Rgb<double>, 4> film;
        for (std::size_t i = 0; i < 4; ++i)
            film[i] = spectral_.filmValue(s[i], path);
        return film;
    }
    std::array<Rgb<double>, 4> filmStokes(const Spectrum& L, const Vec3f& rayDirection,
                                          const Vec3f& imageRight, const Path& path) const {
        return filmStokes(imageStokes(L, rayDirection, imageRight), path);
    }
    /// What the spectral film receives: S0..S3 of imageStokes per bin (spectral_film.h).
    SpectralFilmSample filmSpectrum(const std::array<Element, 4>& s, const Path& path,
                                    const SpectralBins& bins) const {
        return spectralFilmSample(bins, path.lambda, s.data(), 4);
    }

  private:
    const SceneDesc& scene_;
    std::uint64_t seed_;
    RenderMode<SampledSpectrum<float>> spectral_;
    std::optional<double> analyserDegrees_;
    std::vector<bool> oriented_;  ///< per material: needsOrientation
};

}  // namespace lamina::render
