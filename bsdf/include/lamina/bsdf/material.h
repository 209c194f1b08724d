// Material descriptions: the JSON objects of docs/bsdf.md ("Materials"), parsed and validated
// once, independent of the rendering mode. `buildBxdf` (material_builder.h) turns one into a
// BSDF of either variant. Colours are linear Rec.709 triples; what a colour means in spectral
// mode is decided by the builder's SpectrumContext.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "lamina/bsdf/albedo_table.h"
#include "lamina/bsdf/diffuse.h"
#include "lamina/bsdf/layered.h"
#include "lamina/bsdf/microfacet_distribution.h"
#include "lamina/core/name_table.h"
#include "lamina/core/spectrum.h"
#include "lamina/spectral/ior_spectrum.h"
#include "lamina/spectral/nk_table.h"

namespace lamina {

// Declared only: the JSON library is the costliest header of the build, and most files that
// use materials never parse one (bsdf/src/*_reader.cpp include core/json_reader.h).
class JsonReader;

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

struct ConductorMaterial;

/// `standard`: the article's material (and its generalisations); see docs/bsdf.md.
struct StandardMaterial {
    ColorInput baseColor{RgbInput(0.8)};
    double metalness = 0;
    double specular = 0.04;                 ///< F0 of the dielectric part
    std::optional<RgbInput> specularColor;  ///< specular workflow: F0 directly
    std::optional<RgbInput> f82;            ///< absolute reflectance at cos = 1/7
    std::optional<RgbInput> f82Tint;        ///< multiplier of Schlick at cos = 1/7
    double transmission = 0;
    double ior = 1.5;
    std::optional<DiffuseModel> diffuse = DiffuseModel::Lambert;  ///< nullopt: none
    bool specularLobe = true;
    bool phong = false;  ///< the article's Phong lobe instead of a microfacet one
    /// Perceptual roughness of the diffuse models (`layered` sets it; `standard` uses the
    /// specular roughness, as the article does).
    std::optional<double> diffuseRoughness;
    MicrofacetParams microfacet;
    FresnelChoice fresnel = FresnelChoice::SchlickShadowed;
    LayerCoupling coupling = LayerCoupling::Fresnel;
    /// Albedo coupling: the directional albedo of the specular interface (RGB average).
    std::shared_ptr<const AlbedoTable> interfaceAlbedo;
    /// `layered` with a conductor base: the conductor under the interface (its optics relative
    /// to the interface's medium of index `ior`), in place of the diffuse base.
    std::shared_ptr<const ConductorMaterial> conductorBase;
};

/// `lambert`, `oren_nayar`, `burley`, `frostbite`.
struct DiffuseMaterial {
    DiffuseModel model = DiffuseModel::Lambert;
    ColorInput reflectance{RgbInput(0.5)};
    double roughness = 0;  ///< perceptual
};

/// `thin_film` of a conductor or dielectric: a film of real index `ior` and thickness
/// `thicknessNm` on the outside of the interface (thin_film.h). The thickness limit keeps the
/// film thin: beyond some microns its fringes average out to the incoherent sum anyway.
struct ThinFilmParams {
    double thicknessNm = 0;
    double ior = 1.33;
    static constexpr double kMaxThicknessNm = 10000;
    static constexpr double kMaxIor = 5;
};

/// A conductor's optics: exactly one form.
struct ConductorOptics {
    /// EtaK: numbers per channel; F0F82: reflectances; Spectral: n, k as functions of
    /// wavelength (a named metal or an n/k file), with its RGB-mode reductions precomputed.
    enum class Form { EtaK, F0F82, Spectral };
    Form form = Form::EtaK;
    RgbInput eta{0.2};            ///< EtaK: real part of the relative index (per channel)
    RgbInput k{3.9};              ///< EtaK: imaginary part
    RgbInput f0{0.9};             ///< F0F82: normal-incidence reflectance
    std::optional<RgbInput> f82;  ///< F0F82: reflectance at cos = 1/7 (absent: plain Schlick)
    std::shared_ptr<const IorSpectrum> spectrum;  ///< Spectral (f0 and f82 hold its reductions)
    /// Spectral: `spectrum` tabulated at 1 nm, what spectral mode evaluates at every path's
    /// wavelengths. Without it (a description built by hand) the spectrum is evaluated
    /// directly.
    std::shared_ptr<const NkTable> table;
    /// Spectral optics from n, k: the table and the RGB-mode reductions F0, F82 with it.
    static ConductorOptics fromSpectrum(std::shared_ptr<const IorSpectrum> spectrum);
};

/// `conductor`. Fresnel: Auto is exact for eta/k optics and Hoffman's F82 for f0/f82.
struct ConductorMaterial {
    ConductorOptics optics;
    MicrofacetParams microfacet;
    FresnelChoice fresnel = FresnelChoice::Auto;
    std::optional<ThinFilmParams> thinFilm;  ///< needs n, k optics and the exact Fresnel
};

/// `dielectric`: a boundary between outside (index 1) and inside (index ior).
struct DielectricMaterial {
    double ior = 1.5;  ///< the RGB-mode index (n at 587.56 nm for a dispersive glass)
    std::shared_ptr<const IorSpectrum> spectrum;  ///< a named glass or an ior_file
    MicrofacetParams microfacet;
    std::optional<ThinFilmParams> thinFilm;
};

/// `diffuse_transmission`: Lambertian reflection and transmission (diffuse_transmission.h).
/// Defaults are pbrt-v4's.
struct DiffuseTransmissionMaterial {
    ColorInput reflectance{RgbInput(0.25)};
    ColorInput transmittance{RgbInput(0.25)};
};

/// `thin_dielectric`: a thin slab of glass (thin_dielectric.h); ior as `dielectric` reads it.
struct ThinDielectricMaterial {
    double ior = 1.5;  ///< the RGB-mode index (n at 587.56 nm for a dispersive glass)
    std::shared_ptr<const IorSpectrum> spectrum;  ///< a named glass or an ior_file
};

/// `phong`: the article's Phong lobe alone.
struct PhongMaterial {
    ColorInput reflectance{RgbInput(0.5)};
    double shininess = 0;
};

struct MaterialDesc;

/// `mix`: (1 - weight) a + weight b.
struct MixMaterial {
    std::shared_ptr<const MaterialDesc> a, b;
    double weight = 0.5;
};

/// `coated`: a dielectric coat over a base without transmission, with an optional medium
/// between them; evaluated by a random walk (coated.h).
struct CoatedMaterial {
    double ior = 1.5;
    MicrofacetParams microfacet;  ///< the coat's roughness (0: smooth)
    std::shared_ptr<const MaterialDesc> base;
    double thickness = 0;  ///< optical thickness of the medium at normal incidence; 0: none
    ColorInput albedo{RgbInput(0.0)};  ///< single-scattering albedo of the medium
    double g = 0;                      ///< Henyey-Greenstein asymmetry
    int maxDepth = 0;  ///< the most events of a walk; 0: no cap (Russian roulette ends it)
    int samples = 1;
};

/// `polariser`: an ideal linear polariser sheet (optical_sheet.h). `axis`: the transmission
/// axis, in the world as the scene gives it, in the shading frame once the polarised mode has
/// turned it (MaterialKind::orient); unit length.
struct PolariserMaterial {
    Vec3d axis{1, 0, 0};
    double transmittance = 1;  ///< of light polarised along the axis
};

/// `retarder`: an ideal linear retarder sheet, a wave plate (optical_sheet.h). `axis`: the fast
/// axis, as PolariserMaterial's.
struct RetarderMaterial {
    Vec3d axis{1, 0, 0};
    double retardanceDegrees = 90;  ///< the slow component's lag, at every wavelength
};

using MaterialModel =
    std::variant<StandardMaterial, DiffuseMaterial, ConductorMaterial, DielectricMaterial,
                 PhongMaterial, MixMaterial, CoatedMaterial, DiffuseTransmissionMaterial,
                 ThinDielectricMaterial, PolariserMaterial, RetarderMaterial>;

struct MaterialDesc {
    std::string type;  ///< the JSON "type", for messages and `lamina info`
    MaterialModel model;
};

/// The material types parseMaterial accepts, in the order its messages list them.
std::vector<std::string> materialTypeNames();

/// Parses and validates one material object ({"type": ..., ...}); unknown types, unknown keys
/// and out-of-range values are InputErrors naming the JSON path.
MaterialDesc parseMaterial(const JsonReader& reader);

/// Parses a material given on a command line: a JSON object literal or "@file.json".
MaterialDesc parseMaterialArgument(const std::string& argument);

}  // namespace lamina
