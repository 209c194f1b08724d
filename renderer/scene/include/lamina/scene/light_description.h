// The lights of a scene that are not shapes (docs/scene-format.md, "lights"), as the reader
// leaves them: one std::variant of kinds, each kind a struct with only its own fields on top
// of what every light has (LightIntensityDesc). A new kind of light is a LightKind value with
// its name, a struct here as the matching alternative of LightDesc, its reader
// (light_reader.cpp) and one case where the light set makes lights (light_set.cpp).
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <type_traits>
#include <variant>

#include "lamina/core/name_table.h"
#include "lamina/core/vector.h"
#include "lamina/spectral/emission_spectrum.h"

namespace lamina::render {

/// The `type` of a scene file's light; the values are in the order of LightDesc's alternatives.
enum class LightKind { Point, Spot, Directional, Environment };
inline constexpr NameTable kLightKindNames{
    std::array{NameEntry{LightKind::Point, "point"}, NameEntry{LightKind::Spot, "spot"},
               NameEntry{LightKind::Directional, "directional"},
               NameEntry{LightKind::Environment, "environment"}}};

/// How an environment image covers the sphere (environment_map.h).
enum class EnvironmentMapping { Equirectangular, EqualAreaOctahedral };
inline constexpr NameTable kEnvironmentMappingNames{
    std::array{NameEntry{EnvironmentMapping::Equirectangular, "equirectangular"},
               NameEntry{EnvironmentMapping::EqualAreaOctahedral, "equal_area_octahedral"}}};

/// What every light has: how strong it is, in its kind's unit.
struct LightIntensityDesc {
    /// point, spot: intensity, W/sr; directional: irradiance; environment: radiance (an
    /// image's: its scale)
    Rgb<double> intensity{1.0};
    std::shared_ptr<const EmissionSpectrum> spectrum;  ///< set: the intensity is this spectrum
};

struct PointLightDesc : LightIntensityDesc {
    Vec3<double> position{0.0};
};

struct SpotLightDesc : LightIntensityDesc {
    Vec3<double> position{0.0};
    Vec3<double> direction{0, -1, 0};  ///< the cone's axis, unit
    double coneAngle = 30;             ///< half-angle of the cone, degrees
    double falloffStart = 25;          ///< half-angle where the smooth falloff begins, degrees
};

struct DirectionalLightDesc : LightIntensityDesc {
    Vec3<double> direction{0, -1, 0};  ///< the direction light travels, unit
};

/// A constant radiance from every direction, or an image around the scene (`file` set; the
/// intensity scales it).
struct EnvironmentLightDesc : LightIntensityDesc {
    std::filesystem::path file;
    EnvironmentMapping mapping = EnvironmentMapping::Equirectangular;
    double rotation = 0;  ///< rotation of the image about +y, degrees
    /// the `transform` (an orthogonal matrix), applied after `rotation`
    Mat3<double> orientation{1.0};
    /// A rectangle (world corners in order around it) the environment is seen through, and
    /// only through (pbrt-v4's portal; portal_environment.h); the environment lies on the side
    /// of (c3 - c0) x (c1 - c0).
    std::optional<std::array<Vec3<double>, 4>> portal;
};

/// One light that is not a shape.
using LightDesc =
    std::variant<PointLightDesc, SpotLightDesc, DirectionalLightDesc, EnvironmentLightDesc>;

static_assert(std::variant_size_v<LightDesc> == kLightKindNames.entries().size());
static_assert(std::is_same_v<std::variant_alternative_t<std::size_t(LightKind::Point), LightDesc>,
                             PointLightDesc>);
static_assert(std::is_same_v<std::variant_alternative_t<std::size_t(LightKind::Spot), LightDesc>,
                             SpotLightDesc>);
static_assert(
    std::is_same_v<std::variant_alternative_t<std::size_t(LightKind::Directional), LightDesc>,
                   DirectionalLightDesc>);
static_assert(
    std::is_same_v<std::variant_alternative_t<std::size_t(LightKind::Environment), LightDesc>,
                   EnvironmentLightDesc>);

/// The light's kind, the name of its `type` in kLightKindNames.
inline LightKind lightKind(const LightDesc& light) {
    return LightKind(light.index());
}

/// The fields every kind has.
inline const LightIntensityDesc& lightIntensity(const LightDesc& light) {
    return std::visit([](const LightIntensityDesc& l) -> const LightIntensityDesc& { return l; },
                      light);
}

}  // namespace lamina::render
