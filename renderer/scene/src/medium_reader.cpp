// "media" (docs/media.md): the named media, the media a shape's surface separates
// ("interior", "exterior") and the camera's "medium".
#include <algorithm>
#include <cmath>

#include "lamina/core/json_reader.h"
#include "lamina/scene/cloud_density.h"
#include "lamina/scene/colour_grid.h"
#include "lamina/scene/grid_file.h"
#include "lamina/scene/scene_readers.h"
#include "lamina/scene/volume_files.h"

namespace lamina::render {

namespace {

// The medium's RGB coefficient at `key` times `scale`: each component >= 0 and finite in
// float after the scale (a path multiplies it by distances).
Rgb<double> readCoefficient(const JsonReader& r, const std::string& key, double scale,
                            double fallback) {
    const auto v = r.triple(key, {fallback, fallback, fallback}, Range::nonNegative());
    const Rgb<double> sigma(v[0] * scale, v[1] * scale, v[2] * scale);
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(float(sigma[c])))
            r.failAt(key, "times scale is " + formatNumber(sigma[c]) +
                              ", beyond float: expected a smaller coefficient or scale");
    return sigma;
}

// A grid's values: a file's name (a lamina grid, a Mitsuba .vol; NanoVDB is read apart, as it
// places itself) or the grid inline.
DensityGrid readGridValues(const JsonReader& r, const std::string& key) {
    if (!r.value().at(key).is_string()) return readInlineGrid(r.child(key));
    const std::filesystem::path path = r.filePath(key);
    if (isMitsubaVolume(path)) return readMitsubaVolume(path).grid;
    return readGridFile(path);
}

bool namesNanoVdb(const JsonReader& r, const std::string& key) {
    return r.value().at(key).is_string() && isNanoVdbFile(r.filePath(key));
}

// "bounds": the box in medium space (default the unit cube, as pbrt-v4's p0 and p1).
void readBounds(const JsonReader& r, GridDensity& grid) {
    const auto bounds = r.optionalChild("bounds");
    if (!bounds) return;
    bounds->expectObject();
    const auto lo = bounds->requiredArray<3>("min"), hi = bounds->requiredArray<3>("max");
    for (int c = 0; c < 3; ++c)
        if (!(float(hi[c]) > float(lo[c])))
            bounds->failAt("max", "expected every coordinate greater than min's, got " +
                                      formatNumber(hi[c]) + " <= " + formatNumber(lo[c]));
    bounds->finish();
    grid.boxMin = Vec3f(float(lo[0]), float(lo[1]), float(lo[2]));
    grid.boxMax = Vec3f(float(hi[0]), float(hi[1]), float(hi[2]));
}

// Medium space -> scene: the rows of the inverse kept for the trackings.
void placeGrid(const JsonReader& r, GridDensity& grid, const Mat4& mediumToWorld) {
    if (mediumToWorld == Mat4(1.0)) return;
    const Mat4 inverse = glm::inverse(mediumToWorld);
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 4; ++col) {
            const double v = inverse[col][row];  // glm is column-major
            if (!std::isfinite(float(v)))
                r.failAt("transform",
                         "cannot be inverted in float: expected a transform that "
                         "places the grid at a finite, non-zero size");
            grid.worldToMedium[row][col] = float(v);
        }
    grid.transformed = true;
}

