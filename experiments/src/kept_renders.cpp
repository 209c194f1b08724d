#include "lamina/experiments/kept_renders.h"

#include <sstream>
#include <stdexcept>

#include "lamina/core/error.h"
#include "lamina/experiments/image_metrics.h"
#include "lamina/output/render_metadata.h"
#include "lamina/output/shard_file.h"

namespace lamina::experiments {

namespace {

/// The first "key=value" of `wanted` that `found` lacks, as "key=value" of each; both empty
/// if none differs.
std::pair<std::string, std::string> firstDifference(const std::string& found,
                                                    const std::string& wanted) {
    std::istringstream f(found), w(wanted);
    std::vector<std::string> foundWords;
    for (std::string word; f >> word;)
        foundWords.push_back(word);
    for (std::string word; w >> word;) {
        const std::string key = word.substr(0, word.find('=') + 1);
        std::string other = "(none)";
        bool same = false;
        for (const std::string& candidate : foundWords)
            if (candidate.rfind(key, 0) == 0) {
                other = candidate;
                same = candidate == word;
            }
        if (!same) return {other, word};
    }
    if (found != wanted) return {found, wanted};
    return {};
}

/// The kept render in `path`, checked against the render `scene` and `options` ask for.
render::RenderResult takeBack(const std::filesystem::path& path, const render::SceneDesc& scene,
                              const render::RenderOptions& options) {
    render::ShardFile shard = render::readShardExr(path);
    const std::string remedy =
        ": resume with the same options, or remove the directory's renders/ to render them again";
    const auto refuse = [&](const std::string& found, const std::string& wanted) {
        return InputError(path.string() + ": rendered with " + found + ", this run asks for " +
                          wanted + remedy);
    };
    const std::string hash = render::sceneHash(scene);
    if (shard.sceneHash != hash)
        throw refuse("scene files of hash " + shard.sceneHash, "scene files of hash " + hash);
    const auto [found, wanted] =
        firstDifference(shard.settings, render::shardSettings(scene, options));
    if (!wanted.empty()) throw refuse(found, wanted);
    const render::RenderSettings settings = render::resolveRenderSettings(scene, options);
    if (shard.requested.first != 0 || shard.requested.count != settings.spp)
        throw refuse("spp=" + std::to_string(shard.requested.count),
                     "spp=" + std::to_string(settings.spp));
    if (shard.partial || shard.samplesDone != settings.spp)
        throw InputError(path.string() + ": holds " + std::to_string(shard.samplesDone) +
                         " of its " + std::to_string(settings.spp) + " samples per pixel" + remedy);
    render::RenderResult r;
    r.film = std::move(shard.film);
    r.spp = shard.samplesDone;
    r.seconds = shard.seconds;
    r.modeName = render::kRenderModeNames.name(options.mode);
    r.settings = settings;
    return r;
}

}  // namespace

std::filesystem::path keptRenderFile(const std::string& name) {
    return std::filesystem::path("renders") / (name + ".exr");
}

KeptRenders::KeptRenders(std::filesystem::path directory, bool resume)
    : directory_(std::move(directory)), resume_(resume) {}

render::RenderResult KeptRenders::render(const std::string& name, const render::SceneDesc& scene,
                                         const render::RenderOptions& options,
                                         const ProgressSink& progress, const std::string& what) {
    if (options.seconds || options.samples || options.crop)
        throw std::logic_error("KeptRenders::render: a whole render of a fixed sample count");
    const std::filesystem::path path = directory_ / keptRenderFile(name);
    render::RenderResult r;
    if (!directory_.empty() && resume_ && std::filesystem::exists(path)) {
        r = takeBack(path, scene, options);
        if (!what.empty())
            tell(progress, what + ": kept from " + keptRenderFile(name).string() + "\n");
    } else {
        if (!what.empty()) tell(progress, "rendering " + what + "...\n");
        r = renderWhole(scene, options);
        if (!directory_.empty()) {
            render::ImageMetadata meta = render::renderMetadata(scene, options, r, {});
            // A working file of the experiment: its report's files carry the build.
            meta.strings.erase("version");
            meta.strings.erase("git_commit");
            render::addShardMetadata(meta, scene, options, r);
            std::filesystem::create_directories(path.parent_path());
            render::writeShardExr(path, *r.film, meta);
            written_.push_back(path);
            // The film as kept: what a resumed run reads back, to the last bit.
            r.film = render::readShardExr(path).film;
        }
    }
    finished_.push_back({name, r.modeName,
                         std::string(render::kIntegratorNames.name(r.settings.integrator)),
                         r.settings.seed, r.spp, filmImage(*r.film)});
    return r;
}

void KeptRenders::describe(Interrupted& stopped) const {
    for (const std::filesystem::path& file : written_)
        stopped.kept += (stopped.kept.empty() ? "" : ", ") + file.string();
    if (!written_.empty())
        stopped.kept +=
            " (the same command with --resume continues from them without rendering them again)";
    Data renders = Data::list();
    for (const Finished& f : finished_) {
        Data d = Data::dict();
        d.set("name", f.name);
        d.set("mode", f.mode);
        d.set("integrator", f.integrator);
        d.set("seed", static_cast<long long>(f.seed));
        d.set("spp", f.spp);
        d.set("rgb", Data::array(std::vector<double>(f.image.pixels.begin(), f.image.pixels.end()),
                                 {std::size_t(f.image.height), std::size_t(f.image.width), 3}));
        renders.append(std::move(d));
    }
    Data partial = Data::dict();
    partial.set("renders", std::move(renders));
    stopped.partial = std::move(partial);
}

void removeKeptRenders(const std::filesystem::path& directory) {
    std::error_code ignored;
    std::filesystem::remove_all(directory / "renders", ignored);
}

}  // namespace lamina::experiments
