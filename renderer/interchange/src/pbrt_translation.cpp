// The scene-wide part of the pbrt-v4 translation: filter, sampler, integrator, lights, objects
// and instances (the camera and film: pbrt_camera.cpp), and the importer's entry point
// (scene_import.cpp's table).
#include "pbrt_translation.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "lamina/core/error.h"
#include "lamina/core/input_file.h"
#include "lamina/core/rectangle_corners.h"
#include "lamina/interchange/scene_import.h"
#include "pbrt_importer.h"
#include "pbrt_motion.h"
#include "pbrt_shapes.h"
#include "rounded_rotation.h"

namespace lamina::render::pbrt {

namespace {

constexpr double kPi = 3.14159265358979323846;

Json vec(const glm::dvec3& v) {
    return Json::array({v.x, v.y, v.z});
}

glm::dvec3 apply(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}

glm::dvec3 readPoint(const ParamList& params, const std::string& name, const glm::dvec3& fallback) {
    const auto v = params.numbers(name, {"point3"}, 3);
    if (!v) return fallback;
    if (v->size() != 3) params.fail(*params.find(name), "expected one point");
    return {(*v)[0], (*v)[1], (*v)[2]};
}

Entity defaultEntity(const std::string& type) {
    Entity e;
    e.type = type;
    return e;
}

// pbrt-v4's filters (filters.cpp): gaussian is the default (radius 1.5, sigma 0.5), box has
// radius 0.5, triangle 2.
Json translateFilter(TranslationContext& ctx, const Entity& e) {
    const ParamList& p = e.params;
    double radius = 0;
    if (e.type == "box")
        radius = 0.5;
    else if (e.type == "gaussian")
        radius = 1.5;
    else if (e.type == "triangle")
        radius = 2;
    else
        ctx.fail(e.location, "PixelFilter \"" + e.type +
                                 "\" is not supported (box, gaussian, "
                                 "triangle)");
    const double xr = p.number("xradius", radius), yr = p.number("yradius", radius);
    if (xr != yr)
        ctx.fail(e.location, "PixelFilter: different xradius and yradius are not supported");
    Json filter{{"type", e.type}, {"radius", xr}};
    if (e.type == "gaussian") {
        // pbrt-v4's gaussian: exp(-x^2 / 2 sigma^2) minus its value at the radius, per axis:
        // lamina's, whose sigma defaults to radius / 3.
        const double sigma = p.number("sigma", 0.5);
        if (std::abs(sigma - xr / 3) > 1e-12 * xr) filter["sigma"] = sigma;
    }
    p.refuseUnused();
    return filter;
}

Json translateSampler(TranslationContext& ctx, const Entity& e) {
    const ParamList& p = e.params;
    int spp = p.integer("pixelsamples", 16);
    std::string type = "sobol";
    if (e.type == "independent") {
        type = "independent";
    } else if (e.type == "stratified") {
        spp = p.integer("xsamples", 4) * p.integer("ysamples", 4);
        p.boolean("jitter", true);
        ctx.warn(e.location,
                 "Sampler \"stratified\" became lamina's Owen-scrambled Sobol "
                 "sampler with xsamples x ysamples = " +
                     std::to_string(spp) + " samples per pixel");
    } else if (e.type == "sobol") {
        // pbrt-v4's SobolSampler: every dimension from one global Sobol sequence.
        type = "sobol-global";
        if (p.has("randomization")) p.string("randomization", "");
        ctx.warn(e.location,
                 "Sampler \"sobol\" became lamina's sobol-global sampler (pbrt-v4's global "
                 "Sobol points; Owen-scrambled per pixel where pbrt-v4 scrambles per "
                 "dimension; same sample count)");
    } else if (e.type == "zsobol" || e.type == "paddedsobol" || e.type == "halton" ||
               e.type == "pmj02bn") {
        if (p.has("randomization")) p.string("randomization", "");
        ctx.warn(e.location, "Sampler \"" + e.type +
                                 "\" became lamina's Owen-scrambled Sobol "
                                 "sampler (same sample count)");
    } else {
        ctx.fail(e.location, "Sampler \"" + e.type + "\" is not supported");
    }
    if (spp < 1) ctx.fail(e.location, "Sampler: the sample count must be at least 1");
    Json sampler{{"type", type}, {"spp", spp}};
    if (p.has("seed")) sampler["seed"] = p.integer("seed", 0);
    p.refuseUnused();
    return sampler;
}

// pbrt-v4's integrators (integrators.cpp): maxdepth 5, counted as lamina counts max_depth
// (scattering events; PathIntegrator::Li stops when depth++ == maxDepth).
Json translateIntegrator(TranslationContext& ctx, const Entity& e) {
    const ParamList& p = e.params;
    std::string type;
    if (e.type == "path") {
        type = "path";
    } else if (e.type == "volpath") {
        // lamina's path tracer renders media as volpath does (spectral MIS free flights).
        type = "path";
    } else if (e.type == "bdpt") {
        type = "bdpt";
        if (p.boolean("visualizestrategies", false) || p.boolean("visualizeweights", false))
            ctx.fail(e.location,
                     "bdpt's visualizestrategies / visualizeweights are not "
                     "supported (lamina render --strategies writes them)");
    } else if (e.type == "lightpath") {
        type = "light";
    } else if (e.type == "randomwalk" || e.type == "simplepath") {
        // Unbiased path tracers with fewer strategies (integrators.cpp): the same expected
        // image as lamina's path tracer, with more noise in pbrt.
        type = "path";
        if (e.type == "simplepath") {
            p.boolean("samplelights", true);
            p.boolean("samplebsdf", true);
        }
        ctx.warn(e.location, "Integrator \"" + e.type +
                                 "\" became lamina's path tracer (next-event estimation and "
                                 "MIS: the same expected image, less noise)");
    } else if (e.type == "sppm" || e.type == "mlt") {
        // SPPM is consistent (its radius blur vanishes as iterations grow) and MLT unbiased:
        // both converge to the image BDPT converges to. SPPM's iterations are the sampler's
        // sample count in pbrt-v4 (SPPMIntegrator::Render), which the Sampler gives lamina too.
        type = "bdpt";
        if (e.type == "sppm") {
            p.integer("photonsperiteration", -1);
            p.number("radius", 1.0);
            p.integer("seed", 0);
        } else {
            p.integer("bootstrapsamples", 100000);
            p.integer("chains", 1000);
            p.integer("mutationsperpixel", 100);
            p.number("largestepprobability", 0.3);
            p.number("sigma", 0.01);
        }
        ctx.warn(e.location,
                 "Integrator \"" + e.type +
                     "\" became lamina's BDPT with the Sampler's sample count" +
                     (e.type == "sppm" ? " (the image SPPM converges to, without the blur of its "
                                         "photon radius at a finite count)"
                                       : " (the image MLT converges to; its parameters are "
                                         "ignored)"));
    } else {
        ctx.fail(e.location, "Integrator \"" + e.type +
                                 "\" is not supported (path, volpath, bdpt, lightpath, "
                                 "randomwalk, simplepath, sppm, mlt)");
    }
    const int depth = p.integer("maxdepth", 5);
    if (depth < 1 || depth > 1024)
        ctx.fail(e.location, "maxdepth " + std::to_string(depth) +
                                 " is not supported (lamina's max_depth is 1 to 1024)");
    // pbrt-v4's regularize (integrators.cpp, PathIntegrator::Li) roughens near-specular BSDFs
    // after the path's first non-specular bounce: a biased image with less caustic noise.
    if (p.boolean("regularize", false))
        ctx.warn(e.location,
                 "regularize ignored: lamina renders the unregularised image (pbrt-v4 roughens "
                 "near-specular surfaces after a diffuse bounce, which dims and blurs caustics)");
    // pbrt-v3's Russian roulette threshold; pbrt-v4 reads none (its --upgrade removes it).
    // Roulette changes the noise, not the expected image.
    if (const Param* rr = p.find("rrthreshold")) {
        p.expectType(*rr, {"float"});
        ctx.warn(rr->location,
                 "rrthreshold ignored (a pbrt-v3 parameter that pbrt-v4 does not read; Russian "
                 "roulette changes the noise, not the image)");
    }
    Json integrator{{"type", type}, {"max_depth", depth}};
    if (p.has("lightsampler")) {
        const std::string s = p.string("lightsampler", "bvh");
        if (s != "bvh" && s != "power" && s != "uniform")
            ctx.fail(e.location, "lightsampler \"" + s + "\" is not supported");
        integrator["light_selection"] = s;
    }
    p.refuseUnused();
    return integrator;
}

Json translateLight(TranslationContext& ctx, const Entity& e) {
    const ParamList& p = e.params;
    const glm::dmat4& m = e.transform;
    double scale = p.number("scale", 1.0);
    Json light;
    if (e.type == "point") {
        // PointLight::Create: power phi gives scale *= phi / 4 pi.
        const double power = p.number("power", -1);
        if (power > 0) scale *= power / (4 * kPi);
        light = {{"type", "point"},
                 {"position", vec(apply(m, readPoint(p, "from", glm::dvec3(0))))},
                 {"intensity", emissionValue(ctx, p, "I", scale)}};
    } else if (e.type == "spot") {
        const double cone = p.number("coneangle", 30), delta = p.number("conedeltaangle", 5);
        const double start = std::max(0.0, cone - delta);
        const double power = p.number("power", -1);
        if (power > 0) {
            // SpotLight::Create: k_e = 2 pi ((1 - cos start) + (cos start - cos end) / 2).
            const double cs = std::cos(start * kPi / 180), ce = std::cos(cone * kPi / 180);
            scale *= power / (2 * kPi * ((1 - cs) + (cs - ce) / 2));
        }
        light = {{"type", "spot"},
                 {"position", vec(apply(m, readPoint(p, "from", glm::dvec3(0))))},
                 {"look_at", vec(apply(m, readPoint(p, "to", glm::dvec3(0, 0, 1))))},
                 {"intensity", emissionValue(ctx, p, "I", scale)},
                 {"cone_angle", cone},
                 {"falloff_start", start}};
    } else if (e.type == "distant") {
        const glm::dvec3 from = readPoint(p, "from", glm::dvec3(0));
        const glm::dvec3 to = readPoint(p, "to", glm::dvec3(0, 0, 1));
        const glm::dvec3 d = apply(m, to) - apply(m, from);
        if (glm::length(d) == 0) ctx.fail(e.location, "distant: from and to coincide");
        const double illuminance = p.number("illuminance", -1);
        if (illuminance > 0) scale *= illuminance;  // DistantLight::Create
        light = {{"type", "directional"},
                 {"direction", vec(glm::normalize(d))},
                 {"irradiance", emissionValue(ctx, p, "L", scale)}};
    } else if (e.type == "infinite") {
        const double illuminance = p.number("illuminance", -1);
        const Param* file = p.find("filename");
        Json portalCorners;
        if (const Param* portal = p.find("portal")) {
            // pbrt-v4's PortalImageInfiniteLight: the environment seen only through the
            // rectangle, whose corners are world points (lights.cpp applies no light transform
            // to them): lamina's portal (portal_environment.h) is the same light.
            const std::vector<double> c = *p.numbers("portal", {"point3"}, 3);
            if (c.size() != 12) p.fail(*portal, "expected the portal's four corners");
            if (!file)
                ctx.fail(portal->location,
                         "infinite: a portal on a uniform \"L\" is not supported (pbrt-v4 "
                         "turns L into an unnormalised RGB image there): remove the portal");
            std::array<glm::dvec3, 4> corners;
            for (std::size_t k = 0; k < 4; ++k) {
                corners[k] = glm::dvec3(c[3 * k], c[3 * k + 1], c[3 * k + 2]);
                portalCorners.push_back(vec(corners[k]));
            }
            if (const auto why = whyNotARectangle(corners)) p.fail(*portal, *why);
        }
        if (file) {
            p.expectType(*file, {"string"});
            if (p.has("L")) ctx.fail(e.location, "infinite: give either L or filename");
            if (illuminance > 0)
                ctx.fail(e.location, "infinite: illuminance with an image is not supported");
            // pbrt-v4's environment images are equal-area octahedral squares looked up with
            // the direction in light space (ImageInfiniteLight::Le).
            // A rotation or a reflection (Scale -1 1 1, common in exported scenes: a change of
            // handedness lamina's environment transform takes as it is), rounded as exporters
            // write it, with any uniform scale (pbrt-v4 normalises the light-space direction).
            glm::dmat3 r(m);
            const double scaleOf = std::cbrt(std::abs(glm::determinant(r)));
            if (!(scaleOf > 0)) ctx.fail(e.location, "infinite: the light's transform is singular");
            const double skew = columnSkew(r), uneven = columnScaleError(r / scaleOf);
            if (skew > kRoundedRotationTolerance || uneven > kRoundedRotationTolerance)
                ctx.fail(e.location,
                         "infinite: only rotations, reflections and uniform scales may orient an "
                         "environment image (a shear or an uneven scale was given)");
            if (skew > 1e-9 || uneven > 1e-9) {
                ctx.warn(e.location, "infinite: the light's transform is a rotation to within " +
                                         deviationText(std::max(skew, uneven)) +
                                         " (rounded digits): its nearest rotation is used");
                r = orthonormalised(r);
            } else {
                r /= scaleOf;
            }
            light = {{"type", "environment"},
                     {"file", ctx.filePath(p, *file)},
                     {"scale", scale},
                     {"mapping", "equal_area_octahedral"}};
            if (r != glm::dmat3(1.0)) light["transform"] = {{{"matrix", rowMajor(glm::dmat4(r))}}};
            if (!portalCorners.is_null()) light["portal"] = portalCorners;
        } else {
            // UniformInfiniteLight: illuminance E gives scale *= E / pi.
            if (illuminance > 0) scale *= illuminance / kPi;
            light = {{"type", "environment"}, {"radiance", emissionValue(ctx, p, "L", scale)}};
        }
    } else {
        ctx.fail(e.location, "LightSource \"" + e.type +
                                 "\" is not supported (point, spot, "
                                 "distant, infinite)");
    }
    p.refuseUnused();
    return light;
}

}  // namespace

void TranslationContext::fail(const Location& at, const std::string& message) const {
    throw InputError(at.str() + ": " + message);
}

std::string TranslationContext::filePath(const ParamList& params, const Param& p) const {
    if (p.strings.size() != 1) params.fail(p, "expected one file name");
    std::filesystem::path file(p.strings[0]);
    if (file.is_relative()) file = scene.directory / file;
    const std::string why = notARegularFile(file);
    if (!why.empty()) params.fail(p, "\"" + p.strings[0] + "\": " + why);
    return documentPath(file, pathsRelativeTo);
}

Json translate(TranslationContext& ctx) {
    const ParsedScene& scene = ctx.scene;
    Json& doc = ctx.document;
    int width = 1280, height = 720;
    const Entity camera = scene.camera ? *scene.camera : defaultEntity("perspective");
    doc["film"] =
        translateFilm(ctx, scene.film ? *scene.film : defaultEntity("rgb"), camera, width, height);
    doc["film"]["filter"] =
        translateFilter(ctx, scene.filter ? *scene.filter : defaultEntity("gaussian"));
    doc["camera"] = translateCamera(ctx, camera, width, height);
    if (!scene.cameraMedia.outside.empty())
        doc["camera"]["medium"] =
            useMedium(ctx, scene.cameraMedia.outside, scene.cameraMedia.location);
    // pbrt-v4's default sampler is zsobol with 16 samples per pixel, its default integrator
    // volpath with maxdepth 5 (scene.cpp): lamina's Sobol sampler and path tracer.
    doc["sampler"] = scene.sampler ? translateSampler(ctx, *scene.sampler)
                                   : Json{{"type", "sobol"}, {"spp", 16}};
    doc["integrator"] =
        translateIntegrator(ctx, scene.integrator ? *scene.integrator : defaultEntity("path"));
    doc["shapes"] = Json::array();
    warnStandsStill(ctx, camera, "the camera");
    ShapeList topLevel(doc["shapes"]);
    for (const ShapeDef& s : scene.shapes)
        if (s.entity.transformEnd)
            translateMovingShape(ctx, s, doc);
        else if (auto shape = translateShape(ctx, s, false))
            topLevel.append(std::move(*shape));
    // Objects: shared geometry, placed by instances (common-spec: "objects" and "instance").
    std::set<std::string> instanced;
    for (const InstanceDef& i : scene.instances) {
        const ObjectDef* object = nullptr;
        for (const ObjectDef& o : scene.objects)
            if (o.name == i.object) object = &o;
        if (!object) ctx.fail(i.location, "ObjectInstance \"" + i.object + "\": no such object");
        if (!instanced.count(i.object)) {
            Json shapes = Json::array();
            ShapeList objectShapes(shapes);
            for (const ShapeDef& s : object->shapes) {
                warnStandsStill(ctx, s.entity, "a shape inside ObjectBegin");
                if (auto shape = translateShape(ctx, s, true))
                    objectShapes.append(std::move(*shape));
            }
            doc["objects"][i.object] = shapes;
            instanced.insert(i.object);
        }
        doc["shapes"].push_back(translateInstance(ctx, i));
    }
    translateShutter(ctx, camera, doc);
    for (const ObjectDef& o : scene.objects)
        if (!instanced.count(o.name))
            ctx.warn(o.location, "object \"" + o.name + "\" is never instanced: not translated");
    doc["lights"] = Json::array();
    for (const Entity& l : scene.lights) {
        warnStandsStill(ctx, l, "LightSource \"" + l.type + "\"");
        doc["lights"].push_back(translateLight(ctx, l));
    }
    warnUnusedMedia(ctx);
    for (const MediumDef& m : scene.media)
        warnStandsStill(ctx, m.entity, "MakeNamedMedium \"" + m.name + "\"");
    // pbrt-v4's PathIntegrator ignores media (only volpath and bdpt render them); lamina's
    // path tracer renders them.
    if (doc.contains("media") && scene.integrator && scene.integrator->type == "path")
        ctx.warn(scene.integrator->location,
                 "Integrator \"path\" of a scene with media: pbrt-v4's path integrator "
                 "renders it as if there were none, lamina's path tracer with them (as volpath)");
    for (const MaterialDef& m : scene.materials)
        if (!ctx.writtenMaterials.count(m.name) && m.name.rfind("pbrt_material_", 0) != 0)
            ctx.warn(m.entity.location, "material \"" + m.name +
                                            "\" is used by no shape: not "
                                            "translated");
    return doc;
}

ImportedScene importPbrt(const std::filesystem::path& file,
                         const std::filesystem::path& pathsRelativeTo) {
    const ParsedScene scene = parseFile(file);
    TranslationContext ctx{scene, pathsRelativeTo};
    ImportedScene imported;
    imported.format = SceneFormat::Pbrt;
    imported.scene = translate(ctx);
    imported.warnings = scene.warnings;
    imported.warnings.insert(imported.warnings.end(), ctx.warnings.begin(), ctx.warnings.end());
    imported.inputFiles = scene.files;
    return imported;
}

}  // namespace lamina::render::pbrt
