// Mitsuba 3's media -> the lamina document's `media` (docs/interchange.md, "Mitsuba 3"): the
// `homogeneous` medium (mitsuba3 src/media/homogeneous.cpp: albedo, sigma_t, scale, a nested
// phase function), the `interior` and `exterior` media of shapes and the medium of the
// sensor. Heterogeneous media are refused at their line.
#include <cmath>

#include "document_names.h"
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

Json translateHomogeneous(Plugin& p) {
    if (p.type() != "homogeneous")
        p.fail("the medium \"" + p.type() +
               "\" is not supported (the importer translates homogeneous media; grid "
               "volumes are not translated yet)");
    if (p.has("albedo") && p.tagOf("albedo") == "volume")
        p.fail("a spatially varying albedo (a volume) is not supported");
    const Json albedo = coefficient(p, "albedo", 0.75);
    const Json sigmaT = coefficient(p, "sigma_t", 1.0);
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

}  // namespace

std::string useMedium(Translation& t, const Element& medium) {
    if (const auto it = t.media.find(&medium); it != t.media.end()) return it->second;
    const std::string* id = medium.attribute("id");
    std::string name = id ? *id : "medium_" + std::to_string(t.media.size() + 1);
    // "vacuum" names no medium in lamina's documents.
    if (name == kDocumentVacuum) name = "mitsuba_vacuum";
    Plugin p(medium, t.document, t.diagnostics);
    t.scene["media"][name] = translateHomogeneous(p);
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
