#include <cmath>
#include <string>

#include "lamina/core/rectangle_corners.h"
#include "lamina/scene/scene_readers.h"

namespace lamina::render {

std::pair<Rgb<double>, std::shared_ptr<const EmissionSpectrum>> readEmissionValue(
    const JsonReader& parent, const std::string& key) {
    if (!parent.has(key))
        parent.failAt(key, "missing; expected a number >= 0, [r, g, b] or a spectrum object");
    const JsonReader v = parent.child(key);
    if (!v.value().is_object()) {
        const auto rgb = *parent.optionalTriple(key, Range::nonNegative());
        return {Rgb<double>(rgb[0], rgb[1], rgb[2]), nullptr};
    }
    const double scale = v.number("scale", 1.0, Range::nonNegative());
    std::shared_ptr<const EmissionSpectrum> spectrum;
    const int forms = int(v.has("illuminant")) + int(v.has("blackbody")) + int(v.has("spectrum"));
    if (forms != 1) v.fail("expected exactly one of illuminant, blackbody, spectrum");
    try {
        if (v.has("illuminant")) {
            spectrum = std::make_shared<const EmissionSpectrum>(
                EmissionSpectrum::illuminant(v.requiredString("illuminant"), scale));
        } else if (v.has("blackbody")) {
            spectrum = std::make_shared<const EmissionSpectrum>(
                EmissionSpectrum::blackbody(v.requiredNumber("blackbody", {100.0, 1e6}), scale));
        }
    } catch (const InputError& e) {
        v.fail(e.what());
    }
    if (v.has("spectrum")) {
        const JsonReader list = v.child("spectrum");
        const auto [nm, values] = list.wavelengthTable(Range::nonNegative());
        spectrum = std::make_shared<const EmissionSpectrum>(EmissionSpectrum::tabulated(
            nm, values, scale, list.source().name + ": " + list.path()));
    }
    v.finish();
    // The scale times the spectrum is what is rendered, in float.
    const Rgb<double> rgb = spectrum->rgb();
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(float(rgb[c])))
            v.fail("the emission overflows float (scale " + formatNumber(scale) + ")");
    return {rgb, spectrum};
}

std::optional<EmissionDesc> readEmission(const JsonReader& shape) {
    const auto e = shape.optionalChild("emission");
    if (!e) return std::nullopt;
    e->expectObject();
    EmissionDesc d;
    std::tie(d.radiance, d.spectrum) = readEmissionValue(*e, "radiance");
    d.twoSided = e->boolean("two_sided", false);
    e->finish();
    return d;
}

namespace {

// An environment's "transform": directions only, so an orthogonal matrix (rotations, and
// reflections such as pbrt's and Mitsuba's handedness flips); a translation would mean nothing
// at infinity and a scale or shear would distort the map's solid angles, so both are refused.
Mat3<double> readEnvironmentTransform(const JsonReader& r) {
    const Mat4 m = readTransform(r);
    if (Vec3d(m[3]) != Vec3d(0.0))
        r.failAt("transform", "an environment takes rotations only; got a translation");
    const Mat3<double> a(m);
    const Mat3<double> gram = glm::transpose(a) * a;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (std::abs(gram[i][j] - (i == j ? 1.0 : 0.0)) > 1e-9)
                r.failAt("transform",
                         "an environment takes rotations only (and mirror reflections such as a "
                         "scale of [-1, 1, 1]); got a scale or shear");
    return a;
}

// Each kind's reader runs between the type and the check for unknown keys, and reads the
// intensity before the kind's own keys.

PointLightDesc readPointLight(const JsonReader& r) {
    PointLightDesc l;
    std::tie(l.intensity, l.spectrum) = readEmissionValue(r, "intensity");
    l.position = requiredVec3(r, "position");
    checkCoordinates(r, "position", l.position);
    return l;
}

SpotLightDesc readSpotLight(const JsonReader& r) {
    SpotLightDesc l;
    std::tie(l.intensity, l.spectrum) = readEmissionValue(r, "intensity");
    l.position = requiredVec3(r, "position");
    checkCoordinates(r, "position", l.position);
    const Vec3d target = requiredVec3(r, "look_at");
    checkCoordinates(r, "look_at", target);
    if (glm::length(target - l.position) == 0) r.failAt("look_at", "equals position");
    l.direction = glm::normalize(target - l.position);
    l.coneAngle = r.number("cone_angle", 30.0, {0.0, 90.0, true});
    l.falloffStart = r.number("falloff_start", l.coneAngle * 0.8, {0.0, l.coneAngle});
    return l;
}

DirectionalLightDesc readDirectionalLight(const JsonReader& r) {
    DirectionalLightDesc l;
    std::tie(l.intensity, l.spectrum) = readEmissionValue(r, "irradiance");
    l.direction = requiredVec3(r, "direction");
    if (glm::length(l.direction) == 0) r.failAt("direction", "expected a non-zero vector");
    l.direction = glm::normalize(l.direction);
    return l;
}

// A portal: four corners in order around a rectangle. Portal sampling maps directions through
// it by two angles measured in the rectangle's own axes (portal_environment.h), which holds
// only for a rectangle: a parallelogram or a non-planar quadrilateral is refused.
std::array<Vec3d, 4> readPortal(const JsonReader& r) {
    const JsonReader list = r.child("portal");
    if (!list.value().is_array() || list.value().size() != 4)
        list.fail("expected the portal's four corners, [[x, y, z], ...] in order around it");
    std::array<Vec3d, 4> c;
    for (std::size_t i = 0; i < 4; ++i) {
        const auto& v = list.value()[i];
        if (!v.is_array() || v.size() != 3)
            list.fail("expected [x, y, z] at index " + std::to_string(i));
        for (int k = 0; k < 3; ++k)
            c[i][k] = list.checkNumber(v[std::size_t(k)], list.indexPath(i), Range::any());
        checkCoordinates(r, "portal", c[i], "corner " + std::to_string(i));
    }
    if (const auto why = whyNotARectangle(c)) list.fail(*why);
    return c;
}

EnvironmentLightDesc readEnvironmentLight(const JsonReader& r) {
    EnvironmentLightDesc l;
    if (r.has("portal")) l.portal = readPortal(r);
    if (!r.has("file")) {
        std::tie(l.intensity, l.spectrum) = readEmissionValue(r, "radiance");
        return l;
    }
    // An image: "scale" multiplies it, "mapping" lays it on the sphere, "rotate" turns it
    // about +y, then "transform" turns it further.
    if (r.has("radiance")) r.fail("give either radiance or file, not both");
    l.file = r.filePath("file");
    const double scale = r.number("scale", 1.0, Range::nonNegative());
    l.intensity = Rgb<double>(scale);
    l.mapping = r.choice("mapping", EnvironmentMapping::Equirectangular, kEnvironmentMappingNames);
    l.rotation = r.number("rotate", 0.0);
    l.orientation = readEnvironmentTransform(r);
    return l;
}

}  // namespace

LightDesc readLight(const JsonReader& r) {
    r.expectObject();
    LightDesc l;
    switch (r.choice("type", LightKind::Point, kLightKindNames)) {
        case LightKind::Point:
            l = readPointLight(r);
            break;
        case LightKind::Spot:
            l = readSpotLight(r);
            break;
        case LightKind::Directional:
            l = readDirectionalLight(r);
            break;
        case LightKind::Environment:
            l = readEnvironmentLight(r);
            break;
    }
    r.finish();
    return l;
}

}  // namespace lamina::render
