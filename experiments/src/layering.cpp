#include "lamina/experiments/layering.h"

#include <algorithm>
#include <cmath>

#include <tbb/parallel_for.h>

#include "lamina/bsdf/material_builder.h"
#include "lamina/core/error.h"
#include "lamina/core/hash.h"
#include "lamina/experiments/image_metrics.h"
#include "lamina/experiments/interrupted.h"
#include "lamina/experiments/kept_renders.h"
#include "lamina/spectral/color_difference.h"

namespace lamina::experiments {

namespace {

using S = Rgb<double>;
using V3 = Vec3<double>;

struct DirectionPair {
    V3 wo, wi;
};

double radians(double degrees) {
    return degrees * kPi<double> / 180.0;
}

/// wo at theta_o in the x-z plane (phi_o = 0).
V3 outgoing(double thetaO) {
    return {std::sin(radians(thetaO)), 0.0, std::cos(radians(thetaO))};
}

/// wi in the plane of incidence at signed theta_i: positive on the mirror side of wo.
V3 incident(double thetaI) {
    return {-std::sin(radians(thetaI)), 0.0, std::cos(radians(thetaI))};
}

std::vector<double> degreesFrom(double first, double last, double step) {
    std::vector<double> v;
    for (double d = first; d <= last + 1e-9; d += step)
        v.push_back(d);
    return v;
}

/// The walk's f |cos theta_i| (luminance) at every pair: `estimates` independent estimates
/// each, from a generator of its own per pair (so the result does not depend on threads).
std::vector<MeanEstimate> walkEval(const CoatedBxdf<S>& walk,
                                   const std::vector<DirectionPair>& pairs, int estimates,
                                   std::uint64_t seed) {
    std::vector<MeanEstimate> out(pairs.size());
    tbb::parallel_for(std::size_t(0), pairs.size(), [&](std::size_t i) {
        if (render::renderInterruptFlag().load()) return;  // stopIfInterrupted() below
        Pcg32 rng(hashValues({seed, 0x77616c6b, i}));
        RunningMean m;
        for (int e = 0; e < estimates; ++e) {
            if ((e & 1023) == 1023 && render::renderInterruptFlag().load()) return;
            m.add(luminance(
                walk.estimate(pairs[i].wo, pairs[i].wi, TransportMode::Radiance, rng).value));
        }
        out[i] = m.estimate();
    });
    stopIfInterrupted();
    return out;
}

/// An analytic BSDF's f |cos theta_i|: exact (standard error 0).
std::vector<MeanEstimate> exactEval(const Bxdf<S>& bsdf, const std::vector<DirectionPair>& pairs) {
    std::vector<MeanEstimate> out;
    for (const DirectionPair& p : pairs)
        out.push_back({luminance(bsdf.eval(p.wo, p.wi, TransportMode::Radiance)), 0.0, 1});
    return out;
}

/// Directional albedo (luminance) at each theta_o: the mean of sample() weights, a failed
/// sample counting 0 (for the walk, an absorbed path).
std::vector<MeanEstimate> albedo(const Bxdf<S>& bsdf, const std::vector<double>& angles,
                                 int samples, std::uint64_t seed, std::uint64_t stream) {
    std::vector<MeanEstimate> out(angles.size());
    tbb::parallel_for(std::size_t(0), angles.size(), [&](std::size_t i) {
        if (render::renderInterruptFlag().load()) return;  // stopIfInterrupted() below
        Pcg32 rng(hashValues({seed, stream, i}));
        const V3 wo = outgoing(angles[i]);
        RunningMean m;
        for (int s = 0; s < samples; ++s) {
            if ((s & 4095) == 4095 && render::renderInterruptFlag().load()) return;
            const double uc = rng.nextDouble();
            const Vec2<double> u(rng.nextDouble(), rng.nextDouble());
            const auto r = bsdf.sample(wo, uc, u, TransportMode::Radiance);
            m.add(r ? luminance(r->weight) : 0.0);
        }
        out[i] = m.estimate();
    });
    stopIfInterrupted();
    return out;
}

LayeringValues valuesOnly(std::vector<MeanEstimate> v) {
    LayeringValues out;
    out.values = std::move(v);
    return out;
}

/// A twin's values against the walk's.
LayeringValues compared(std::vector<MeanEstimate> twin, const LayeringValues& walk) {
    LayeringValues out;
    out.values = std::move(twin);
    for (std::size_t i = 0; i < out.values.size(); ++i) {
        out.comparisons.push_back(compareWithWalk(out.values[i], walk.values[i]));
        out.counts.add(out.comparisons.back());
    }
    return out;
}

struct Geometry {
    std::vector<double> albedoAngles, lobeAngles, lobeThetaI, mapAngles;
    std::vector<std::vector<DirectionPair>> lobes;
    std::vector<DirectionPair> map;
};

Geometry geometry() {
    Geometry g;
    g.albedoAngles = degreesFrom(0, 85, kLayeringAlbedoStep);
    g.lobeAngles = kLayeringLobeAngles;
    g.lobeThetaI = degreesFrom(-88, 88, kLayeringLobeStep);
    g.mapAngles = degreesFrom(0, 85, kLayeringMapStep);
    for (double thetaO : g.lobeAngles) {
        std::vector<DirectionPair> lobe;
        for (double thetaI : g.lobeThetaI)
            lobe.push_back({outgoing(thetaO), incident(thetaI)});
        g.lobes.push_back(std::move(lobe));
    }
    for (double thetaO : g.mapAngles)
        for (double thetaI : g.mapAngles)
            g.map.push_back({outgoing(thetaO), incident(thetaI)});
    return g;
}

/// The test object rendered with `material` in place of the scene's "sample", in RGB and in
/// spectral mode, kept as NAME_MODE (kept_renders.h).
std::vector<LayeringRender> renderBoth(const render::SceneDesc& scene, std::size_t index,
                                       const MaterialDesc& material, const LayeringInputs& in,
                                       KeptRenders& kept, const std::string& name,
                                       const std::string& what, std::uint64_t seed) {
    render::SceneDesc s = scene;
    s.materials[index] = material;
    std::vector<LayeringRender> out;
    for (const render::RenderModeKind mode :
         {render::RenderModeKind::Rgb, render::RenderModeKind::Spectral}) {
        render::RenderOptions o;
        if (in.spp > 0) o.spp = in.spp;
        o.resolution = in.resolution;
        o.seed = seed;
        o.mode = mode;
        const std::string modeName(render::kRenderModeNames.name(mode));
        render::RenderResult r = kept.render(name + "_" + modeName, s, o, in.progress,
                                             what + " in " + modeName + " mode");
        render::RgbImage image = filmImage(*r.film);
        out.push_back({std::shared_ptr<const render::Film>(std::move(r.film)), std::move(image),
                       r.seconds, r.spp});
    }
    return out;
}

LayeringRenderComparison compareRenders(const render::RgbImage& twin,
                                        const render::RgbImage& walk) {
    LayeringRenderComparison c;
    const std::size_t n = std::size_t(walk.width) * std::size_t(walk.height);
    c.ciede2000.resize(n);
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Rgb<double> a(twin.pixels[3 * i], twin.pixels[3 * i + 1], twin.pixels[3 * i + 2]);
        const Rgb<double> b(walk.pixels[3 * i], walk.pixels[3 * i + 1], walk.pixels[3 * i + 2]);
        c.ciede2000[i] = float(ciede2000Rec709(a, b));
        sum += c.ciede2000[i];
    }
    if (n == 0) return c;
    c.meanDeltaE = sum / double(n);
    std::vector<float> sorted = c.ciede2000;
    const std::size_t k = std::min(n - 1, std::size_t(std::ceil(0.95 * double(n))) - 1);
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(k), sorted.end());
    c.p95DeltaE = sorted[k];
    return c;
}

