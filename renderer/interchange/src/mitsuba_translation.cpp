// Mitsuba 3 scene -> lamina scene: the walk over the scene and the sensor, film, sampler and
// integrator (mitsuba_translation.h). Defaults are those of mitsuba3's plugin documentation
// (src/sensors/perspective.cpp, src/films/hdrfilm.cpp, src/samplers/*.cpp,
// src/integrators/*.cpp, src/render/sensor.cpp parse_fov).
#include "mitsuba_translation.h"

#include <cmath>
#include <glm/trigonometric.hpp>

#include "lamina/core/error.h"
#include "mitsuba_bsdfs.h"

namespace lamina::render::mitsuba {

namespace {

// Lamina's deepest path; Mitsuba's max_depth -1 (unbounded) becomes it.
constexpr long kMaxLaminaDepth = 1024;

Json translateFilter(Plugin& film, Diagnostics& d, const MitsubaDocument& document) {
    const auto filters = film.objects("rfilter");
    if (filters.size() > 1) film.fail("a film takes one rfilter");
    if (filters.empty())
        // hdrfilm's default: a gaussian of standard deviation 0.5 cut at 4 standard deviations.
        return {{"type", "gaussian"}, {"radius", 2.0}, {"sigma", 0.5}};
    Plugin f(*filters[0], document, d);
    Json out;
    if (f.type() == "box") {
        out = {{"type", "box"}, {"radius", 0.5}};
    } else if (f.type() == "gaussian") {
        // mitsuba3 gaussian.cpp: exp(-x^2 / 2 s^2) minus its value at 4 s, as lamina's with sigma.
        const double s = f.number("stddev", 0.5);
        if (!(s > 0 && 4 * s <= 16)) f.fail("stddev must be in (0, 4]");
        out = {{"type", "gaussian"}, {"radius", 4 * s}, {"sigma", s}};
    } else if (f.type() == "tent") {
        const double r = f.number("radius", 1.0);
        if (!(r > 0 && r <= 16)) f.fail("radius must be in (0, 16]");
        out = {{"type", "triangle"}, {"radius", r}};
    } else if (f.type() == "lanczos" || f.type() == "mitchell" || f.type() == "catmullrom") {
        const double r = f.type() == "lanczos" ? double(f.integer("lobes", 3)) : 2.0;
        if (f.type() == "mitchell") {
            f.ignore("B", "lamina has no Mitchell-Netravali filter");
            f.ignore("C", "lamina has no Mitchell-Netravali filter");
        }
        if (!(r > 0 && r <= 16)) f.fail("lobes must be in [1, 16]");
        out = {{"type", "blackman_harris"}, {"radius", r}};
        f.warn(f.type() + " became lamina's blackman_harris of radius " + std::to_string(int(r)) +
               " (positive everywhere: no negative lobes)");
    } else {
        f.fail("the filter \"" + f.type() + "\" is not supported");
    }
    f.finish();
    return out;
}

void translateFilm(Translation& t, const Element* film, double& aspect) {
    Json out = Json::object();
    long width = 768, height = 576;
    if (film) {
        Plugin p(*film, t.document, t.diagnostics);
        if (p.type() != "hdrfilm" && p.type() != "specfilm" && p.type() != "ldrfilm")
            p.fail("the film \"" + p.type() + "\" is not supported (hdrfilm, ldrfilm)");
        if (p.type() == "ldrfilm") {
            // Mitsuba 0.6's ldrfilm: hdrfilm's image, tonemapped (scaled by 2^exposure, then
            // gamma or Reinhard's operator) into 8 bits for display.
            // Read (and checked for their types) to be named once in the warning below.
            p.string("tonemap_method");
            for (const char* name : {"gamma", "exposure", "key", "burn"})
                p.number(name, 0.0);
            p.warn(
                "ldrfilm became lamina's film: lamina writes the linear radiance to OpenEXR "
                "(and a PNG preview); the film's tonemapping (gamma, exposure) is for display "
                "and is not applied");
        }
        p.ignore("high_quality_edges",
                 "lamina's filters draw sample positions inside the pixel's radius");
        width = p.integer("width", width);
        height = p.integer("height", height);
        if (width < 1 || width > 65536 || height < 1 || height > 65536)
            p.fail("width and height must be in [1, 65536]");
        out["filter"] = translateFilter(p, t.diagnostics, t.document);
        for (const char* name : {"pixel_format", "component_format", "file_format"})
            p.ignore(name, "lamina writes linear RGB float OpenEXR");
        p.ignore("sample_border",
                 "lamina's filters draw sample positions inside the pixel's radius");
        p.ignore("banner", "lamina writes no banner");
        p.ignore("compensate", "lamina accumulates in float per pixel");
        p.finish();
    } else {
        out["filter"] = Json{{"type", "gaussian"}, {"radius", 2.0}, {"sigma", 0.5}};
    }
    out["resolution"] = Json::array({width, height});
    aspect = double(width) / double(height);
    t.scene["film"] = out;
}

void translateSampler(Translation& t, const Element* sampler) {
    Json out{{"type", "independent"}, {"spp", 4}};
    if (sampler) {
        Plugin p(*sampler, t.document, t.diagnostics);
        const std::string& type = p.type();
        // Mitsuba 0.6's quasi-random samplers (sobol, halton, hammersley) too.
        if (type == "stratified" || type == "multijitter" || type == "orthogonal" ||
            type == "ldsampler" || type == "sobol" || type == "halton" || type == "hammersley") {
            out["type"] = "sobol";
            p.ignore("jitter", "lamina's Sobol points are scrambled, not jittered");
            p.ignore("strength", "lamina's Sobol points are scrambled");
            p.ignore("scramble", "lamina scrambles its Sobol points (Owen) in every dimension");
            p.ignore("dimension", "lamina's Sobol points serve every dimension of a path");
            p.warn(type + " became lamina's Owen-scrambled Sobol sampler (the same expectation)");
        } else if (type != "independent") {
            p.fail("the sampler \"" + type + "\" is not supported");
        }
        const long spp = p.integer("sample_count", 4);
        const long seed = p.integer("seed", 0);
        if (spp < 1 || spp > (1L << 30)) p.fail("sample_count must be in [1, 2^30]");
        if (seed < 0) p.fail("seed must be >= 0");
        out["spp"] = spp;
        if (seed) out["seed"] = seed;
        p.finish();
    }
    t.scene["sampler"] = out;
}

// Mitsuba's vertical field of view for lamina from fov / fov_axis or focal_length.
double verticalFov(Plugin& p, double aspect) {
    if (p.has("fov") && p.has("focal_length")) p.fail("give fov or focal_length, not both");
    double fov = 0;
    std::string axis;
    if (p.has("fov")) {
        fov = p.number("fov", 0);
        axis = p.string("fov_axis").value_or("x");
        if (axis == "smaller") axis = aspect > 1 ? "y" : "x";
        if (axis == "larger") axis = aspect > 1 ? "x" : "y";
    } else {
        std::string f = p.string("focal_length").value_or("50mm");
        if (f.size() > 2 && f.compare(f.size() - 2, 2, "mm") == 0) f.resize(f.size() - 2);
        const auto numbers = parseNumbers(f, p.element(), "focal_length");
        if (numbers.size() != 1 || !(numbers[0] > 0))
            p.fail("focal_length must be one number > 0 (in mm)");
        const double mm = numbers[0];
        // The diagonal of a 36 x 24 mm frame (mitsuba3 parse_fov).
        fov = glm::degrees(2.0 * std::atan(std::sqrt(36.0 * 36.0 + 24.0 * 24.0) / (2.0 * mm)));
        axis = "diagonal";
    }
    if (!(fov > 0 && fov < 180)) p.fail("the field of view must be in (0, 180) degrees");
    const double half = std::tan(glm::radians(fov) / 2);
    double tanVertical = 0;
    if (axis == "x")
        tanVertical = half / aspect;
    else if (axis == "y")
        tanVertical = half;
    else if (axis == "diagonal")
        tanVertical = half / std::sqrt(1 + aspect * aspect);
    else
        p.fail("fov_axis \"" + axis + "\" is not one of x, y, diagonal, smaller, larger");
    return glm::degrees(2.0 * std::atan(tanVertical));
}

void translateSensor(Translation& t, const Element& sensor) {
    Plugin p(sensor, t.document, t.diagnostics);
    Json camera = Json::object();
    if (p.type() == "thinlens") {
        camera["type"] = "thin_lens";
        const double radius = p.number("aperture_radius", 0.0);
        if (!(radius > 0)) p.fail("aperture_radius must be > 0");
        camera["aperture_radius"] = radius;
        if (const auto focus = p.optionalNumber("focus_distance"))
            camera["focus_distance"] = *focus;
    } else if (p.type() == "orthographic") {
        camera["type"] = "orthographic";
    } else if (p.type() != "perspective") {
        p.fail("the sensor \"" + p.type() +
               "\" is not supported (perspective, thinlens, orthographic)");
    }
    const auto films = p.objects("film");
    const auto samplers = p.objects("sampler");
    if (films.size() > 1 || samplers.size() > 1) p.fail("a sensor takes one film and one sampler");
    double aspect = 1;
    translateFilm(t, films.empty() ? nullptr : films[0], aspect);
    translateSampler(t, samplers.empty() ? nullptr : samplers[0]);
    const auto transform = p.transform("to_world");
    if (camera.value("type", "") == "orthographic") {
        // Mitsuba's orthographic film spans x in [-1, 1] and y in [-1 / aspect, 1 / aspect] of
        // to_world's frame (orthographic_projection, src/render/sensor.cpp), scaled by it.
        const glm::dmat4 m = transform ? transform->matrix : glm::dmat4(1.0);
        const double sx = glm::length(glm::dvec3(m[0])), sy = glm::length(glm::dvec3(m[1]));
        camera["screen_window"] = {-sx, sx, -sy / aspect, sy / aspect};
    } else {
        camera["fov"] = verticalFov(p, aspect);
    }
    if (transform) {
        // Mitsuba's camera looks along +z of to_world with +y up and +x to the image's left,
        // lamina's `matrix` convention; a mirroring to_world flips the image (handedness left).
        Json rows = Json::array();
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 4; ++col)
                rows.push_back(transform->matrix[col][row]);
        camera["matrix"] = rows;
        if (glm::determinant(glm::dmat3(transform->matrix)) < 0) camera["handedness"] = "left";
    }
    // A pinhole's focus distance changes nothing (mitsuba3 ProjectiveCamera reads it for all).
    if (camera.value("type", "") != "thin_lens") p.optionalNumber("focus_distance");
    p.ignore("near_clip", "lamina's camera rays start at the lens");
    p.ignore("far_clip", "lamina's camera rays are unbounded");
    p.ignore("srf", "lamina's film uses the CIE 1931 observer");
    for (const char* name : {"principal_point_offset_x", "principal_point_offset_y"})
        if (p.number(name, 0.0) != 0) p.fail(std::string(name) + " is not supported");
    if (const auto medium = endpointMedium(t, p)) camera["medium"] = *medium;
    p.finish();
    t.scene["camera"] = camera;
}

// Mitsuba's max_depth counts the emitter vertex: 2 is direct light, lamina's 1.
long laminaDepth(Plugin& p, const char* name, long fallback) {
    const long depth = p.integer(name, fallback);
    if (depth == -1) return kMaxLaminaDepth;
    if (depth < 2 || depth - 1 > kMaxLaminaDepth)
        p.fail(std::string(name) + " " + std::to_string(depth) +
               " is not supported (lamina renders 2 to " + std::to_string(kMaxLaminaDepth + 1) +
               " or -1)");
    return depth - 1;
}

void translateIntegrator(Translation& t, const Element& integrator) {
    Plugin p(integrator, t.document, t.diagnostics);
    if (p.type() == "moment") {
        // mitsuba3 moment.cpp: the nested integrators' images with their second moments as
        // extra channels; lamina renders the first.
        const auto nested = p.objects("integrator");
        if (nested.size() != 1)
            p.fail("moment with " + std::to_string(nested.size()) +
                   " integrators is not supported (lamina takes one)");
        p.warn("moment became its nested integrator: lamina writes no second-moment channels");
        p.finish();
        translateIntegrator(t, *nested[0]);
        return;
    }
    const std::string& type = p.type();
    Json out = Json::object();
    if (type == "path" || type == "volpath" || type == "volpathmis") {
        // lamina's path tracer renders media with spectral MIS, as volpathmis does.
        out["type"] = "path";
    } else if (type == "ptracer") {
        out["type"] = "light";
        p.ignore("samples_per_pass", "lamina schedules its own passes");
    } else if (type == "bdpt") {
        out["type"] = "bdpt";
    } else if (type == "direct") {
        out = {{"type", "path"}, {"max_depth", 1}};
        for (const char* name : {"shading_samples", "emitter_samples", "bsdf_samples"})
            p.ignore(name, "lamina takes one light and one BSDF sample per hit, MIS-weighted");
        p.warn("direct became lamina's path with max_depth 1 (direct light only)");
    } else {
        p.fail("the integrator \"" + type + "\" is not supported (path, ptracer, bdpt, direct)");
    }
    if (type != "direct") {
        const bool given = p.has("max_depth");
        out["max_depth"] = laminaDepth(p, "max_depth", -1);
        if (out["max_depth"] == kMaxLaminaDepth)
            p.warn(std::string(given ? "" : "the default ") +
                   "max_depth -1 (unbounded) became lamina's max_depth 1024 (Russian roulette "
                   "ends paths long before)");
        out["rr_depth"] = std::max(1L, p.integer("rr_depth", 5) - 1);
    }
    if (p.boolean("hide_emitters", false)) p.fail("hide_emitters is not supported");
    // Mitsuba 0.6's strictNormals ends a path where the geometric and shading normals put a
    // direction on different sides; lamina keeps it and corrects the adjoint instead.
    if (p.boolean("strict_normals", false))
        p.warn(
            "strict_normals ignored: lamina follows a path where the geometric and shading "
            "normals disagree (light leaks there differ from Mitsuba 0.6's)");
    p.finish();
    t.scene["integrator"] = out;
}

// An element standing for a plugin the file leaves out (Mitsuba's defaults apply).
Element defaultElement(const Element& scene, const char* tag, const char* type) {
    Element e;
    e.tag = tag;
    e.attributes = {{"type", type}};
    e.file = scene.file;
    e.line = scene.line;
    return e;
}

}  // namespace

