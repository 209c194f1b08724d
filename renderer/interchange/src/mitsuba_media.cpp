// Mitsuba 3's media -> the lamina document's `media` (docs/interchange.md, "Mitsuba 3"): the
// `homogeneous` medium (mitsuba3 src/media/homogeneous.cpp: albedo, sigma_t, scale, a nested
// phase function), the `interior` and `exterior` media of shapes and the medium of the
// sensor; the `heterogeneous` medium with grid volumes (.vol files) as a lamina grid medium.
#include <cmath>
#include <map>

#include "document_names.h"
#include "lamina/interchange/scene_import.h"
#include "mitsuba_translation.h"

namespace lamina::render::mitsuba {

namespace {

// A coefficient as a number or an rgb triple; a spectrum or a volume is refused.
Json coefficient(Plugin& p, const std::string& name, double fallback) {
    const std::optional<Json> value = p.color(name);
    if (!value) return fallback;
    if (!value->is_number() && !value->is_array())
        p.fail("parameter \"" + name +
               "\": a spectrum is not supported (lamina's media take a number or rgb)");
    const auto check = [&](double c) {
        if (!(c >= 0) || !std::isfinite(c))
            p.fail("parameter \"" + name + "\" must be finite and >= 0");
    };
    if (value->is_array())
        for (const Json& c : *value)
            check(c.get<double>());
    else
        check(value->get<double>());
    return *value;
}

double component(const Json& v, int c) {
    return v.is_number() ? v.get<double>() : v[std::size_t(c)].get<double>();
}

// f(a_c, b_c) per channel: a number when both are numbers, else an rgb triple.
template <typename F>
Json perChannel(const Json& a, const Json& b, F f) {
    if (a.is_number() && b.is_number()) return f(a.get<double>(), b.get<double>());
    return Json::array({f(component(a, 0), component(b, 0)), f(component(a, 1), component(b, 1)),
                        f(component(a, 2), component(b, 2))});
}

// The nested phase function's Henyey-Greenstein g: isotropic (0) or hg.
double phaseAsymmetry(Plugin& p) {
    double g = 0;
    const auto phases = p.objects("phase");
    if (phases.size() > 1) p.fail("a medium takes one phase function");
    if (!phases.empty()) {
        Plugin phase(*phases[0], p.document(), p.diagnostics());
        if (phase.type() == "hg")
            g = phase.number("g", 0.8);  // mitsuba3 src/phase/hg.cpp's default
        else if (phase.type() != "isotropic")
            phase.fail("the phase function \"" + phase.type() +
                       "\" is not supported (isotropic, hg)");
        if (!(std::abs(g) < 1)) phase.fail("g must lie in (-1, 1)");
        phase.finish();
    }
    return g;
}

// A medium's `albedo` and `sigma_t`: numbers or rgb (`volumes` holds a heterogeneous medium's
// constvolume values in their place).
Json translateHomogeneous(Plugin& p, const std::map<std::string, Json>& volumes = {}) {
    const auto given = [&](const char* name, double fallback) {
        const auto v = volumes.find(name);
        return v != volumes.end() ? v->second : coefficient(p, name, fallback);
    };
    const Json albedo = given("albedo", 0.75);
    const Json sigmaT = given("sigma_t", 1.0);
    if (albedo.is_array() || albedo.get<double>() > 1)
        for (int c = 0; c < 3; ++c)
            if (component(albedo, c) > 1) p.fail("parameter \"albedo\" must be <= 1");
    const double scale = p.number("scale", 1.0);
    if (!(scale >= 0) || !std::isfinite(scale)) p.fail("parameter \"scale\" must be >= 0");
    // Shadow rays from inside the medium are on in lamina always; the flag changes the time a
    // render takes, not its expected value.
    p.boolean("sample_emitters", true);
    if (!p.boolean("has_spectral_extinction", true))
        p.fail(
            "has_spectral_extinction false is not supported (lamina's extinction is "
            "per wavelength)");
    const double g = phaseAsymmetry(p);
    if ((albedo.is_array() || sigmaT.is_array()) && !(albedo.is_number() && sigmaT.is_number()))
        p.warn(
            "sigma_s = albedo sigma_t and sigma_a = sigma_t - sigma_s per RGB channel: the "
            "same RGB as Mitsuba's, but spectral mode upsamples lamina's sigma_a and sigma_s "
            "where Mitsuba upsamples albedo and sigma_t, so chromatic spectra differ slightly");
    p.finish();
    // Mitsuba's medium: sigma_s = albedo sigma_t, sigma_a = (1 - albedo) sigma_t.
    return {{"type", "homogeneous"},
            {"sigma_s", perChannel(albedo, sigmaT, [](double a, double t) { return a * t; })},
            {"sigma_a", perChannel(albedo, sigmaT, [](double a, double t) { return (1 - a) * t; })},
            {"scale", scale},
            {"g", g}};
}

// A heterogeneous medium's volume (mitsuba3 src/volumes/grid.cpp and const.cpp): a
// constvolume's value, or a gridvolume's file with its to_world, which becomes a lamina grid.
struct Volume {
    std::optional<Json> constant;
    std::filesystem::path file;
    glm::dmat4 toWorld{1.0};
};

Volume readVolume(const Element& e, Plugin& medium) {
    Plugin v(e, medium.document(), medium.diagnostics());
    Volume out;
    if (v.type() == "constvolume" || v.type() == "const") {
        out.constant = coefficient(v, "value", 1.0);
    } else if (v.type() == "gridvolume" || v.type() == "grid") {
        const auto file = v.file("filename");
        if (!file) v.fail("needs a filename (a grid given in memory cannot be read)");
        out.file = *file;
        if (const auto filter = v.string("filter_type"); filter && *filter != "trilinear")
            v.fail("filter_type \"" + *filter + "\" is not supported (trilinear)");
        if (const auto wrap = v.string("wrap_mode"); wrap && *wrap != "clamp")
            v.fail("wrap_mode \"" + *wrap + "\" is not supported (clamp)");
        if (v.boolean("use_grid_bbox", false))
            v.fail("use_grid_bbox is not supported: give the box as to_world");
        // Spectral conversion of 3-channel data (raw) and the hardware lookups (accel) do not
        // change a trilinear RGB lookup; max_value only bounds Mitsuba's majorant.
        v.boolean("raw", false);
        v.boolean("accel", true);
        v.optionalNumber("max_value");
        if (const auto m = v.transform("to_world")) out.toWorld = m->matrix;
    } else {
        v.fail("the volume \"" + v.type() + "\" is not supported (gridvolume, constvolume)");
    }
    v.finish();
    return out;
}

// Mitsuba's heterogeneous medium (mitsuba3 src/media/heterogeneous.cpp): sigma_t and albedo
// volumes (or numbers), `scale`, a phase function. A sigma_t grid becomes lamina's grid medium:
// its values are the density (1 or 3 channels), sigma_s = albedo scale and sigma_a =
// (1 - albedo) scale per unit of it, over the unit cube placed by the volume's to_world, with
// clamped edges (gridvolume's default wrap mode); outside the cube the medium is empty, as
// Mitsuba samples it inside the volume's box only.
Json translateHeterogeneous(Translation& t, Plugin& p) {
    std::map<std::string, Json> constants;
    std::optional<Volume> grid;
    for (const Element& c : p.element().children) {
        const Element* target = c.tag == "ref" ? &t.document.find(*c.attribute("id"), c) : &c;
        if (target->tag != "volume") continue;
        const std::string* name = c.attribute("name");
        if (!name || (*name != "sigma_t" && *name != "albedo"))
            throw InputError(c.where() + ": " + p.element().describe() +
                             ": a volume of a medium is named \"sigma_t\" or \"albedo\"");
        Volume v = readVolume(*target, p);
        if (v.constant) {
            constants[*name] = *v.constant;
        } else if (*name == "albedo") {
            throw InputError(c.where() + ": " + p.element().describe() +
                             ": an albedo grid is not supported (lamina's grid media scale "
                             "sigma_a and sigma_s by one grid, not by the product of two)");
        } else {
            grid = std::move(v);
        }
    }
    p.objects("volume");  // read above
    // A sigma_t grid is the density: sigma_t is 1 per unit of it.
    if (grid) constants["sigma_t"] = 1.0;
    Json medium = translateHomogeneous(p, constants);
    if (!grid) return medium;  // constant volumes: the homogeneous medium
    medium["type"] = "grid";
    medium["density"] = documentPath(grid->file, t.pathsRelativeTo);
    if (grid->toWorld != glm::dmat4(1.0)) {
        Json rows = Json::array();
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c)
                rows.push_back(grid->toWorld[c][r]);
        medium["transform"] = Json::array({Json{{"matrix", rows}}});
    }
    return medium;
}

}  // namespace

