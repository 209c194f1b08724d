// "media" (docs/media.md): the named media, the media a shape's surface separates
// ("interior", "exterior") and the camera's "medium".
#include <algorithm>
#include <cmath>

#include "lamina/core/json_reader.h"
#include "lamina/scene/grid_file.h"
#include "lamina/scene/scene_readers.h"

namespace lamina::render {

namespace {

// The medium's RGB coefficient at `key` times `scale`: each component >= 0 and finite in
// float after the scale (a path multiplies it by distances).
Rgb<double> readCoefficient(const JsonReader& r, const std::string& key, double scale) {
    const auto v = r.triple(key, {0.0, 0.0, 0.0}, Range::nonNegative());
    const Rgb<double> sigma(v[0] * scale, v[1] * scale, v[2] * scale);
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(float(sigma[c])))
            r.failAt(key, "times scale is " + formatNumber(sigma[c]) +
                              ", beyond float: expected a smaller coefficient or scale");
    return sigma;
}

// A grid medium's "density" (a grid file's name, or the grid inline) over its "bounds"
// (default the unit cube, as pbrt-v4's uniformgrid's p0 and p1), with its majorants.
std::shared_ptr<const GridDensity> readGrid(const JsonReader& r, const MediumDesc& m) {
    auto grid = std::make_shared<GridDensity>();
    if (!r.has("density"))
        r.failAt("density",
                 "missing; expected a grid file's name or {\"size\": [nx, ny, nz], "
                 "\"values\": [...]}");
    grid->density = r.value().at("density").is_string() ? readGridFile(r.filePath("density"))
                                                        : readInlineGrid(r.child("density"));
    if (const auto bounds = r.optionalChild("bounds")) {
        bounds->expectObject();
        const auto lo = bounds->requiredArray<3>("min"), hi = bounds->requiredArray<3>("max");
        for (int c = 0; c < 3; ++c)
            if (!(float(hi[c]) > float(lo[c])))
                bounds->failAt("max", "expected every coordinate greater than min's, got " +
                                          formatNumber(hi[c]) + " <= " + formatNumber(lo[c]));
        bounds->finish();
        grid->boxMin = Vec3f(float(lo[0]), float(lo[1]), float(lo[2]));
        grid->boxMax = Vec3f(float(hi[0]), float(hi[1]), float(hi[2]));
    }
    float densest = 0.0f;
    for (const float v : grid->density.values)
        densest = std::max(densest, v);
    // The majorants are the densest value times sigma_t: a path multiplies them by distances.
    const Rgb<double> sigmaT = m.sigmaA + m.sigmaS;
    if (!std::isfinite(float(double(densest) * sigmaT.maxValue())))
        r.failAt("density", "the largest density " + formatNumber(densest) +
                                " times sigma_a + sigma_s is beyond float: expected smaller "
                                "densities or coefficients");
    grid->majorants = MajorantGrid::build(grid->density);
    return grid;
}

MediumDesc readMedium(const JsonReader& r, const std::string& name) {
    r.expectObject();
    MediumDesc m;
    m.name = name;
    r.noteNames("type", kMediumKindNames.names());
    const std::string type = r.requiredString("type");
    const auto kind = kMediumKindNames.find(type);
    if (!kind)
        r.failAt("type", "expected one of " + kMediumKindNames.list() + "; got \"" + type + "\"");
    m.kind = *kind;
    const double scale = r.number("scale", 1.0, Range::nonNegative());
    m.sigmaA = readCoefficient(r, "sigma_a", scale);
    m.sigmaS = readCoefficient(r, "sigma_s", scale);
    // |g| = 1 is a delta phase function (every scattering straight on or straight back),
    // which the Henyey-Greenstein density cannot express.
    m.g = r.number("g", 0.0, {-1.0, 1.0, true, true});
    if (r.has("Le")) std::tie(m.emission, m.emissionSpectrum) = readEmissionValue(r, "Le");
    if (m.kind == MediumKind::Grid) m.grid = readGrid(r, m);
    r.finish();
    return m;
}

}  // namespace

void readMedia(const JsonReader& media, SceneDesc& scene) {
    media.expectObject();
    for (const auto& [name, value] : media.value().items()) {
        if (name == kVacuumMediumName)
            media.failAt(name, "\"vacuum\" is the name of no medium; choose another name");
        scene.media.push_back(readMedium(media.child(name), name));
    }
    media.finish();
}

int mediumIndex(const JsonReader& at, const std::string& key,
                const std::vector<MediumDesc>& media) {
    const std::string name = at.requiredString(key);
    if (name == kVacuumMediumName) return -1;
    for (std::size_t i = 0; i < media.size(); ++i)
        if (media[i].name == name) return int(i);
    std::string known;
    for (const MediumDesc& m : media)
        known += (known.empty() ? "" : ", ") + m.name;
    at.failAt(key, "unknown medium \"" + name + "\"" +
                       (known.empty() ? " (the scene defines no media)" : "; defined: " + known) +
                       " (or \"vacuum\")");
}

std::optional<MediumInterfaceDesc> readMediumInterface(const JsonReader& shape,
                                                       const std::vector<MediumDesc>& media) {
    if (!shape.has("interior") && !shape.has("exterior")) return std::nullopt;
    MediumInterfaceDesc m;
    if (shape.has("interior")) m.interior = mediumIndex(shape, "interior", media);
    if (shape.has("exterior")) m.exterior = mediumIndex(shape, "exterior", media);
    return m;
}

bool SceneDesc::hasMedia() const {
    const auto touches = [](const ShapeDesc& s) {
        const SurfaceDesc& surface = render::surface(s);
        return surface.isInterface() || surface.media.has_value();
    };
    if (!media.empty() || camera.medium >= 0) return true;
    if (std::any_of(shapes.begin(), shapes.end(), touches)) return true;
    return std::any_of(objects.begin(), objects.end(), [&](const ObjectDesc& o) {
        return std::any_of(o.shapes.begin(), o.shapes.end(), touches);
    });
}

}  // namespace lamina::render
