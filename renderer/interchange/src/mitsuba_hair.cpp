// Mitsuba 3's `hair` BSDF (mitsuba3 src/bsdfs/hair.cpp) -> lamina's `hair` material. Both are
// Chiang et al. 2016's fibre with d'Eon et al. 2011's longitudinal lobes, and they agree term
// by term: Mitsuba's longitudinal_roughness and azimuthal_roughness are the model's beta_m and
// beta_n (its update() maps them to the variance v and the logistic scale s by Chiang's fits,
// as lamina's beta_m and beta_n), scale_tilt is the cuticle angle alpha in degrees, the index
// is int_ior / ext_ior, h is taken from the direction and the tube's normal, and the pigments
// are the same d'Eon et al. 2011 coefficients per unit radius. The absorption it attenuates by,
// exp(-sigma_a 2 cos gamma_t / cos theta_t), measures the chord in radii, so sigma_a is per
// unit radius (the plugin's documentation says "inverse scene units"; its code does not).
#include <cmath>
#include <string>

#include "lamina/core/json_reader.h"
#include "mitsuba_bsdf_parameters.h"
#include "mitsuba_bsdfs.h"

namespace lamina::render::mitsuba {

namespace {

double roughness(Plugin& p, const char* name) {
    const double b = p.number(name, 0.3);
    if (!(b >= 0 && b <= 1)) p.fail(std::string(name) + " must be in [0, 1] (as Mitsuba asks)");
    if (b < 0.01)
        p.warn(std::string(name) + " " + formatNumber(b) +
               " became 0.01 (lamina's smallest hair roughness)");
    return b;
}

}  // namespace

Json hairMaterial(Plugin& p) {
    Json m{{"type", "hair"}};
    const double betaM = roughness(p, "longitudinal_roughness");
    const double betaN = roughness(p, "azimuthal_roughness");
    if (betaM != 0.3) m["beta_m"] = betaM;
    if (betaN != 0.3) m["beta_n"] = betaN;
    const double alpha = p.number("scale_tilt", 2.0);
    if (!(std::abs(alpha) <= 30)) p.fail("scale_tilt must be in [-30, 30] degrees for lamina");
    if (alpha != 2.0) m["alpha"] = alpha;
    const double interior = indexOfRefraction(p, "int_ior", "amber");
    const double exterior = indexOfRefraction(p, "ext_ior", "air");
    const double eta = interior / exterior;
    if (!(eta > 1 && eta <= 5))
        p.fail("int_ior / ext_ior must be in (1, 5] (a fibre denser than its surroundings)");
    m["eta"] = eta;
    const bool pigments = p.has("eumelanin") || p.has("pheomelanin");
    const double scale = p.number("scale", 1.0);
    if (p.has("sigma_a")) {
        if (pigments) p.fail("give sigma_a or eumelanin and pheomelanin, not both (as Mitsuba)");
        if (p.texture("sigma_a")) p.fail("a textured sigma_a is not supported (give a colour)");
        const Json sigma = *p.color("sigma_a");
        if (sigma.is_object())
            p.fail("sigma_a as a spectrum is not supported (give rgb: lamina's is Rec.709)");
        if (!(scale >= 0)) p.fail("scale must be >= 0");
        Json rgb = Json::array();
        for (int c = 0; c < 3; ++c) {
            const double v =
                scale * (sigma.is_number() ? sigma.get<double>() : sigma[c].get<double>());
            if (!(v >= 0 && v <= 1e4)) p.fail("sigma_a x scale must be in [0, 1e4] per channel");
            rgb.push_back(v);
        }
        m["sigma_a"] = rgb;
        return m;
    }
    // Mitsuba's defaults are eumelanin 1.3 and pheomelanin 0.2 (lamina's, 1.3 and 0): both are
    // written. `scale` multiplies sigma_a only.
    const double eumelanin = p.number("eumelanin", 1.3);
    const double pheomelanin = p.number("pheomelanin", 0.2);
    if (!(eumelanin >= 0 && eumelanin <= 100) || !(pheomelanin >= 0 && pheomelanin <= 100))
        p.fail("eumelanin and pheomelanin must be in [0, 100]");
    if (scale != 1.0)
        p.warn("scale ignored: it multiplies sigma_a only, not the pigments (as in Mitsuba)");
    m["eumelanin"] = eumelanin;
    m["pheomelanin"] = pheomelanin;
    return m;
}

}  // namespace lamina::render::mitsuba
