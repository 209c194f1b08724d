#include "lamina/experiments/convergence_premises.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <variant>

#include "lamina/experiments/image_metrics.h"
#include "lamina/experiments/text_format.h"
#include "lamina/output/render_metadata.h"

namespace lamina::experiments {

namespace {

std::string metadataValue(const ReferenceFacts& r, const std::string& key) {
    const auto it = r.metadata.find("lamina:" + key);
    return it == r.metadata.end() ? std::string() : it->second;
}

/// A premise read from one metadata key: NotChecked without it, Refused when it differs.
Premise keyPremise(const ReferenceFacts& r, const std::string& check, const std::string& key,
                   const std::string& expected, const std::string& what) {
    const std::string found = metadataValue(r, key);
    if (found.empty())
        return {check, PremiseOutcome::NotChecked,
                "the reference has no lamina:" + key + " metadata (another renderer?)"};
    if (found != expected)
        return {check, PremiseOutcome::Refused,
                "the reference was rendered with " + what + " " + found +
                    ", the measured renders use " + expected};
    return {check, PremiseOutcome::Holds, what + " " + found + " in both"};
}

/// Lights that only next-event estimation reaches: a point, spot or directional light is a
/// delta distribution that no BSDF-sampled ray hits.
bool hasDeltaLights(const render::SceneDesc& scene) {
    return std::any_of(scene.lights.begin(), scene.lights.end(), [](const render::LightDesc& l) {
        return !std::holds_alternative<render::EnvironmentLightDesc>(l);
    });
}

}  // namespace

std::vector<Premise> referencePremises(const ReferenceFacts& reference,
                                       const render::SceneDesc& scene,
                                       const render::RenderOptions& measured,
                                       render::RenderModeKind mode) {
    if (reference.source == ReferenceSource::Rendered)
        return {{"reference", PremiseOutcome::Flagged,
                 "self-rendered by this run (" + reference.name +
                     "): the measured renders' mode, resolution, scene and max_depth by "
                     "construction, its own seed"}};
    std::vector<Premise> out;
    if (reference.source == ReferenceSource::Resumed)
        out.push_back(
            {"reference", PremiseOutcome::Flagged,
             "rendered by the interrupted run (" + reference.name + "), checked as a given one"});

    out.push_back(keyPremise(reference, "mode", "mode",
                             std::string(render::kRenderModeNames.name(mode)), "mode"));

    // The size of the measured films: the override, else the scene's film (or its crop).
    int width = scene.film.width, height = scene.film.height;
    if (measured.resolution)
        std::tie(width, height) = *measured.resolution;
    else if (scene.film.crop)
        std::tie(width, height) = std::pair{scene.film.crop->width(), scene.film.crop->height()};
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    const std::string found =
        std::to_string(reference.width) + "x" + std::to_string(reference.height);
    if (found != size)
        out.push_back({"resolution", PremiseOutcome::Refused,
                       "the reference is " + found + ", the measured renders " + size});
    else
        out.push_back({"resolution", PremiseOutcome::Holds, size + " in both"});

    Premise sceneCheck = keyPremise(reference, "scene", "scene_hash", render::sceneHash(scene),
                                    "the scene files of hash");
    if (sceneCheck.outcome == PremiseOutcome::Refused)
        sceneCheck.detail =
            "the reference was rendered from other scene files (lamina:scene_hash " +
            metadataValue(reference, "scene_hash") + ", " + metadataValue(reference, "scene") +
            ") than " + scene.file.string() + " (" + render::sceneHash(scene) + ")";
    out.push_back(std::move(sceneCheck));

    const int maxDepth = measured.maxDepth.value_or(scene.settings.maxDepth);
    out.push_back(
        keyPremise(reference, "max_depth", "max_depth", std::to_string(maxDepth), "max_depth"));

    // A setting of the reference's integrator whose image converges elsewhere: next-event
    // estimation off misses every delta light.
    const std::string nextEvent = metadataValue(reference, "next_event");
    if (nextEvent == "0" && hasDeltaLights(scene))
        out.push_back({"integrator settings", PremiseOutcome::Refused,
                       "the reference was rendered without next-event estimation "
                       "(lamina:next_event 0), which never reaches the scene's point, spot or "
                       "directional lights: it converges to another image"});
    else if (metadataValue(reference, "integrator").empty())
        out.push_back({"integrator settings", PremiseOutcome::NotChecked,
                       "the reference has no lamina:integrator metadata (another renderer?)"});
    else
        out.push_back({"integrator settings", PremiseOutcome::Holds,
                       metadataValue(reference, "integrator") +
                           " integrator, no setting that converges to another image"});
    return out;
}

double referenceNoiseFloor(const std::vector<float>& reference,
                           const std::vector<float>& variance) {
    double sum = 0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < reference.size() && i < variance.size(); ++i) {
        const double r = reference[i], v = variance[i];
        if (!std::isfinite(r) || !std::isfinite(v) || v < 0) continue;
        sum += v / (r * r + kRelMseEpsilon);
        ++n;
    }
    return n ? sum / double(n) : NAN;
}