// A grid medium: its grids (docs/media.md, "Grid media"), box, edges and transform, with its
// majorants. `m`'s coefficients multiply a density grid; with per-cell colour grids they are
// folded into the cells' values.
std::shared_ptr<const GridDensity> readGrid(const JsonReader& r, MediumDesc& m, bool hasSigmaA,
                                            bool hasSigmaS) {
    auto grid = std::make_shared<GridDensity>();
    const bool colourKeys = r.has("sigma_a_grid") || r.has("sigma_s_grid");
    if (colourKeys && r.has("density"))
        r.failAt("density",
                 "a grid medium has a density grid or sigma_a_grid / sigma_s_grid, "
                 "not both");
    if (!colourKeys && !r.has("density"))
        r.failAt("density",
                 "missing; expected a grid file's name or {\"size\": [nx, ny, nz], "
                 "\"values\": [...]} (or sigma_a_grid / sigma_s_grid)");
    const bool zero = r.string("edges", "clamp") == "zero";
    if (r.has("edges") && !zero && r.string("edges", "") != "clamp")
        r.failAt("edges", "expected \"clamp\" or \"zero\", got \"" + r.string("edges", "") + "\"");
    Mat4 mediumToWorld = readTransform(r);
    if (!colourKeys && namesNanoVdb(r, "density")) {
        // A NanoVDB grid places itself: its index box through its own map, then `transform`.
        if (r.has("bounds"))
            r.failAt("bounds", "a NanoVDB grid's box is its own (give a transform instead)");
        NanoVdbGrid nano = readNanoVdbFile(r.filePath("density"), "density");
        grid->density = std::move(nano.grid);
        grid->boxMin = Vec3f(nano.indexMin);
        grid->boxMax = Vec3f(nano.indexMax);
        mediumToWorld = mediumToWorld * nano.indexToWorld;
    } else {
        readBounds(r, *grid);
        if (!colourKeys) grid->density = readGridValues(r, "density");
    }
    placeGrid(r, *grid, mediumToWorld);
    if (colourKeys || grid->density.channels == 3) {
        // The cells' RGB coefficients: a grid times its constant, or the constant alone (the
        // same everywhere in the box) where a coefficient has no grid.
        auto colours = std::make_shared<ColourGrids>();
        const auto channel = [&](const char* key, const Rgb<double>& sigma, bool given) {
            if (!colourKeys) return ColourGrid::fromGrid(grid->density, sigma);
            if (!r.has(key)) return ColourGrid::constant(given ? sigma : Rgb<double>(0.0));
            DensityGrid g = readGridValues(r, key);
            g.zeroOutside = zero;
            return ColourGrid::fromGrid(g, sigma);
        };
        grid->density.zeroOutside = zero;
        colours->sigmaA = channel("sigma_a_grid", m.sigmaA, hasSigmaA || r.has("sigma_a_grid"));
        colours->sigmaS = channel("sigma_s_grid", m.sigmaS, hasSigmaS || r.has("sigma_s_grid"));
        grid->majorants = colours->majorants();
        float largest = 0.0f;
        for (const float v : grid->majorants.maxima)
            largest = std::max(largest, v);
        if (!std::isfinite(largest))
            r.failAt(
                colourKeys ? (r.has("sigma_a_grid") ? "sigma_a_grid" : "sigma_s_grid") : "density",
                "the largest sigma_a + sigma_s is beyond float: expected smaller values");
        grid->colours = std::move(colours);
        grid->density = DensityGrid{};
        grid->density.values = {0.0f};
        return grid;
    }
    grid->density.zeroOutside = zero;
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

// A cloud medium (docs/media.md, "Procedural clouds"): pbrt-v4's procedural density over its
// box, evaluated at every lookup, with majorants along y. Its cost does not depend on the
// numbers (a fixed number of noise lookups per point, a fixed majorant grid).
std::shared_ptr<const GridDensity> readCloud(const JsonReader& r) {
    auto grid = std::make_shared<GridDensity>();
    readBounds(r, *grid);
    placeGrid(r, *grid, readTransform(r));
    auto cloud = std::make_shared<CloudDensity>();
    cloud->density = float(r.number("density", 1.0, Range::nonNegative()));
    cloud->wispiness = float(r.number("wispiness", 1.0));
    cloud->frequency = float(r.number("frequency", 5.0));
    grid->majorants = cloud->majorants(grid->boxMin, grid->boxMax);
    grid->density.values = {0.0f};  // unused: the cloud is the density
    grid->cloud = std::move(cloud);
    return grid;
}

// Keys of other kinds of media, refused on `type`'s.
void refuseKeys(const JsonReader& r, std::initializer_list<const char*> keys, const char* owner,
                const std::string& type) {
    for (const char* key : keys)
        if (r.has(key))
            r.failAt(key, std::string("is a key of ") + owner + " media; this medium is \"" + type +
                              "\"");
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
    // A coefficient that multiplies its own grid (sigma_a_grid, sigma_s_grid) is 1 by default.
    m.sigmaA = readCoefficient(r, "sigma_a", scale, r.has("sigma_a_grid") ? 1.0 : 0.0);
    m.sigmaS = readCoefficient(r, "sigma_s", scale, r.has("sigma_s_grid") ? 1.0 : 0.0);
    // |g| = 1 is a delta phase function (every scattering straight on or straight back),
    // which the Henyey-Greenstein density cannot express.
    m.g = r.number("g", 0.0, {-1.0, 1.0, true, true});
    if (r.has("Le")) std::tie(m.emission, m.emissionSpectrum) = readEmissionValue(r, "Le");
    if (m.kind == MediumKind::Grid) {
        m.grid = readGrid(r, m, r.has("sigma_a"), r.has("sigma_s"));
        if (m.grid->colours) {
            // The cells carry the coefficients; the medium's own are the majorants' unit.
            m.sigmaA = Rgb<double>(0.0);
            m.sigmaS = Rgb<double>(0.0);
        }
    } else if (m.kind == MediumKind::Cloud) {
        refuseKeys(r, {"sigma_a_grid", "sigma_s_grid", "edges"}, "grid", type);
        m.grid = readCloud(r);
    } else {
        refuseKeys(r, {"density", "sigma_a_grid", "sigma_s_grid", "edges", "bounds"}, "grid", type);
        refuseKeys(r, {"wispiness", "frequency"}, "cloud", type);
    }
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
