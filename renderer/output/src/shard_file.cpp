#include "lamina/output/shard_file.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "lamina/core/error.h"
#include "lamina/core/input_file.h"
#include "lamina/image/image_files.h"
#include "lamina/output/render_metadata.h"
#include "lamina/output/spectral_layout.h"
#include "lamina/render/render_limits.h"
#include "shard_layers.h"

namespace lamina::render {

namespace {

/// Every double of PixelSums, by channel name.
struct SumChannel {
    const char* name;
    std::function<double&(PixelSums&)> field;
};

const std::vector<SumChannel>& sumChannels() {
    static const std::vector<SumChannel> channels = {
        {"Sum.R", [](PixelSums& p) -> double& { return p.sum[0]; }},
        {"Sum.G", [](PixelSums& p) -> double& { return p.sum[1]; }},
        {"Sum.B", [](PixelSums& p) -> double& { return p.sum[2]; }},
        {"Weight.Sum", [](PixelSums& p) -> double& { return p.weightSum; }},
        {"Y.Sum", [](PixelSums& p) -> double& { return p.ySum; }},
        {"Y.SqSum", [](PixelSums& p) -> double& { return p.ySqSum; }},
        {"Y.Max", [](PixelSums& p) -> double& { return p.yMax; }},
        {"AlbedoSum.R", [](PixelSums& p) -> double& { return p.aovSum.albedo[0]; }},
        {"AlbedoSum.G", [](PixelSums& p) -> double& { return p.aovSum.albedo[1]; }},
        {"AlbedoSum.B", [](PixelSums& p) -> double& { return p.aovSum.albedo[2]; }},
        {"NSum.X", [](PixelSums& p) -> double& { return p.aovSum.normal.x; }},
        {"NSum.Y", [](PixelSums& p) -> double& { return p.aovSum.normal.y; }},
        {"NSum.Z", [](PixelSums& p) -> double& { return p.aovSum.normal.z; }},
        {"ZSum.Z", [](PixelSums& p) -> double& { return p.aovSum.depth; }},
        {"Splat.R", [](PixelSums& p) -> double& { return p.splatSum[0]; }},
        {"Splat.G", [](PixelSums& p) -> double& { return p.splatSum[1]; }},
        {"Splat.B", [](PixelSums& p) -> double& { return p.splatSum[2]; }},
        {"Splat.YSum", [](PixelSums& p) -> double& { return p.splatYSum; }},
        {"Splat.YSqSum", [](PixelSums& p) -> double& { return p.splatYSqSum; }},
        {"SqSum.R", [](PixelSums& p) -> double& { return p.sqSum[0]; }},
        {"SqSum.G", [](PixelSums& p) -> double& { return p.sqSum[1]; }},
        {"SqSum.B", [](PixelSums& p) -> double& { return p.sqSum[2]; }},
        {"SplatSqSum.R", [](PixelSums& p) -> double& { return p.splatSqSum[0]; }},
        {"SplatSqSum.G", [](PixelSums& p) -> double& { return p.splatSqSum[1]; }},
        {"SplatSqSum.B", [](PixelSums& p) -> double& { return p.splatSqSum[2]; }},
    };
    return channels;
}

// The two counts, stored the same way (exact below 2^48).
constexpr const char* kCountChannel = "Count.N";
constexpr const char* kSplatCountChannel = "Splat.Count";
constexpr const char* kLowPrefix = "Low.";

std::string boundsText(const PixelBounds& b) {
    return std::to_string(b.x0) + "," + std::to_string(b.x1) + "," + std::to_string(b.y0) + "," +
           std::to_string(b.y1);
}

}  // namespace

namespace {

std::string settingsLine(const SceneDesc& scene, const RenderOptions& options,
                         const RenderSettings& s, std::string_view modeName, int fullWidth,
                         int fullHeight) {
    std::ostringstream out;
    out << "mode=" << modeName << " integrator=" << kIntegratorNames.name(s.integrator)
        << " sampler=" << kSamplerNames.name(s.sampler) << " seed=" << s.seed
        << " max_depth=" << s.maxDepth << " rr_depth=" << s.russianRouletteDepth
        << " mis=" << kMisHeuristicNames.name(s.mis)
        << " light_selection=" << kLightSelectionNames.name(s.lightSelection)
        << " filter=" << kFilterNames.name(scene.film.filter)
        << " filter_radius=" << scene.film.filterRadius << " resolution=" << fullWidth << "x"
        << fullHeight << " aovs=" << (options.aovs ? 1 : 0)
        << " ablations=" << options.ablations.noAdjointCorrection
        << options.ablations.radianceOnLightPaths << options.ablations.swappedConnections;
    // Only when given, so that the settings of shards rendered before the key existed match.
    if (options.ablations.noMediaSpectralMis) out << " media_spectral_mis=0";
    if (scene.film.filterSigma) out << " filter_sigma=" << *scene.film.filterSigma;
    if (scene.film.imagingRatio() != 1) out << " imaging_ratio=" << scene.film.imagingRatio();
    if (scene.film.whiteBalance > 0) out << " white_balance=" << scene.film.whiteBalance;
    if (scene.film.maxComponentValue)
        out << " max_component_value=" << *scene.film.maxComponentValue;
    if (options.spectralBins > 0) out << " spectral_film=" << options.spectralBins;
    return out.str();
}

}  // namespace

std::string shardSettings(const SceneDesc& scene, const RenderOptions& options,
                          const RenderResult& r) {
    return settingsLine(scene, options, r.settings, r.modeName, r.film->fullWidth(),
                        r.film->fullHeight());
}

std::string shardSettings(const SceneDesc& scene, const RenderOptions& options) {
    const auto [width, height] =
        options.resolution.value_or(std::pair{scene.film.width, scene.film.height});
    return settingsLine(scene, options, resolveRenderSettings(scene, options),
                        kRenderModeNames.name(options.mode), width, height);
}

void addShardMetadata(ImageMetadata& meta, const SceneDesc& scene, const RenderOptions& options,
                      const RenderResult& r) {
    meta.ints["shard"] = 1;
    meta.strings["shard_settings"] = shardSettings(scene, options, r);
    meta.ints["sample_first"] = r.firstSample;
    meta.ints["sample_count"] = options.samples ? options.samples->count : r.settings.spp;
    meta.ints["samples_done"] = r.spp;
    meta.strings["crop"] = boundsText(r.film->window());
    meta.ints["full_width"] = r.film->fullWidth();
    meta.ints["full_height"] = r.film->fullHeight();
    meta.strings["film_space"] = r.film->space() == FilmSpace::Xyz ? "xyz" : "rec709";
}

void writeShardExr(const std::filesystem::path& path, const Film& film,
                   const ImageMetadata& metadata) {
    std::vector<std::string> names = {"R", "G", "B"};
    const auto& sums = sumChannels();
    for (const auto& c : sums)
        names.push_back(c.name);
    names.push_back(kCountChannel);
    names.push_back(kSplatCountChannel);
    for (const std::string& name : layerSumNames(film))
        names.push_back(name);
    const std::size_t doubles = names.size() - 3;
    for (std::size_t i = 3; i < 3 + doubles; ++i)
        names.push_back(kLowPrefix + names[i]);
    const std::size_t nc = names.size();
    const int w = film.width(), h = film.height();
    std::vector<float> data(std::size_t(w) * h * nc);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* out = &data[(std::size_t(y) * w + x) * nc];
            const Rgb<double> v = film.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                out[c] = float(v[c]);
            PixelSums p = film.sums(x, y);
            std::vector<double> values;
            for (const auto& c : sums)
                values.push_back(c.field(p));
            values.push_back(double(p.count));
            values.push_back(double(p.splatCount));
            appendLayerSums(film, x, y, values);
            for (std::size_t i = 0; i < doubles; ++i) {
                const float high = float(values[i]);
                if (!std::isfinite(high))
                    throw InputError(path.string() + ": pixel (" + std::to_string(x) + ", " +
                                     std::to_string(y) + ") " + names[3 + i] +
                                     " is beyond the float range");
                out[3 + i] = high;
                out[3 + doubles + i] = float(values[i] - double(high));
            }
        }
    writeFloatExr(path, film.window(), film.fullWidth(), film.fullHeight(), names, data, metadata);
}