std::size_t sceneMaterialIndex(const render::SceneDesc& scene) {
    for (std::size_t i = 0; i < scene.materialNames.size(); ++i)
        if (scene.materialNames[i] == kLayeringSceneMaterial) return i;
    throw InputError(scene.file.string() + ": materials: expected a material named \"" +
                     kLayeringSceneMaterial +
                     "\" (the test object's, which lamina layering replaces)");
}

}  // namespace

std::string cappedWalkNote(int maxDepth) {
    return "the walk is capped at max_depth " + std::to_string(maxDepth) +
           ": paths of more events are absorbed, so its f and albedo are biased low and it is "
           "not the truth the twins are measured against (remove max_depth for the unbiased "
           "walk, which ends by Russian roulette)";
}

namespace {

LayeringResult compareLayering(const LayeringInputs& in, KeptRenders& kept) {
    if (in.materials.empty()) throw InputError("lamina layering: expected at least one material");
    if (in.estimates < 2 || in.albedoSamples < 2)
        throw InputError(
            "lamina layering: estimates and albedo samples must be at least 2 "
            "(a standard error needs two)");
    std::vector<LayeringMaterial> materials;
    for (std::size_t i = 0; i < in.materials.size(); ++i)
        materials.push_back(readLayeringMaterial(in.materials[i], int(i) + 1));
    std::optional<render::SceneDesc> scene;
    std::size_t sceneIndex = 0;
    if (!in.scene.empty()) {
        scene = render::loadScene(in.scene);
        sceneIndex = sceneMaterialIndex(*scene);
    }

    LayeringResult result;
    result.inputs = in;
    const Geometry g = geometry();
    result.albedoAngles = g.albedoAngles;
    result.lobeAngles = g.lobeThetaI;
    result.mapAngles = g.mapAngles;
    const SpectrumContext<S> context;
    for (std::size_t mi = 0; mi < materials.size(); ++mi) {
        stopIfInterrupted();
        const LayeringMaterial& m = materials[mi];
        const std::uint64_t seed = hashValues({in.seed, mi});
        LayeringMaterialResult r;
        r.stem = m.stem;
        r.json = m.json;
        r.walksPerEstimate = m.coated().samples;
        r.walkMaxDepth = m.coated().maxDepth;
        if (r.walkMaxDepth > 0)
            tell(in.progress,
                 "layering: warning: " + m.stem + ": " + cappedWalkNote(r.walkMaxDepth) + "\n");
        const auto walkBsdf = buildBxdf(m.desc, context);
        const auto& walk = dynamic_cast<const CoatedBxdf<S>&>(*walkBsdf);
        tell(in.progress, "layering: " + m.stem + ": the walk...\n");
        r.walkAlbedo = valuesOnly(albedo(walk, g.albedoAngles, in.albedoSamples, seed, 1));
        for (const auto& lobe : g.lobes)
            r.walkLobes.push_back(valuesOnly(walkEval(walk, lobe, in.estimates, seed + 2)));
        stopIfInterrupted();
        r.walkMap = valuesOnly(walkEval(walk, g.map, in.estimates, seed + 3));
        const std::vector<LayeringTwin> twins = analyticTwins(m, r.twinNote);
        if (scene && !twins.empty()) {
            r.walkRenders = renderBoth(*scene, sceneIndex, m.desc, in, kept, m.stem + "_walk",
                                       m.stem + " (walk)", in.seed);
            const std::vector<LayeringRender> again = renderBoth(
                *scene, sceneIndex, m.desc, in, kept, m.stem + "_walk_seed2",
                m.stem + " (walk, the noise floor)", hashValues({in.seed, 0x666c6f6f72}));
            for (std::size_t k = 0; k < again.size(); ++k)
                r.walkNoise.push_back(compareRenders(again[k].image, r.walkRenders[k].image));
        }
        for (std::size_t ti = 0; ti < twins.size(); ++ti) {
            stopIfInterrupted();
            const LayeringTwin& twin = twins[ti];
            tell(in.progress, "layering: " + m.stem + ": " + twin.name + "...\n");
            LayeringTwinResult t;
            t.name = twin.name;
            t.json = twin.json;
            const auto bsdf = buildBxdf(twin.desc, context);
            t.albedo = compared(albedo(*bsdf, g.albedoAngles, in.albedoSamples, seed, 4 + ti),
                                r.walkAlbedo);
            for (std::size_t li = 0; li < g.lobes.size(); ++li)
                t.lobes.push_back(compared(exactEval(*bsdf, g.lobes[li]), r.walkLobes[li]));
            t.map = compared(exactEval(*bsdf, g.map), r.walkMap);
            if (scene) {
                t.renders = renderBoth(*scene, sceneIndex, twin.desc, in, kept,
                                       m.stem + "_" + twin.name.substr(0, twin.name.find(' ')),
                                       m.stem + " (" + twin.name + ")", in.seed);
                for (std::size_t k = 0; k < t.renders.size(); ++k)
                    t.renderErrors.push_back(
                        compareRenders(t.renders[k].image, r.walkRenders[k].image));
            }
            r.twins.push_back(std::move(t));
        }
        result.materials.push_back(std::move(r));
    }
    if (scene) result.renderSpp = in.spp > 0 ? in.spp : scene->settings.spp;
    return result;
}

}  // namespace

LayeringResult runLayering(const LayeringInputs& in) {
    KeptRenders kept(in.keepDirectory, in.resume);
    return keepingOnInterrupt(kept, [&] { return compareLayering(in, kept); });
}

}  // namespace lamina::experiments
