#include "lamina/experiments/convergence.h"
#include "lamina/experiments/interrupted.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "lamina/core/error.h"
#include "lamina/experiments/text_format.h"

namespace lamina::experiments {

double fittedSlope(const std::vector<ErrorLog::Row>& rows, SlopeAxis axis) {
    if (rows.empty()) return NAN;
    const auto along = [axis](const ErrorLog::Row& r) {
        return axis == SlopeAxis::Seconds ? r.seconds : double(r.spp);
    };
    const double from = 0.1 * along(rows.back());
    double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const auto& r : rows) {
        if (along(r) < from || !(r.metrics.relmse > 0) || !(along(r) > 0)) continue;
        const double x = std::log(along(r)), y = std::log(r.metrics.relmse);
        n += 1;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    const double den = n * sxx - sx * sx;
    if (n < 3 || !(std::abs(den) > 0)) return NAN;
    return (n * sxy - sx * sy) / den;
}

double timeToReach(const std::vector<ErrorLog::Row>& rows, double level) {
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (!(rows[i].metrics.relmse <= level)) continue;
        if (i == 0) return rows[0].seconds;
        const double x0 = std::log(rows[i - 1].seconds), x1 = std::log(rows[i].seconds);
        const double y0 = std::log(rows[i - 1].metrics.relmse),
                     y1 = std::log(rows[i].metrics.relmse);
        const double t = y1 != y0 ? (std::log(level) - y0) / (y1 - y0) : 1.0;
        return std::exp(x0 + std::clamp(t, 0.0, 1.0) * (x1 - x0));
    }
    return NAN;
}

namespace {

std::string metadataValue(const render::RgbImage& image, const std::string& key) {
    const auto it = image.metadata.find("lamina:" + key);
    return it == image.metadata.end() ? std::string() : it->second;
}

}  // namespace

std::optional<std::string> referenceCorrelation(const render::RgbImage& reference,
                                                const render::SceneDesc& scene,
                                                const render::RenderOptions& measured) {
    const std::string seed = metadataValue(reference, "seed");
    const std::string sampler = metadataValue(reference, "sampler");
    if (seed.empty() || sampler.empty()) return std::nullopt;
    const std::string measuredSeed = std::to_string(measured.seed.value_or(scene.settings.seed));
    const std::string measuredSampler(
        render::kSamplerNames.name(measured.sampler.value_or(scene.settings.sampler)));
    if (seed != measuredSeed || sampler != measuredSampler) return std::nullopt;
    const std::string hash = metadataValue(reference, "scene_hash");
    const bool sameScene = hash == render::sceneHash(scene);
    return formatText(
        "the reference was rendered %swith the same sampler (%s) and seed (%s) as the measured "
        "renders, so their samples are correlated with its own: the measured error would be "
        "understated and the slope too steep; render the reference with another seed "
        "(lamina render --seed) or pass --allow-correlated-reference",
        sameScene ? "from the same scene files " : "", sampler.c_str(), seed.c_str());
}

ConvergenceResult runConvergence(const ConvergenceInputs& in) {
    for (const render::RenderModeKind m : in.modes)
        for (const render::IntegratorKind i : in.integrators)
            render::checkModeAndIntegrator(m, i);
    const render::SceneDesc scene = render::loadScene(in.scene);
    for (const render::RenderModeKind m : in.modes) {
        for (const render::IntegratorKind i : in.integrators)
            render::checkMedia(scene, m, i);
        if (in.reference.empty()) render::checkMedia(scene, m, in.referenceIntegrator);
    }
    ConvergenceResult result{in, {}, {}, {}};

    // One reference per mode (the two modes converge to slightly different images), unless
    // the caller gives one.
    std::map<render::RenderModeKind, render::RgbImage> references;
    if (!in.reference.empty()) {
        const render::RgbImage ref = render::readLinearRgbImage(in.reference);
        const std::optional<std::string> correlated =
            referenceCorrelation(ref, scene, in.overrides);
        if (correlated && !in.allowCorrelatedReference)
            throw InputError(in.reference + ": " + *correlated);
        if (correlated)
            result.referenceNote =
                "correlated with the measured renders (same sampler and seed, allowed by "
                "--allow-correlated-reference): the errors below are understated";
        else if (metadataValue(ref, "seed").empty())
            result.referenceNote =
                "without lamina metadata (another renderer?): its sampler and seed, and so its "
                "independence from the measured renders, could not be checked";
        else
            result.referenceNote = "rendered by lamina with another seed or sampler";
        for (const render::RenderModeKind m : in.modes)
            references[m] = ref;
    } else {
        const double refSeconds = in.referenceSeconds > 0 ? in.referenceSeconds : 20 * in.seconds;
        for (const render::RenderModeKind m : in.modes) {
            render::RenderOptions o = in.overrides;
            o.mode = m;
            o.integrator = in.referenceIntegrator;
            o.sampler = render::SamplerKind::Sobol;
            o.seconds = refSeconds;
            // Its own seed: with the measured renders' seed, their first samples would be the
            // reference's and their error would look smaller than it is.
            o.seed = (scene.settings.seed + 0x5eed) & 0x7fffffffu;
            tell(in.progress,
                 formatText(
                     "rendering the %s reference (%s integrator, %.0f s)...\n",
                     std::string(render::kRenderModeNames.name(m)).c_str(),
                     std::string(render::kIntegratorNames.name(in.referenceIntegrator)).c_str(),
                     refSeconds));
            render::RenderResult r = renderWhole(scene, o);
            references[m] = filmImage(*r.film);
            render::ImageMetadata meta = render::renderMetadata(scene, o, r, in.build);
            result.references.push_back({m, std::move(r), std::move(meta)});
            if (in.onReference) in.onReference(result.references.back());
        }
    }

    for (const render::RenderModeKind m : in.modes)
        for (const render::IntegratorKind i : in.integrators) {
            render::RenderOptions o = in.overrides;
            o.mode = m;
            o.integrator = i;
            o.seconds = in.seconds;
            ErrorLog log(references[m]);
            tell(in.progress,
                 formatText("%s, %s mode: %.3g s...\n",
                            std::string(render::kIntegratorNames.name(i)).c_str(),
                            std::string(render::kRenderModeNames.name(m)).c_str(), in.seconds));
            const render::RenderResult r =
                renderWhole(scene, o, [&](const render::RenderProgress& p) {
                    log.record(p.seconds, p.sppDone, *p.film);
                });
            result.curves.push_back({i, m, std::move(log), double(r.paths) / r.seconds, r.spp});
        }
    return result;
}

}  // namespace lamina::experiments
