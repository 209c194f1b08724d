#include "lamina/experiments/reciprocity.h"

#include <chrono>

#include "lamina/bsdf/material_builder.h"
#include "lamina/core/error.h"
#include "lamina/core/hash.h"
#include "lamina/experiments/text_format.h"
#include "lamina/output/image_output.h"

namespace lamina::experiments {

namespace {

void apply(Ablation a, render::TransportAblations& ablations) {
    switch (a) {
        case Ablation::AdjointCorrection:
            ablations.noAdjointCorrection = true;
            break;
        case Ablation::TransportMode:
            ablations.radianceOnLightPaths = true;
            break;
        case Ablation::SwappedDirections:
            ablations.swappedConnections = true;
            break;
    }
}

/// A reference image as a single batch (no variance).
BatchImages referenceImages(const std::string& path, int width, int height) {
    const render::RgbImage img = render::readLinearRgbImage(path);
    if (img.width != width || img.height != height)
        throw InputError(path + " is " + std::to_string(img.width) + "x" +
                         std::to_string(img.height) + " but the renders are " +
                         std::to_string(width) + "x" + std::to_string(height));
    render::Film film(width, height, render::FilmSpace::Rec709);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            film.addSample(x, y, Rgb<double>(img.at(x, y, 0), img.at(x, y, 1), img.at(x, y, 2)),
                           1.0);
    BatchImages images(width, height);
    images.add(film);
    return images;
}

PairAgreement comparePair(const std::string& nameA, const BatchImages& a, const std::string& nameB,
                          const BatchImages& b, const AgreementTest& test, int spp) {
    PairAgreement p{nameA, nameB, testAgreement(a, b, test)};
    p.agree = p.result.agree(test.alpha);
    p.pixelTest = calibratePixelTest(a, b, test, spp);
    p.width = a.width();
    p.height = a.height();
    return p;
}

template <SpectrumType S>
void checkMaterials(const render::SceneDesc& scene, const SpectrumContext<S>& context,
                    render::RenderModeKind mode, std::vector<MaterialReciprocity>& out) {
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const auto bsdf = buildBxdf(scene.materials[m], context);
        out.push_back({scene.materialNames[m], mode,
                       checkBsdfReciprocity(*bsdf, kBsdfReciprocityPairs, 1 + m)});
    }
}

}  // namespace

ReciprocityResult runReciprocity(const ReciprocityInputs& in) {
    const render::SceneDesc scene = render::loadScene(in.scene);
    for (const render::IntegratorKind i : in.integrators)
        render::checkMedia(scene, in.mode, i);
    ReciprocityResult result{in, {}, {}, {}, {}};
    render::RenderOptions o = in.overrides;
    o.mode = in.mode;
    for (const Ablation a : in.ablations)
        apply(a, o.ablations);

    KeptRenders kept(in.keepDirectory, in.resume);
    for (std::size_t i = 0; i < in.integrators.size(); ++i) {
        const std::string name(render::kIntegratorNames.name(in.integrators[i]));
        o.integrator = in.integrators[i];
        o.seed = hashValues({in.seed, i, 0x7265636970ull}) & 0x7fffffffull;
        const auto start = std::chrono::steady_clock::now();
        BatchImages images = keepingOnInterrupt(kept, [&] {
            return renderBatches(scene, o, in.spp, in.batches, kept, name, [&](int k) {
                tell(in.progress, formatText("\r%s: batch %d/%d", name.c_str(), k + 1, in.batches));
            });
        });
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        tell(in.progress,
             formatText("\r%s: %d batches (%.1f s)\n", name.c_str(), in.batches, seconds));
        result.renders.push_back({in.integrators[i], std::move(images), seconds});
    }

    const auto nameOf = [](const IntegratorBatches& r) {
        return std::string(render::kIntegratorNames.name(r.integrator));
    };
    for (std::size_t i = 0; i < result.renders.size(); ++i)
        for (std::size_t j = i + 1; j < result.renders.size(); ++j)
            result.pairs.push_back(comparePair(nameOf(result.renders[i]), result.renders[i].images,
                                               nameOf(result.renders[j]), result.renders[j].images,
                                               in.test, in.spp));
    if (!in.reference.empty()) {
        const BatchImages ref = referenceImages(in.reference, result.renders.front().images.width(),
                                                result.renders.front().images.height());
        for (const IntegratorBatches& r : result.renders)
            result.pairs.push_back(
                comparePair(nameOf(r), r.images, "reference", ref, in.test, in.spp));
    }
    for (const PairAgreement& p : result.pairs)
        result.allAgree &= p.agree;
    for (const PairAgreement& p : result.pairs)
        if (p.pixelTest.checked &&
            (!result.pixelTest.checked ||
             p.pixelTest.nullRejectionRate > result.pixelTest.nullRejectionRate))
            result.pixelTest = p.pixelTest;

    checkMaterials(scene, SpectrumContext<Rgb<double>>{}, render::RenderModeKind::Rgb,
                   result.materials);
    SampledWavelengths<double> lambda =
        SampledWavelengths<double>::fixed({450.0, 520.0, 590.0, 660.0});
    checkMaterials(scene, SpectrumContext<SampledSpectrum<double>>{lambda},
                   render::RenderModeKind::Spectral, result.materials);
    return result;
}

}  // namespace lamina::experiments
