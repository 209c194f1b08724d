#include "lamina/experiments/stability_audit.h"

#include <cmath>

#include "lamina/core/pcg32.h"
#include "lamina/core/warp.h"
#include "lamina/experiments/interrupted.h"

namespace lamina::experiments {

namespace {

void classifyScalar(double x, StabilityCell& cell) {
    if (std::isnan(x))
        ++cell.nan;
    else if (std::isinf(x))
        ++cell.inf;
    else if (x < 0)
        ++cell.negative;
}

template <typename S>
void classify(const S& v, StabilityCell& cell) {
    for (int i = 0; i < S::kSize; ++i)
        classifyScalar(double(v[i]), cell);
}

}  // namespace

StabilityReport auditStability(const StabilityModel& model, std::vector<double> alphas,
                               std::vector<double> cosines, int directions, int samples) {
    using V3 = Vec3<double>;
    StabilityReport report;
    report.alphas = std::move(alphas);
    report.cosines = std::move(cosines);
    report.cells.resize(report.alphas.size() * report.cosines.size());
    for (std::size_t ai = 0; ai < report.alphas.size(); ++ai) {
        stopIfInterrupted();  // a row of the sweep takes a while
        const auto d = model.makeDouble(report.alphas[ai]);
        const auto f = model.makeFloat(report.alphas[ai]);
        for (std::size_t ci = 0; ci < report.cosines.size(); ++ci) {
            StabilityCell& cell = report.cells[ai * report.cosines.size() + ci];
            const double c = report.cosines[ci];
            // Rounded to float first, so both precisions see the same input.
            const V3 wo(Vec3<float>(V3(std::sqrt(std::max(0.0, 1 - c * c)), 0.0, c)));
            std::vector<V3> wis = {
                wo,          V3(-wo.x, -wo.y, wo.z), -wo, V3(1, 0, 0), V3(0, 1, 0), V3(0, 0, 1),
                V3(0, 0, -1)};
            Pcg32 rng(1 + ai * 131 + ci, 7);
            for (int k = 0; k < directions; ++k)
                wis.emplace_back(Vec3<float>(
                    squareToUniformSphere(Vec2<double>(rng.nextDouble(), rng.nextDouble()))));
            double peak = 0;
            std::vector<Rgb<double>> values;
            for (const V3& wi : wis)
                for (auto mode : {TransportMode::Radiance, TransportMode::Importance}) {
                    const Rgb<double> v = d->eval(wo, wi, mode);
                    const Rgb<float> vf = f->eval(Vec3<float>(wo), Vec3<float>(wi), mode);
                    classify(v, cell);
                    classify(vf, cell);
                    classifyScalar(d->pdf(wo, wi), cell);
                    classifyScalar(double(f->pdf(Vec3<float>(wo), Vec3<float>(wi))), cell);
                    cell.evaluations += 2;
                    if (mode == TransportMode::Radiance) values.push_back(v);
                    if (v.isFinite()) peak = std::max(peak, v.maxValue());
                }
            for (std::size_t k = 0; k < wis.size(); ++k) {
                const Rgb<double>& v = values[k];
                const Rgb<float> vf =
                    f->eval(Vec3<float>(wo), Vec3<float>(wis[k]), TransportMode::Radiance);
                for (int ch = 0; ch < 3; ++ch)
                    if (std::isfinite(v[ch]) && v[ch] > 1e-6 * peak && std::isfinite(vf[ch]))
                        cell.worstFloatError = std::max(cell.worstFloatError,
                                                        std::abs(double(vf[ch]) - v[ch]) / v[ch]);
            }
            // Sampling, including the random numbers' edges (pbrt-v4 #313).
            Rgb<double> sum(0.0), sumSq(0.0);
            for (int k = 0; k < samples; ++k) {
                const bool edge = k < 8;
                const double uc = edge ? (k & 1 ? 1 - 1e-16 : 0.0) : rng.nextDouble();
                const Vec2<double> u =
                    edge ? Vec2<double>(k & 2 ? 1 - 1e-16 : 0.0, k & 4 ? 1 - 1e-16 : 0.0)
                         : Vec2<double>(rng.nextDouble(), rng.nextDouble());
                ++cell.samples;
                const TransportMode mode =
                    k % 2 ? TransportMode::Importance : TransportMode::Radiance;
                const auto s = d->sample(wo, uc, u, mode);
                const auto sf = f->sample(Vec3<float>(wo), float(uc), Vec2<float>(u), mode);
                if (sf) {
                    classify(sf->weight, cell);
                    classifyScalar(double(sf->pdf), cell);
                }
                if (!s) continue;
                classify(s->weight, cell);
                classifyScalar(s->pdf, cell);
                if (!s->weight.isFinite()) continue;
                if (!edge && mode == TransportMode::Importance) {
                    sum += s->weight;
                    sumSq += s->weight * s->weight;
                }
                if (!s->isSpecular() && s->pdf > 0) {
                    const Rgb<double> expected = d->eval(wo, s->wi, mode) / d->pdf(wo, s->wi);
                    for (int ch = 0; ch < 3; ++ch)
                        if (std::abs(expected[ch] - s->weight[ch]) >
                            1e-3 * std::max(std::abs(expected[ch]), 1e-6)) {
                            ++cell.weightMismatch;
                            break;
                        }
                }
            }
            const double n = double(samples - 8) / 2;  // importance-mode samples
            for (int ch = 0; ch < 3; ++ch) {
                const double mean = sum[ch] / n;
                const double se = std::sqrt(std::max(0.0, sumSq[ch] / n - mean * mean) / n);
                if (mean > 1 + 3 * se + 1e-3) {
                    ++cell.energyGain;
                    break;
                }
            }
        }
    }
    return report;
}

}  // namespace lamina::experiments