std::string useMedium(Translation& t, const Element& medium) {
    if (const auto it = t.media.find(&medium); it != t.media.end()) return it->second;
    const std::string* id = medium.attribute("id");
    std::string name = id ? *id : "medium_" + std::to_string(t.media.size() + 1);
    // "vacuum" names no medium in lamina's documents.
    if (name == kDocumentVacuum) name = "mitsuba_vacuum";
    Plugin p(medium, t.document, t.diagnostics);
    if (p.type() == "homogeneous")
        t.scene["media"][name] = translateHomogeneous(p);
    else if (p.type() == "heterogeneous")
        t.scene["media"][name] = translateHeterogeneous(t, p);
    else
        p.fail("the medium \"" + p.type() + "\" is not supported (homogeneous, heterogeneous)");
    t.media.emplace(&medium, name);
    return name;
}

void shapeMedia(Translation& t, Plugin& p, Json& shape) {
    p.objects("medium");  // consumed here; their names below
    for (const Element& c : p.element().children) {
        const Element* target = &c;
        if (c.tag == "ref") target = &t.document.find(*c.attribute("id"), c);
        if (target->tag != "medium") continue;
        const std::string* side = c.attribute("name");
        if (!side || (*side != "interior" && *side != "exterior"))
            throw InputError(c.where() + ": " + p.element().describe() +
                             ": a medium of a shape is named \"interior\" or \"exterior\"");
        if (shape.contains(*side))
            throw InputError(c.where() + ": " + p.element().describe() + ": a second " + *side +
                             " medium");
        shape[*side] = useMedium(t, *target);
    }
}

std::optional<std::string> endpointMedium(Translation& t, Plugin& p) {
    const auto media = p.objects("medium");
    if (media.size() > 1) p.fail("an endpoint takes one medium (Mitsuba's rule too)");
    if (media.empty()) return std::nullopt;
    return useMedium(t, *media[0]);
}

}  // namespace lamina::render::mitsuba
