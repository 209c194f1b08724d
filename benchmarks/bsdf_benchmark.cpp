// Throughput of eval, pdf and sample per material, in float (the renderer's precision), in
// RGB mode and in spectral mode (4 wavelengths; the material built once, as for a constant
// material in RGB mode). Results are recorded in docs/bsdf.md ("Performance").
#include <benchmark/benchmark.h>

#include "lamina/bsdf/material_builder.h"
#include "lamina/core/pcg32.h"

namespace lamina {
namespace {

struct Named {
    const char* name;
    const char* json;
};

constexpr Named kMaterials[] = {
    {"lambert", R"({"type":"lambert","reflectance":0.5})"},
    {"oren_nayar", R"({"type":"oren_nayar","reflectance":0.5,"roughness":0.5})"},
    {"burley", R"({"type":"burley","reflectance":0.5,"roughness":0.5})"},
    {"phong", R"({"type":"phong","reflectance":0.5,"roughness":0.4})"},
    {"conductor_ggx_f82", R"({"type":"conductor","f0":[0.9,0.6,0.3],"roughness":0.4})"},
    {"conductor_beckmann",
     R"({"type":"conductor","distribution":"beckmann","f0":0.9,"roughness":0.4})"},
    {"conductor_ggx_exact",
     R"({"type":"conductor","eta":0.2,"k":3.5,"fresnel":"exact","roughness":0.4})"},
    {"conductor_ggx_multiscatter",
     R"({"type":"conductor","f0":0.9,"roughness":0.4,"multiscatter":true})"},
    {"conductor_au_spectral_exact", R"({"type":"conductor","material":"Au","roughness":0.4})"},
    {"dielectric_rough", R"({"type":"dielectric","ior":1.5,"roughness":0.3})"},
    {"standard_article", R"({"type":"standard","base_color":[0.8,0.4,0.2],"roughness":0.5})"},
    {"standard_albedo_multiscatter",
     R"({"type":"standard","base_color":[0.8,0.4,0.2],"roughness":0.5,"coupling":"albedo","multiscatter":true})"},
    {"standard_glass", R"({"type":"standard","transmission":1,"roughness":0.3})"},
    // The random-walk coat against its analytic twins (same interface and base).
    {"layered_albedo_twin",
     R"({"type":"layered","interface":{"roughness":0.3,"ior":1.5,"fresnel":"exact"},"base":{"type":"lambert","reflectance":[0.8,0.4,0.2]},"coupling":"albedo"})"},
    {"coated_rough_lambert",
     R"({"type":"coated","roughness":0.3,"base":{"type":"lambert","reflectance":[0.8,0.4,0.2]}})"},
    {"coated_rough_lambert_4_samples",
     R"({"type":"coated","roughness":0.3,"samples":4,"base":{"type":"lambert","reflectance":[0.8,0.4,0.2]}})"},
    {"coated_medium_gold",
     R"({"type":"coated","roughness":0.1,"thickness":0.5,"albedo":[0.9,0.7,0.4],"g":0.3,"base":{"type":"conductor","material":"Au","roughness":0.3}})"},
};

enum class Op { Eval, Pdf, Sample };

template <typename S>
void run(benchmark::State& state, const Bxdf<S>& bxdf, Op op) {
    Pcg32 rng(1);
    const Vec3f wo = glm::normalize(Vec3f(0.3f, 0.2f, 0.9f));
    for (auto _ : state) {
        const Vec3f wi =
            glm::normalize(Vec3f(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f, 0.7f));
        switch (op) {
            case Op::Eval:
                benchmark::DoNotOptimize(bxdf.eval(wo, wi, TransportMode::Radiance));
                break;
            case Op::Pdf:
                benchmark::DoNotOptimize(bxdf.pdf(wo, wi));
                break;
            case Op::Sample:
                benchmark::DoNotOptimize(bxdf.sample(wo, rng.nextFloat(),
                                                     Vec2f(rng.nextFloat(), wi.x + 0.5f),
                                                     TransportMode::Radiance));
                break;
        }
    }
}

void registerAll() {
    for (const Named& m : kMaterials) {
        const auto desc = std::make_shared<const MaterialDesc>(parseMaterialArgument(m.json));
        for (Op op : {Op::Eval, Op::Pdf, Op::Sample}) {
            const char* opName = op == Op::Eval ? "eval" : op == Op::Pdf ? "pdf" : "sample";
            benchmark::RegisterBenchmark((std::string("rgb/") + m.name + "/" + opName).c_str(),
                                         [desc, op](benchmark::State& s) {
                                             const auto b =
                                                 buildBxdf(*desc, SpectrumContext<Rgb<float>>{});
                                             run(s, *b, op);
                                         });
            benchmark::RegisterBenchmark(
                (std::string("spectral/") + m.name + "/" + opName).c_str(),
                [desc, op](benchmark::State& s) {
                    auto lambda = SampledWavelengths<float>::fixed({450, 520, 590, 660});
                    const auto b =
                        buildBxdf(*desc, SpectrumContext<SampledSpectrum<float>>{lambda});
                    run(s, *b, op);
                });
        }
    }
    // Building a material per hit, as spectral mode does.
    for (const Named& m : kMaterials) {
        const auto desc = std::make_shared<const MaterialDesc>(parseMaterialArgument(m.json));
        benchmark::RegisterBenchmark(
            (std::string("spectral/") + m.name + "/build").c_str(), [desc](benchmark::State& s) {
                auto lambda = SampledWavelengths<float>::fixed({450, 520, 590, 660});
                for (auto _ : s)
                    benchmark::DoNotOptimize(
                        buildBxdf(*desc, SpectrumContext<SampledSpectrum<float>>{lambda}));
            });
    }
}

}  // namespace
}  // namespace lamina

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    lamina::registerAll();
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