Premise noisePremise(const ReferenceFacts& reference, double smallestFinalRelMse, bool allowNoisy,
                     const NoiseConsequence& consequence) {
    if (!reference.noiseFloor || !std::isfinite(*reference.noiseFloor))
        return {"reference noise", PremiseOutcome::NotChecked,
                !reference.noiseSource.empty()
                    ? reference.noiseSource
                    : "the reference has no variance channels (Variance.R/G/B or Variance.Y): "
                      "its own noise could not be estimated"};
    const double floor = *reference.noiseFloor;
    if (floor == 0)
        return {"reference noise", PremiseOutcome::Holds,
                "its variance channels are 0 (" + reference.noiseSource + "): no noise"};
    if (!(smallestFinalRelMse > 0) || !std::isfinite(smallestFinalRelMse))
        return {"reference noise", PremiseOutcome::NotChecked,
                formatText("its noise adds %.3g to every relMSE (from its %s); no run measured "
                           "an error to set it against",
                           floor, reference.noiseSource.c_str())};
    const double share = floor / smallestFinalRelMse;
    const std::string measured = formatText(
        "its noise adds %.3g to every relMSE (from its %s), %.1f%% of the smallest "
        "final relMSE of the runs (%.3g)",
        floor, reference.noiseSource.c_str(), 100 * share, smallestFinalRelMse);
    if (share <= kMaxReferenceNoiseShare)
        return {"reference noise", PremiseOutcome::Holds,
                measured + formatText(" (at most %.0f%%)", 100 * kMaxReferenceNoiseShare)};
    const std::string flattens =
        !consequence.flattensSlopes ? formatText("; above %.0f%% %s", 100 * kMaxReferenceNoiseShare,
                                                 consequence.otherwise.c_str())
        : share < 1                 ? formatText(
                                          "; above %.0f%% it flattens the slopes (to about %.2f at the "
                                                          "end of the run)",
                                          100 * kMaxReferenceNoiseShare, -(1 - share))
                    : std::string("; the runs' errors are the reference's noise (slopes near 0)");
    if (reference.source == ReferenceSource::Given && !allowNoisy)
        return {
            "reference noise", PremiseOutcome::Refused,
            measured + flattens + ": render a longer reference or pass --allow-noisy-reference"};
    const std::string why = reference.source == ReferenceSource::Given
                                ? " (allowed by --allow-noisy-reference)"
                                : ": " + consequence.quieter;
    return {"reference noise", PremiseOutcome::Flagged, measured + flattens + why};
}

ReferenceFacts readReferenceFacts(const std::string& path, ReferenceSource source,
                                  const render::RgbImage& image) {
    ReferenceFacts facts;
    facts.name = path;
    facts.source = source;
    facts.width = image.width;
    facts.height = image.height;
    facts.metadata = image.metadata;
    const render::FloatImage all = render::readFloatImage(path);
    if (all.width != image.width || all.height != image.height) return facts;
    const int r = all.channel("Variance.R"), g = all.channel("Variance.G"),
              b = all.channel("Variance.B"), y = all.channel("Variance.Y");
    const bool rgb = r >= 0 && g >= 0 && b >= 0;
    if (!rgb && y < 0) return facts;
    // A pixel of one sample has no variance estimate (the film writes 0).
    const auto sppEntry = image.metadata.find("lamina:spp");
    const std::string spp = sppEntry == image.metadata.end() ? std::string() : sppEntry->second;
    if (!spp.empty() && std::atoi(spp.c_str()) < 2) {
        facts.noiseSource =
            "the reference has " + spp +
            " sample per pixel: its variance channels hold no estimate of its noise";
        return facts;
    }
    std::vector<float> variance;
    variance.reserve(image.pixels.size());
    for (int py = 0; py < all.height; ++py)
        for (int px = 0; px < all.width; ++px)
            for (const int c : {r, g, b})
                variance.push_back(all.at(px, py, rgb ? c : y));
    facts.noiseFloor = referenceNoiseFloor(image.pixels, variance);
    facts.noiseSource = rgb ? "Variance.R/G/B channels" : "Variance.Y channel, for every channel";
    return facts;
}

ReferenceFacts renderedReferenceFacts(const std::string& name, const render::Film& film,
                                      const render::RgbImage& image) {
    ReferenceFacts facts;
    facts.name = name;
    facts.source = ReferenceSource::Rendered;
    facts.width = image.width;
    facts.height = image.height;
    std::vector<float> variance;
    variance.reserve(image.pixels.size());
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const Rgb<double> v = film.varianceOfMeanRgb(x, y);
            for (int c = 0; c < 3; ++c)
                variance.push_back(float(v[c]));
        }
    facts.noiseFloor = referenceNoiseFloor(image.pixels, variance);
    facts.noiseSource = "per-pixel variance of its samples";
    return facts;
}

std::string describePremise(const Premise& premise) {
    return premise.check + " (" + std::string(kPremiseOutcomeNames.name(premise.outcome)) +
           "): " + premise.detail;
}

}  // namespace lamina::experiments
