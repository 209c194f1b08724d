#include "lamina/experiments/convergence.h"
#include "lamina/experiments/convergence_runs.h"
#include "lamina/experiments/interrupted.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
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
    if (sampler != measuredSampler) return std::nullopt;
    const std::string hash = metadataValue(reference, "scene_hash");
    const bool sameScene = hash == render::sceneHash(scene);
    // sobol-global's film positions are one fixed pattern whatever the seed.
    if (sampler == render::kSamplerNames.name(render::SamplerKind::SobolGlobal))
        return formatText(
            "the reference was rendered %swith the sampler sobol-global, as the measured "
            "renders are: its film positions are the same for every seed, so their samples are "
            "correlated with its own and the measured error would be understated; render the "
            "reference with another sampler (lamina render --sampler sobol) or pass "
            "--allow-correlated-reference",
            sameScene ? "from the same scene files " : "");
    if (seed != measuredSeed) return std::nullopt;
    return formatText(
        "the reference was rendered %swith the same sampler (%s) and seed (%s) as the measured "
        "renders, so their samples are correlated with its own: the measured error would be "
        "understated and the slope too steep; render the reference with another seed "
        "(lamina render --seed) or pass --allow-correlated-reference",
        sameScene ? "from the same scene files " : "", sampler.c_str(), seed.c_str());
}

namespace {

/// The independence premise of a given reference (referenceCorrelation), and the note the
/// summary prints.
Premise independencePremise(const ConvergenceInputs& in, const render::RgbImage& ref,
                            const render::SceneDesc& scene, std::string& note) {
    const std::optional<std::string> correlated = referenceCorrelation(ref, scene, in.overrides);
    if (correlated && !in.allowCorrelatedReference)
        return {"independence", PremiseOutcome::Refused, *correlated};
    if (correlated) {
        note =
            "correlated with the measured renders (same sampler and seed, allowed by "
            "--allow-correlated-reference): the errors below are understated";
        return {"independence", PremiseOutcome::Flagged, note};
    }
    if (metadataValue(ref, "seed").empty()) {
        note =
            "without lamina metadata (another renderer?): its sampler and seed, and so its "
            "independence from the measured renders, could not be checked";
        return {"independence", PremiseOutcome::NotChecked, note};
    }
    note = "rendered by lamina with another seed or sampler";
    return {"independence", PremiseOutcome::Holds, note};
}

}  // namespace

std::string renderedReferenceName(render::RenderModeKind mode) {
    return "reference_" + std::string(render::kRenderModeNames.name(mode)) + ".exr";
}

ConvergenceResult runConvergence(const ConvergenceInputs& in) {
    if (in.resume && in.keepDirectory.empty())
        throw std::logic_error("runConvergence: resume without a keepDirectory");
    const render::SceneDesc scene = render::loadScene(in.scene);
    for (const render::RenderModeKind m : in.modes) {
        for (const render::IntegratorKind i : in.integrators)
            render::checkMedia(scene, m, i);
        if (in.reference.empty()) render::checkMedia(scene, m, in.referenceIntegrator);
    }
    ConvergenceResult result{in, {}, {}, {}, {}};

    // The premises of every reference read from a file, before any render: one mode's
    // reference may be given, another resumed, another still to render.
    std::map<render::RenderModeKind, render::RgbImage> references;
    std::map<render::RenderModeKind, ReferenceFacts> facts;
    std::string refused;
    for (const render::RenderModeKind m : in.modes) {
        const std::filesystem::path kept = in.keepDirectory / renderedReferenceName(m);
        const bool given = !in.reference.empty();
        if (!given && !(in.resume && std::filesystem::exists(kept))) continue;
        const std::string path = given ? in.reference : kept.string();
        references[m] = render::readLinearRgbImage(path);
        facts[m] = readReferenceFacts(
            path, given ? ReferenceSource::Given : ReferenceSource::Resumed, references[m]);
        std::vector<Premise> premises = referencePremises(facts[m], scene, in.overrides, m);
        if (given)
            premises.push_back(independencePremise(in, references[m], scene, result.referenceNote));
        for (Premise& p : premises) {
            if (p.outcome == PremiseOutcome::Refused && refused.find(p.detail) == std::string::npos)
                refused += (refused.empty() ? path + ": " : "; ") + p.detail;
            result.premises.push_back({m, std::move(p)});
        }
    }
    if (!refused.empty()) throw InputError(refused);

    try {
        // One reference per mode (the two modes converge to slightly different images),
        // unless the caller gives one or the interrupted run rendered it.
        const double refSeconds = in.referenceSeconds > 0 ? in.referenceSeconds : 20 * in.seconds;
        for (const render::RenderModeKind m : in.modes) {
            if (references.count(m)) continue;
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
            facts[m] = renderedReferenceFacts(renderedReferenceName(m), *r.film, references[m]);
            for (Premise& p : referencePremises(facts[m], scene, o, m))
                result.premises.push_back({m, std::move(p)});
            render::ImageMetadata meta = render::renderMetadata(scene, o, r, in.build);
            result.references.push_back({m, std::move(r), std::move(meta)});
            if (in.onReference) in.onReference(result.references.back());
        }

        for (const render::RenderModeKind m : in.modes) {
            const RunSettings settings = runSettings(in, scene, references[m]);
            double smallest = INFINITY;
            for (const render::IntegratorKind i : in.integrators) {
                std::optional<ConvergenceCurve> run;
                if (in.resume) run = readRunFile(in.keepDirectory, i, m, settings, references[m]);
                if (run) {
                    run->resumed = true;
                    tell(in.progress,
                         formatText("%s, %s mode: kept from %s\n",
                                    std::string(render::kIntegratorNames.name(i)).c_str(),
                                    std::string(render::kRenderModeNames.name(m)).c_str(),
                                    runFile(i, m).string().c_str()));
                } else {
                    render::RenderOptions o = in.overrides;
                    o.mode = m;
                    o.integrator = i;
                    o.seconds = in.seconds;
                    ErrorLog log(references[m]);
                    tell(in.progress,
                         formatText("%s, %s mode: %.3g s...\n",
                                    std::string(render::kIntegratorNames.name(i)).c_str(),
                                    std::string(render::kRenderModeNames.name(m)).c_str(),
                                    in.seconds));
                    const render::RenderResult r =
                        renderWhole(scene, o, [&](const render::RenderProgress& p) {
                            log.record(p.seconds, p.sppDone, *p.film);
                        });
                    run =
                        ConvergenceCurve{i, m, std::move(log), double(r.paths) / r.seconds, r.spp};
                    if (!in.keepDirectory.empty()) writeRunFile(in.keepDirectory, *run, settings);
                }
                if (!run->log.rows().empty())
                    smallest = std::min(smallest, run->log.rows().back().metrics.relmse);
                result.curves.push_back(std::move(*run));
                // The reference's noise against the errors the runs reach: a given reference
                // too noisy to score them is refused at the first run that shows it.
                const Premise noise = noisePremise(facts[m], smallest, in.allowNoisyReference);
                if (noise.outcome == PremiseOutcome::Refused)
                    throw InputError(facts[m].name + ": " + noise.detail);
            }
            result.premises.push_back(
                {m, noisePremise(facts[m], smallest, in.allowNoisyReference)});
        }
    } catch (const Interrupted&) {
        if (in.onInterrupted) in.onInterrupted(result);
        throw;
    }
    return result;
}

}  // namespace lamina::experiments
