// The types of the BSDF interface (docs/bsdf.md, "Interface").
#pragma once

#include <cstdint>
#include <string>

#include "lamina/core/name_table.h"
#include "lamina/core/spectrum.h"
#include "lamina/core/vector.h"

namespace lamina {

/// Which quantity a path carries. Refraction scales radiance by 1/eta^2 but not importance
/// (Veach 1997, section 5.2); evaluating in the wrong mode makes light tracing and camera
/// tracing disagree.
enum class TransportMode { Radiance, Importance };
inline constexpr NameTable kTransportModeNames{
    std::array{NameEntry{TransportMode::Radiance, "radiance"},
               NameEntry{TransportMode::Importance, "importance"}}};

/// Lobe flags: what kind of scattering a lobe or a sample is. A sample has exactly one kind
/// (one of kLobeKindNames); a BSDF's flags are the union of its lobes' kinds. A kind is its
/// component bits (reflection or transmission; diffuse, glossy or specular) plus a bit of its
/// own, so that a union names its kinds exactly: diffuse reflection with glossy transmission
/// holds the component bits of diffuse transmission, but not its kind bit.
enum LobeFlags : std::uint32_t {
    kLobeNone = 0,
    kLobeReflection = 1u << 0,
    kLobeTransmission = 1u << 1,
    kLobeDiffuse = 1u << 2,
    kLobeGlossy = 1u << 3,
    kLobeSpecular = 1u << 4,  ///< a Dirac delta: never evaluated by eval() or pdf()
    kLobeDiffuseReflection = kLobeDiffuse | kLobeReflection | (1u << 5),
    kLobeGlossyReflection = kLobeGlossy | kLobeReflection | (1u << 6),
    kLobeSpecularReflection = kLobeSpecular | kLobeReflection | (1u << 7),
    kLobeDiffuseTransmission = kLobeDiffuse | kLobeTransmission | (1u << 8),
    kLobeGlossyTransmission = kLobeGlossy | kLobeTransmission | (1u << 9),
    kLobeSpecularTransmission = kLobeSpecular | kLobeTransmission | (1u << 10),
    kLobeAll = kLobeDiffuseReflection | kLobeGlossyReflection | kLobeSpecularReflection |
               kLobeDiffuseTransmission | kLobeGlossyTransmission | kLobeSpecularTransmission,
};

/// The kinds of lobe lamina has, in the order descriptions list them.
inline constexpr NameTable kLobeKindNames{
    std::array{NameEntry{kLobeDiffuseReflection, "diffuse_reflection"},
               NameEntry{kLobeGlossyReflection, "glossy_reflection"},
               NameEntry{kLobeSpecularReflection, "specular_reflection"},
               NameEntry{kLobeDiffuseTransmission, "diffuse_transmission"},
               NameEntry{kLobeGlossyTransmission, "glossy_transmission"},
               NameEntry{kLobeSpecularTransmission, "specular_transmission"}}};

/// The lobe kinds a flags word holds, in words: "diffuse reflection, glossy transmission";
/// "none (black)" for a BSDF without lobes.
std::string describeLobes(std::uint32_t flags);

/// The reflection kinds of a flags word (what a BSDF that closes off transmission keeps).
inline std::uint32_t reflectionKinds(std::uint32_t f) {
    std::uint32_t out = kLobeNone;
    for (const auto k : {kLobeDiffuseReflection, kLobeGlossyReflection, kLobeSpecularReflection})
        if ((f & k) == k) out |= k;
    return out;
}

inline bool isSpecular(std::uint32_t f) {
    return (f & kLobeSpecular) != 0;
}
inline bool isTransmission(std::uint32_t f) {
    return (f & kLobeTransmission) != 0;
}
inline bool isReflection(std::uint32_t f) {
    return (f & kLobeReflection) != 0;
}

/// What sample() returns: the article's evalIndirect.
template <SpectrumType S>
struct BsdfSample {
    using Float = typename S::Float;
    Vec3<Float> wi{0, 0, 1};
    /// eval(wo, wi) / pdf(wo, wi) for the whole BSDF; for a delta lobe, the lobe's
    /// f * |cos| / (discrete probability of choosing it).
    S weight{};
    /// Solid-angle density of wi (mixture over lobes), or the discrete probability of the
    /// chosen delta lobe times the probabilities of delta choices.
    Float pdf = 0;
    /// The sampled lobe's LobeFlags (every kind fits in 16 bits).
    std::uint16_t flags = kLobeNone;
    /// Which material of each enclosing `mix` drew a delta sample, one bit per mix, the
    /// outermost in bit 0 (mix.h): the polarised mode hands the sample back to the material
    /// that drew it for its Mueller matrix (Bxdf::sampleMueller). 0 from every other BSDF.
    std::uint16_t component = 0;
    /// Relative index of refraction across the boundary along the sampled direction
    /// (eta_transmitted / eta_incident); 1 for reflection.
    Float eta = 1;

    BsdfSample() = default;
    BsdfSample(const Vec3<Float>& wi, const S& weight, Float pdf, std::uint32_t flags, Float eta,
               std::uint16_t component = 0)
        : wi(wi),
          weight(weight),
          pdf(pdf),
          flags(std::uint16_t(flags)),
          component(component),
          eta(eta) {}

    bool isSpecular() const { return lamina::isSpecular(flags); }
    bool isTransmission() const { return lamina::isTransmission(flags); }
};

static_assert(kLobeAll <= 0xFFFFu, "BsdfSample::flags holds every lobe kind in 16 bits");

/// What a single reflection lobe's sampler returns (microfacet, Phong): the direction, the
/// lobe's own eval / pdf, and its density. The BSDFs combine these into BsdfSample.
template <SpectrumType S>
struct LobeSample {
    Vec3<typename S::Float> wi;
    S weight;
    typename S::Float pdf;
};

}  // namespace lamina
