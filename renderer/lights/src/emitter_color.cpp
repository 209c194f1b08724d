#include "lamina/lights/emitter_color.h"

#include <map>
#include <mutex>
#include <tuple>

#include "lamina/spectral/rgb_to_spectrum.h"

namespace lamina::render {
namespace {

/// The resampled spectrum of an emitter colour, shared by every emitter of that colour while
/// any of them lives: a scene's mesh light of 100,000 triangles holds one table, not 100,000
/// (1.9 KB each). Keyed by the given spectrum (kept alive by the emitters that hold its table,
/// so its address is not reused while the entry can be found) or by the RGB value.
std::shared_ptr<const ResampledSpectrum> sharedTable(
    const Rgb<double>& rgb, const std::shared_ptr<const EmissionSpectrum>& given) {
    using Key = std::tuple<const EmissionSpectrum*, double, double, double>;
    static std::mutex mutex;
    static std::map<Key, std::weak_ptr<const ResampledSpectrum>> tables;
    const Key key = given ? Key{given.get(), 0.0, 0.0, 0.0} : Key{nullptr, rgb[0], rgb[1], rgb[2]};
    const std::lock_guard lock(mutex);
    if (auto found = tables.find(key); found != tables.end())
        if (auto table = found->second.lock()) return table;
    std::shared_ptr<const ResampledSpectrum> table;
    if (given) {
        table = std::make_shared<const ResampledSpectrum>([&](double nm) { return (*given)(nm); });
    } else {
        const RgbSpectrum upsampled(rgb, RgbSpectrumKind::Illuminant);
        table = std::make_shared<const ResampledSpectrum>(upsampled);
    }
    // Entries of scenes gone: dropped whenever the map has doubled since the last sweep.
    static std::size_t sweepAt = 64;
    if (tables.size() >= sweepAt) {
        std::erase_if(tables, [](const auto& entry) { return entry.second.expired(); });
        sweepAt = 2 * std::max<std::size_t>(tables.size(), 32);
    }
    tables[key] = table;
    return table;
}

}  // namespace

EmitterColor::EmitterColor(const Rgb<double>& rgb, std::shared_ptr<const EmissionSpectrum> spectrum)
    : rgbD_(spectrum ? spectrum->rgb() : rgb),
      rgb_(float(rgbD_[0]), float(rgbD_[1]), float(rgbD_[2])),
      given_(std::move(spectrum)),
      table_(sharedTable(rgb, given_)) {}

}  // namespace lamina::render
