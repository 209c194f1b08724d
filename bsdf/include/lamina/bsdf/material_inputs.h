// The inputs material descriptions share: colours (RGB or a reflectance spectrum), the
// microfacet switches of every rough lobe, the Fresnel and specular-model choices and a thin
// film's parameters. Each material type's description lives in its BSDF header (material.h
// says how a description becomes a BSDF); these are the words they are written in.
#pragma once

#include <functional>
#include <memory>
#include <optional>

#include "lamina/bsdf/albedo_table.h"
#include "lamina/bsdf/microfacet_distribution.h"
#include "lamina/core/name_table.h"
#include "lamina/core/spectrum.h"

namespace lamina {

using RgbInput = Rgb<double>;

/// A reflectance input: a linear Rec.709 colour, or a reflectance spectrum (values in [0, 1]
/// per nm) with its colour under D65 as the RGB-mode value.
struct ColorInput {
    RgbInput rgb{0.0};
    std::shared_ptr<const std::function<double(double)>> spectrum;

    ColorInput() = default;
    ColorInput(const RgbInput& c) : rgb(c) {}  // NOLINT: a colour is a colour input
};

/// The microfacet switches shared by every rough lobe.
struct MicrofacetParams {
    NdfKind ndf = NdfKind::Ggx;
    double alphaX = 0;
    double alphaY = 0;
    G2Form g2 = G2Form::HeightCorrelated;
    MicrofacetSampling sampling = MicrofacetSampling::VisibleNormals;
    /// Kulla-Conty multiple-scattering compensation, with the F = 1 albedo table it needs.
    bool multiscatter = false;
    std::shared_ptr<const AlbedoTable> energyF1;

    /// Perceptual roughness for the diffuse models (sqrt of the mean alpha).
    double perceptualRoughness() const;
};

/// The `fresnel` of a material. Auto: the conductor's default (exact for n, k optics, Hoffman's
/// F82 for f0 / f82); `standard` and `layered` do not take it.
enum class FresnelChoice { Auto, Schlick, SchlickShadowed, SchlickSphericalGaussian, F82, Exact };
inline constexpr NameTable kFresnelChoiceNames{
    std::array{NameEntry{FresnelChoice::Schlick, "schlick"},
               NameEntry{FresnelChoice::SchlickShadowed, "schlick_shadowed"},
               NameEntry{FresnelChoice::SchlickSphericalGaussian, "schlick_sg"},
               NameEntry{FresnelChoice::F82, "f82"}, NameEntry{FresnelChoice::Exact, "exact"},
               NameEntry{FresnelChoice::Auto, "auto"}}};

/// The lobe of a specular interface: the `specular_model` of `standard` (which also takes
/// "none") and the `model` of a `layered` interface.
enum class SpecularModel { Ggx, Beckmann, Phong };
inline constexpr NameTable kSpecularModelNames{
    std::array{NameEntry{SpecularModel::Ggx, "ggx"}, NameEntry{SpecularModel::Beckmann, "beckmann"},
               NameEntry{SpecularModel::Phong, "phong"}}};

/// `thin_film` of a conductor or dielectric: a film of real index `ior` and thickness
/// `thicknessNm` on the outside of the interface (thin_film.h). The thickness limit keeps the
/// film thin: beyond some microns its fringes average out to the incoherent sum anyway.
struct ThinFilmParams {
    double thicknessNm = 0;
    double ior = 1.33;
    static constexpr double kMaxThicknessNm = 10000;
    static constexpr double kMaxIor = 5;
};

}  // namespace lamina
