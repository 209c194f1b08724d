#include "lamina/experiments/noise_floor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lamina/core/error.h"
#include "lamina/experiments/image_metrics.h"
#include "lamina/experiments/text_format.h"

namespace lamina::experiments {

void requireSeedDependentSampler(render::SamplerKind sampler, const std::string& experiment) {
    if (sampler == render::SamplerKind::SobolGlobal)
        throw InputError(experiment +
                         ": the noise floor compares renders with different seeds, and the "
                         "sampler sobol-global's film positions are the same for every seed; "
                         "use --sampler sobol");
}

NoiseOnlyPair pairedNoise(const render::RgbImage& a1, const render::RgbImage& b1,
                          const render::RgbImage& a2, const render::RgbImage& b2) {
    for (const render::RgbImage* image : {&a1, &a2, &b2})
        if (image->width != b1.width || image->height != b1.height)
            throw std::logic_error("pairedNoise: four renders of one size");
    NoiseOnlyPair pair{a1, b1};
    for (std::size_t i = 0; i < b1.pixels.size(); ++i) {
        const double mean = (double(a1.pixels[i]) + double(b1.pixels[i])) / 2;
        const double difference1 = double(a1.pixels[i]) - double(b1.pixels[i]);
        const double difference2 = double(a2.pixels[i]) - double(b2.pixels[i]);
        const double noise = (difference1 - difference2) / std::sqrt(2.0);
        pair.a.pixels[i] = float(mean + noise / 2);
        pair.b.pixels[i] = float(mean - noise / 2);
    }
    return pair;
}

FlooredMap flooredMap(
    const std::function<std::vector<float>(const render::RgbImage&, const render::RgbImage&)>& map,
    const render::RgbImage& a1, const render::RgbImage& b1, const render::RgbImage& a2,
    const render::RgbImage& b2, const NoiseOnlyPair& noiseOnly) {
    FlooredMap m;
    m.values = map(a1, b1);
    const std::vector<float> floor = map(noiseOnly.a, noiseOnly.b);
    const std::vector<float> other = map(a2, b2);
    m.mean = {meanOfFinite(m.values), meanOfFinite(floor), meanOfFinite(other)};
    m.p95 = {percentileOf(m.values, 95), percentileOf(floor, 95), percentileOf(other, 95)};
    return m;
}

NoiseFloorReading readAgainstFloor(double difference, double floor, int spp) {
    NoiseFloorReading r;
    r.difference = difference;
    r.floor = floor;
    r.resolved = difference > kResolvedOverFloor * floor;
    if (r.resolved || spp <= 0) return r;
    const double trueDifference = std::sqrt(std::max(0.0, difference * difference - floor * floor));
    if (trueDifference <= 0) return r;
    const double ratio = kResolvedOverFloor * floor / trueDifference;
    r.sppToResolve = static_cast<long long>(std::ceil(double(spp) * ratio * ratio));
    return r;
}

std::string describeReading(const NoiseFloorReading& r, int spp) {
    const std::string value = formatText("%.2f", r.difference);
    const std::string floor = formatText("%.2f", r.floor);
    if (r.resolved) return value + " (noise floor " + floor + ")";
    std::string s =
        value + " (noise floor " + floor + ": not resolved at " + std::to_string(spp) + " spp";
    if (r.sppToResolve > 0)
        s += "; about " + std::to_string(r.sppToResolve) + " spp would resolve it";
    else
        s += "; no difference beyond the noise";
    return s + ")";
}

}  // namespace lamina::experiments
