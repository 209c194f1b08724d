#include "lamina/output/render_metadata.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>

#include "lamina/render/camera.h"

namespace lamina::render {

namespace {

struct Fnv1a {
    std::uint64_t h = 1469598103934665603ULL;
    void add(const char* data, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
            h ^= std::uint8_t(data[i]);
            h *= 1099511628211ULL;
        }
    }
};

}  // namespace

std::string sceneHash(const SceneDesc& scene) {
    Fnv1a fnv;
    std::vector<std::filesystem::path> files = scene.inputFiles;
    if (files.empty()) files.push_back(scene.file);
    for (const auto& f : files) {
        // The name's length separates the files, so that moving bytes from one file to the
        // next changes the hash; the name itself does not count (a copied scene hashes alike).
        const std::string len = std::to_string(f.filename().string().size()) + ":";
        fnv.add(len.data(), len.size());
        std::ifstream in(f, std::ios::binary);
        char buf[1 << 16];
        while (in.read(buf, sizeof buf) || in.gcount() > 0)
            fnv.add(buf, std::size_t(in.gcount()));
    }
    char out[17];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(fnv.h));
    return out;
}

std::string processCommandLine() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (raw.empty()) return "unknown";
    if (raw.back() == '\0') raw.pop_back();
    std::replace(raw.begin(), raw.end(), '\0', ' ');
    return raw;
}

ImageMetadata renderMetadata(const SceneDesc& scene, const RenderOptions& options,
                             const RenderResult& r, const BuildInfo& build) {
    const RenderSettings& s = r.settings;
    ImageMetadata meta;
    meta.strings["version"] = build.version;
    meta.strings["git_commit"] = build.gitCommit;
    meta.strings["command_line"] = processCommandLine();
    meta.strings["mode"] = r.modeName;
    meta.strings["integrator"] = std::string(kIntegratorNames.name(s.integrator));
    meta.strings["scene"] = scene.file.string();
    meta.strings["scene_hash"] = sceneHash(scene);
    meta.ints["input_files"] = int(std::max<std::size_t>(scene.inputFiles.size(), 1));
    meta.strings["sampler"] = std::string(kSamplerNames.name(s.sampler));
    meta.strings["mis_heuristic"] = std::string(kMisHeuristicNames.name(s.mis));
    meta.strings["light_selection"] = std::string(kLightSelectionNames.name(s.lightSelection));
    meta.strings["filter"] = std::string(kFilterNames.name(scene.film.filter));
    meta.floats["filter_radius"] = float(scene.film.filterRadius);
    if (scene.film.filter == FilterKind::Gaussian)
        meta.floats["filter_sigma"] =
            float(scene.film.filterSigma.value_or(scene.film.filterRadius / 3));
    meta.ints["spp"] = r.spp;
    meta.ints["seed"] = int(s.seed);
    meta.ints["max_depth"] = s.maxDepth;
    meta.ints["rr_depth"] = s.russianRouletteDepth;
    if (s.integrator == IntegratorKind::Path) meta.ints["next_event"] = s.nextEvent ? 1 : 0;
    // Only when set: an estimator worse on purpose (transport_ablations.h).
    if (options.ablations.noMediaSpectralMis)
        meta.strings["ablations"] =
            std::string(kRenderAblationNames.name(RenderAblation::MediaSpectralMis));
    meta.ints["partial"] = r.partial ? 1 : 0;
    meta.ints["rejected_samples"] =
        int(std::min<std::uint64_t>(r.film->rejectedSamples(), 1u << 30));
    meta.floats["seconds"] = float(r.seconds);
    // 0: no time budget (a fixed sample count).
    meta.floats["time_budget"] = float(options.seconds.value_or(0.0));
    // The sensor, where it is not the identity (film_response.h).
    const FilmDesc& film = scene.film;
    if (film.imagingRatio() != 1) meta.floats["imaging_ratio"] = float(film.imagingRatio());
    if (film.whiteBalance > 0) meta.floats["white_balance"] = float(film.whiteBalance);
    if (film.maxComponentValue) {
        meta.floats["max_component_value"] = float(*film.maxComponentValue);
        meta.strings["clamp"] = "on: every sample's largest CIE XYZ component clamped (biased)";
    }
    // The spectral film's bins (spectral_film.h): N equal bins over [min, max] nm.
    if (const SpectralFilm* spectral = r.film->spectralFilm()) {
        meta.ints["spectral_film"] = spectral->bins().count;
        meta.floats["spectral_film_min_nm"] = float(kLambdaMin);
        meta.floats["spectral_film_max_nm"] = float(kLambdaMax);
    }
    // The camera of the whole image, also for a crop.
    const Camera camera(scene.camera, r.film->fullWidth(), r.film->fullHeight());
    meta.matrices["camera_to_world"] = camera.cameraToWorld();
    meta.matrices["world_to_ndc"] = camera.worldToNdc();
    return meta;
}

}  // namespace lamina::render