ImportedScene importMitsubaScene(const std::filesystem::path& file,
                                 const std::filesystem::path& pathsRelativeTo) {
    MitsubaDocument document;
    readMitsubaDocument(file, document);
    Diagnostics diagnostics;
    // loadScene passes the scene's parent path, empty for a file in the working directory.
    Translation t{document, diagnostics,
                  pathsRelativeTo.empty() ? std::filesystem::path(".") : pathsRelativeTo};
    t.scene["shapes"] = Json::array();
    const Element& scene = document.scene;
    // Named BSDFs first: shapes anywhere in the file refer to them by id.
    for (const Element& e : scene.children) {
        if (e.tag != "bsdf") continue;
        // A null BSDF becomes the shapes' "interface" where they use it (shapeMaterial).
        if (const std::string* type = e.attribute("type"); type && *type == "null") continue;
        const std::string* id = e.attribute("id");
        if (!id) {
            diagnostics.warn(e, e.describe() + " without an id is used by no shape: not imported");
            continue;
        }
        TranslatedBsdf bsdf = translateBsdf(e, document, diagnostics);
        t.scene["materials"][*id] = bsdf.material;
        addTextures(t, bsdf.textures);
        t.namedBsdfs.emplace(&e, bsdf.alpha);
    }
    const Element* sensor = nullptr;
    const Element* integrator = nullptr;
    for (const Element& e : scene.children) {
        if (e.tag == "bsdf") continue;
        if (e.tag == "sensor") {
            if (sensor)
                throw InputError(e.where() +
                                 ": a second <sensor> (lamina renders one camera; the "
                                 "first is at " +
                                 sensor->where() + ")");
            sensor = &e;
        } else if (e.tag == "integrator") {
            if (integrator)
                throw InputError(e.where() + ": a second <integrator> (the first is at " +
                                 integrator->where() + ")");
            integrator = &e;
        } else if (e.tag == "shape") {
            const std::string* type = e.attribute("type");
            if (type && *type == "shapegroup")
                translateShapeGroup(t, e);
            else
                translateShape(t, e, t.scene["shapes"], false);
        } else if (e.tag == "emitter" && e.attribute("id") && e.attribute("type") &&
                   *e.attribute("type") == "area") {
            continue;  // the emission of the shapes that refer to it
        } else if (e.tag == "emitter") {
            translateEmitter(t, e);
        } else if ((e.tag == "medium" || e.tag == "texture" || e.tag == "sampler" ||
                    e.tag == "film" || e.tag == "rfilter") &&
                   e.attribute("id")) {
            continue;  // translated where a shape, a sensor, a film or a BSDF refers to it
        } else if (e.tag == "texture" || e.tag == "medium" || e.tag == "phase" ||
                   e.tag == "volume" || e.tag == "film" || e.tag == "sampler" ||
                   e.tag == "rfilter") {
            throw InputError(e.where() + ": " + e.describe() +
                             " at the top level is not supported" +
                             (e.tag == "medium" || e.tag == "texture"
                                  ? " without an id (nothing can refer to it)"
                                  : ""));
        } else {
            throw InputError(e.where() + ": unknown element <" + e.tag + "> in <scene>");
        }
    }
    if (sensor) {
        translateSensor(t, *sensor);
    } else {
        diagnostics.warn(scene,
                         "no <sensor>: Mitsuba's default perspective camera at the origin "
                         "looking along +z (50 mm, 768 x 576, 4 spp)");
        translateSensor(t, defaultElement(scene, "sensor", "perspective"));
    }
    if (integrator) {
        translateIntegrator(t, *integrator);
    } else {
        diagnostics.warn(scene, "no <integrator>: Mitsuba's default path tracer");
        translateIntegrator(t, defaultElement(scene, "integrator", "path"));
    }
    for (const Element& e : scene.children)
        if (e.tag == "emitter" && e.attribute("id") && !t.areaEmitters.count(&e) &&
            e.attribute("type") && *e.attribute("type") == "area")
            diagnostics.warn(e, e.describe() + " \"" + *e.attribute("id") +
                                    "\" is used by no shape: not imported");
    for (const Element& e : scene.children)
        if (e.tag == "medium" && e.attribute("id") && !t.media.count(&e))
            diagnostics.warn(e, e.describe() + " \"" + *e.attribute("id") +
                                    "\" is used by no shape or sensor: not imported");
    // Mitsuba 3's path integrator ignores media (volpath and volpathmis render them).
    if (t.scene.contains("media") && integrator && integrator->attribute("type") &&
        *integrator->attribute("type") == "path")
        diagnostics.warn(*integrator,
                         "the path integrator of a scene with media: Mitsuba's renders it as if "
                         "there were none, lamina's path tracer with them (as volpath)");
    ImportedScene out;
    out.format = SceneFormat::Mitsuba;
    out.scene = std::move(t.scene);
    out.warnings = std::move(diagnostics.warnings);
    out.inputFiles = document.files;
    out.inputFiles.insert(out.inputFiles.end(), diagnostics.files.begin(), diagnostics.files.end());
    return out;
}

}  // namespace lamina::render::mitsuba