namespace {

PixelBounds parseBounds(const std::string& text, const std::string& file) {
    PixelBounds b;
    char c1 = 0, c2 = 0, c3 = 0;
    std::istringstream in(text);
    if (!(in >> b.x0 >> c1 >> b.x1 >> c2 >> b.y0 >> c3 >> b.y1) || c1 != ',' || c2 != ',' ||
        c3 != ',')
        throw InputError(file + ": lamina:crop: expected X0,X1,Y0,Y1, found \"" + text + "\"");
    return b;
}

}  // namespace

ShardFile readShardExr(const std::filesystem::path& path) {
    const std::string file = path.string();
    checkInputFile(path, kMaxImageFileBytes);
    Failure failure;
    const auto in = openImageFile(path, failure);
    if (!in) throw InputError(file + ": cannot read image: " + failure.message);
    const ImageHeader& spec = in->header();
    const int nchannels = int(spec.channels.size());
    ShardFile shard;
    shard.path = path;
    shard.metadata = spec.laminaMetadata;
    const ImageMetadata& m = shard.metadata;
    if (!m.ints.contains("shard") || m.ints.at("shard") != 1)
        throw InputError(file + ": lamina:shard: not a shard (render it with --samples or --crop)");
    const auto needString = [&](const char* key) {
        if (!m.strings.contains(key)) throw InputError(file + ": lamina:" + key + ": missing");
        return m.strings.at(key);
    };
    const auto needInt = [&](const char* key) {
        if (!m.ints.contains(key)) throw InputError(file + ": lamina:" + key + ": missing");
        return m.ints.at(key);
    };
    shard.sceneHash = needString("scene_hash");
    shard.settings = needString("shard_settings");
    shard.fullWidth = needInt("full_width");
    shard.fullHeight = needInt("full_height");
    shard.crop = parseBounds(needString("crop"), file);
    shard.requested = {needInt("sample_first"), needInt("sample_count")};
    shard.samplesDone = needInt("samples_done");
    shard.partial = m.ints.contains("partial") && m.ints.at("partial") != 0;
    if (m.floats.contains("seconds")) shard.seconds = m.floats.at("seconds");
    const std::string space = needString("film_space");
    if (space != "xyz" && space != "rec709")
        throw InputError(file + ": lamina:film_space: expected xyz or rec709, found " + space);
    const PixelBounds& c = shard.crop;
    if (c.x0 < 0 || c.y0 < 0 || c.x1 > shard.fullWidth || c.y1 > shard.fullHeight || c.x0 >= c.x1 ||
        c.y0 >= c.y1 || spec.width != c.width() || spec.height != c.height() || spec.x != c.x0 ||
        spec.y != c.y0)
        throw InputError(file + ": lamina:crop " + boundsText(c) +
                         " does not match the image's data window");
    if (shard.requested.first < 0 || shard.samplesDone < 0 ||
        shard.samplesDone > shard.requested.count)
        throw InputError(file + ": lamina:samples_done: expected 0 to lamina:sample_count");

    // The window matches the crop, inside the full image, whose size the header gave: refuse
    // one larger than any image before allocating for it.
    if (std::uintmax_t(spec.width) * std::uintmax_t(spec.height) > kMaxImagePixels)
        throw InputError(file + ": " + std::to_string(spec.width) + " x " +
                         std::to_string(spec.height) + " pixels, more than the limit of " +
                         std::to_string(kMaxImagePixels));
    std::vector<float> all(std::size_t(spec.width) * spec.height * std::size_t(nchannels));
    if (!in->read(nchannels, all.data(), failure))
        throw InputError(file + ": cannot read image: " + failure.message);
    const auto channel = [&](const std::string& name) {
        for (int i = 0; i < nchannels; ++i)
            if (spec.channels[std::size_t(i)] == name) return i;
        throw InputError(file + ": channel " + name + ": missing (not a complete shard)");
    };
    const auto& sums = sumChannels();
    std::vector<int> high, low;
    for (const auto& s : sums) {
        high.push_back(channel(s.name));
        low.push_back(channel(kLowPrefix + std::string(s.name)));
    }
    const int count[2] = {channel(kCountChannel), channel(kSplatCountChannel)};
    const int countLow[2] = {channel(kLowPrefix + std::string(kCountChannel)),
                             channel(kLowPrefix + std::string(kSplatCountChannel))};
    shard.film = std::make_unique<Film>(shard.fullWidth, shard.fullHeight, c,
                                        space == "xyz" ? FilmSpace::Xyz : FilmSpace::Rec709);
    // The layers' sums where the shard has them: the Stokes sums of a polarised render, the
    // spectral film's (lamina:spectral_film bins, a splat layer if the render splatted).
    const auto has = [&](const std::string& name) {
        return std::find(spec.channels.begin(), spec.channels.end(), name) != spec.channels.end();
    };
    const bool stokes = has("S1.Sum.R");
    if (stokes) shard.film->enableStokes();
    if (m.ints.contains("spectral_film")) {
        const SpectralBins bins{m.ints.at("spectral_film")};
        if (bins.count < 1 || bins.count > kMaxSpectralFilmBins)
            throw InputError(file + ": lamina:spectral_film: expected 1 to " +
                             std::to_string(kMaxSpectralFilmBins) + " bins");
        const int components = stokes ? 4 : 1;
        shard.film->enableSpectralFilm(
            bins, components, has("S0.Splat." + spectralChannelName(0, bins.centre(0)).substr(3)));
    }
    const std::vector<std::string> layerNames = layerSumNames(*shard.film);
    std::vector<int> layerHigh, layerLow;
    for (const std::string& name : layerNames) {
        layerHigh.push_back(channel(name));
        layerLow.push_back(channel(kLowPrefix + name));
    }
    std::vector<double> layerValues(layerNames.size());
    const std::size_t nc = std::size_t(nchannels);
    for (int y = 0; y < spec.height; ++y)
        for (int x = 0; x < spec.width; ++x) {
            const float* v = &all[(std::size_t(y) * spec.width + x) * nc];
            PixelSums p;
            for (std::size_t i = 0; i < sums.size(); ++i)
                sums[i].field(p) = double(v[high[i]]) + double(v[low[i]]);
            double n[2];
            for (int k = 0; k < 2; ++k) {
                n[k] = double(v[count[k]]) + double(v[countLow[k]]);
                if (!(n[k] >= 0) || n[k] != std::floor(n[k]))
                    throw InputError(file + ": pixel (" + std::to_string(c.x0 + x) + ", " +
                                     std::to_string(c.y0 + y) + "): a sample count of " +
                                     std::to_string(n[k]));
            }
            p.count = std::uint64_t(n[0]);
            p.splatCount = std::uint64_t(n[1]);
            for (std::size_t i = 0; i < sums.size(); ++i)
                if (!std::isfinite(sums[i].field(p)))
                    throw InputError(file + ": pixel (" + std::to_string(c.x0 + x) + ", " +
                                     std::to_string(c.y0 + y) + "): " + sums[i].name +
                                     " is not finite");
            shard.film->addSums(c.x0 + x, c.y0 + y, p);
            if (layerNames.empty()) continue;
            for (std::size_t i = 0; i < layerNames.size(); ++i) {
                layerValues[i] = double(v[layerHigh[i]]) + double(v[layerLow[i]]);
                if (!std::isfinite(layerValues[i]))
                    throw InputError(file + ": pixel (" + std::to_string(c.x0 + x) + ", " +
                                     std::to_string(c.y0 + y) + "): " + layerNames[i] +
                                     " is not finite");
            }
            addLayerSums(*shard.film, c.x0 + x, c.y0 + y, layerValues.data());
        }
    if (const auto rejected = shard.metadata.ints.find("rejected_samples");
        rejected != shard.metadata.ints.end() && rejected->second > 0)
        shard.film->addRejectedSamples(std::uint64_t(rejected->second));
    return shard;
}

void addShardSums(Film& film, const ShardFile& earlier) {
    const PixelBounds& w = film.window();
    const PixelBounds& c = earlier.film->window();
    if (w.x0 != c.x0 || w.x1 != c.x1 || w.y0 != c.y0 || w.y1 != c.y1 ||
        film.fullWidth() != earlier.fullWidth || film.fullHeight() != earlier.fullHeight)
        throw InputError(earlier.path.string() + ": lamina:crop " + boundsText(c) +
                         ": another window than the render's " + boundsText(w));
    addFilmSums(film, *earlier.film);
}

void addFilmSums(Film& film, const Film& other) {
    if (layerSumNames(film) != layerSumNames(other))
        throw std::logic_error("addFilmSums: films of different layers");
    const PixelBounds& w = other.window();
    std::vector<double> layers;
    for (int y = 0; y < other.height(); ++y)
        for (int x = 0; x < other.width(); ++x) {
            film.addSums(w.x0 + x, w.y0 + y, other.sums(x, y));
            layers.clear();
            appendLayerSums(other, x, y, layers);
            if (!layers.empty()) addLayerSums(film, w.x0 + x, w.y0 + y, layers.data());
        }
}

}  // namespace lamina::render
