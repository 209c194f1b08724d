// pbrt-v4's grid media -> lamina's grid media (docs/interchange.md, "Media"), read as pbrt-v4's
// media.cpp reads them (GridMedium, RGBGridMedium, NanoVDBMedium), and its procedural
// CloudMedium -> lamina's cloud medium (the same density, cloud_density.h). Every grid is placed by
// the transform in effect at MakeNamedMedium (pbrt-v4's renderFromMedium), and pbrt-v4's grids read
// 0 beyond their outermost values (SampledGrid), which is lamina's `"edges": "zero"`.
#include <cmath>

#include "pbrt_shapes.h"
#include "pbrt_translation.h"

namespace lamina::render::pbrt {

namespace {

/// nx, ny, nz (default 1 each), checked against the values given.
Json gridSize(const ParamList& params, const Param& values, std::size_t count) {
    const int n[3] = {params.integer("nx", 1), params.integer("ny", 1), params.integer("nz", 1)};
    for (const int v : n)
        if (v < 1) params.fail(values, "nx, ny and nz must be >= 1");
    if (std::size_t(n[0]) * std::size_t(n[1]) * std::size_t(n[2]) != count)
        params.fail(values,
                    "has " + std::to_string(count) + " values; expected nx * ny * nz = " +
                        std::to_string(std::size_t(n[0]) * std::size_t(n[1]) * std::size_t(n[2])));
    return Json::array({n[0], n[1], n[2]});
}

/// The values of an array parameter, each finite and >= 0.
std::vector<double> gridValues(const ParamList& params, const std::string& name,
                               const std::string& type, std::size_t arity) {
    const auto values = params.numbers(name, {type}, arity);
    if (!values || values->empty()) return {};
    for (const double v : *values)
        if (!(v >= 0) || !std::isfinite(v))
            params.fail(*params.find(name), "values must be finite and >= 0");
    return *values;
}

/// p0 and p1: the box in medium space (default the unit cube).
Json bounds(const ParamList& params) {
    const auto point = [&](const char* name, double fallback) {
        const auto p = params.numbers(name, {"point3", "point"}, 3);
        if (p && p->size() != 3) params.fail(*params.find(name), "expected one point");
        return p ? *p : std::vector<double>(3, fallback);
    };
    const std::vector<double> lo = point("p0", 0.0), hi = point("p1", 1.0);
    for (int a = 0; a < 3; ++a)
        if (!(float(hi[std::size_t(a)]) > float(lo[std::size_t(a)])))
            params.fail(*params.find("p1"), "must exceed p0 on every axis");
    return {{"min", lo}, {"max", hi}};
}

void place(const Entity& e, Json& medium) {
    if (e.transform != glm::dmat4(1.0))
        medium["transform"] = Json::array({Json{{"matrix", rowMajor(e.transform)}}});
}

std::string named(const MediumDef& m) {
    return "MakeNamedMedium \"" + m.name + "\": ";
}

Json uniformGrid(TranslationContext& ctx, const MediumDef& m) {
    const ParamList& params = m.entity.params;
    const std::vector<double> density = gridValues(params, "density", "float", 1);
    if (density.empty())
        ctx.fail(m.entity.location, named(m) + "no \"float density\" values (pbrt-v4 needs them)");
    const Json size = gridSize(params, *params.find("density"), density.size());
    Json medium{{"type", "grid"},
                {"density", {{"size", size}, {"values", density}}},
                {"edges", "zero"},
                {"bounds", bounds(params)},
                {"sigma_a", mediumCoefficient(ctx, params, "sigma_a")},
                {"sigma_s", mediumCoefficient(ctx, params, "sigma_s")}};
    mediumScaleAndPhase(params, medium);
    if (params.find("temperature"))
        params.fail(*params.find("temperature"),
                    "a temperature grid (blackbody emission varying in space) is not translated: "
                    "lamina's grid media emit sigma_a Le with one Le");
    // Read with the temperature grid in pbrt-v4; without one they change nothing.
    params.number("temperatureoffset", params.number("temperaturecutoff", 0.0));
    params.number("temperaturescale", 1.0);
    if (params.find("Le")) {
        // pbrt-v4's emission is sigma_a(p) Le Lescale(p), Lescale a grid of nx ny nz values
        // (1: Le normalised to one nit): lamina's sigma_a(p) Le when Lescale is one constant.
        double scale = 1.0;
        if (const Param* s = params.find("Lescale")) {
            const std::vector<double> v = gridValues(params, "Lescale", "float", 1);
            gridSize(params, *s, v.size());
            for (const double x : v)
                if (x != v[0])
                    params.fail(*s,
                                "varies in space: an emission grid apart from the density is "
                                "not translated (lamina's grid media emit sigma_a Le)");
            scale = v.empty() ? 1.0 : v[0];
        }
        if (scale > 0) medium["Le"] = emissionValue(ctx, params, "Le", scale);
    } else {
        params.find("Lescale");  // read by pbrt-v4 always; without Le it changes nothing
    }
    place(m.entity, medium);
    return medium;
}

Json rgbGrid(TranslationContext& ctx, const MediumDef& m) {
    const ParamList& params = m.entity.params;
    Json medium{{"type", "grid"}, {"edges", "zero"}, {"bounds", bounds(params)}};
    bool any = false;
    for (const char* name : {"sigma_a", "sigma_s"}) {
        const std::vector<double> v = gridValues(params, name, "rgb", 3);
        if (v.empty()) {
            // pbrt-v4's RGBGridMedium: a coefficient without its grid is 1 (times scale).
            medium[name] = 1.0;
            continue;
        }
        any = true;
        medium[std::string(name) + "_grid"] = {
            {"size", gridSize(params, *params.find(name), v.size() / 3)},
            {"channels", 3},
            {"values", v}};
    }
    if (!any)
        ctx.fail(m.entity.location, named(m) +
                                        "an rgbgrid needs \"rgb sigma_a\" and/or "
                                        "\"rgb sigma_s\" values (as pbrt-v4)");
    mediumScaleAndPhase(params, medium);
    if (const Param* le = params.find("Le")) {
        const std::vector<double> v = gridValues(params, "Le", "rgb", 3);
        bool dark = true;
        for (const double x : v)
            dark = dark && x == 0;
        if (!dark || params.number("Lescale", 1.0) < 0)
            params.fail(*le,
                        "an emission grid (rgb Le per cell) is not translated: lamina's grid "
                        "media emit sigma_a Le with one Le");
    }
    params.number("Lescale", 1.0);
    place(m.entity, medium);
    return medium;
}

Json nanoVdb(TranslationContext& ctx, const MediumDef& m) {
    const ParamList& params = m.entity.params;
    const Param* file = params.find("filename");
    if (!file) ctx.fail(m.entity.location, named(m) + "nanovdb needs a \"string filename\"");
    params.expectType(*file, {"string"});
    Json medium{{"type", "grid"},
                {"density", ctx.filePath(params, *file)},
                {"edges", "zero"},
                {"sigma_a", mediumCoefficient(ctx, params, "sigma_a")},
                {"sigma_s", mediumCoefficient(ctx, params, "sigma_s")}};
    mediumScaleAndPhase(params, medium);
    const double leScale = params.number("LeScale", params.number("Lescale", 1.0));
    params.number("temperatureoffset", params.number("temperaturecutoff", 0.0));
    params.number("temperaturescale", 1.0);
    if (leScale > 0)
        ctx.warn(m.entity.location,
                 named(m) +
                     "a \"temperature\" grid in the file, if it has one, is not rendered "
                     "(pbrt-v4 makes it glow as a blackbody; lamina reads the density "
                     "grid only)");
    place(m.entity, medium);
    return medium;
}

// pbrt-v4's CloudMedium::Create reads density (1), wispiness (1), frequency (5), g, sigma_a and
// sigma_s (1 each) and p0, p1, and no scale or emission (which pbrt-v4 then refuses as unused,
// as refuseUnused does here).
Json cloud(TranslationContext& ctx, const MediumDef& m) {
    const ParamList& params = m.entity.params;
    Json medium{{"type", "cloud"},
                {"bounds", bounds(params)},
                {"sigma_a", mediumCoefficient(ctx, params, "sigma_a")},
                {"sigma_s", mediumCoefficient(ctx, params, "sigma_s")}};
    const double density = params.number("density", 1.0);
    if (!(density >= 0) || !std::isfinite(density))
        params.fail(*params.find("density"),
                    "must be finite and >= 0 (lamina's cloud medium; a negative density "
                    "turns pbrt-v4's cloud inside out)");
    medium["density"] = density;
    for (const auto& [name, fallback] : {std::pair{"wispiness", 1.0}, {"frequency", 5.0}}) {
        const double v = params.number(name, fallback);
        if (!std::isfinite(float(v))) params.fail(*params.find(name), "must be finite");
        medium[name] = v;
    }
    mediumPhase(params, medium);
    place(m.entity, medium);
    return medium;
}

}  // namespace

Json translateGridMedium(TranslationContext& ctx, const MediumDef& m) {
    const Entity& e = m.entity;
    Json medium;
    if (e.type == "uniformgrid")
        medium = uniformGrid(ctx, m);
    else if (e.type == "rgbgrid")
        medium = rgbGrid(ctx, m);
    else if (e.type == "nanovdb")
        medium = nanoVdb(ctx, m);
    else if (e.type == "cloud")
        medium = cloud(ctx, m);
    else
        ctx.fail(e.location, named(m) + "\"" + e.type +
                                 "\" media are not supported (homogeneous, uniformgrid, rgbgrid, "
                                 "cloud, nanovdb)");
    e.params.refuseUnused();
    return medium;
}

}  // namespace lamina::render::pbrt
