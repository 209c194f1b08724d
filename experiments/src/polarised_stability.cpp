#include "lamina/experiments/polarised_stability.h"

#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "lamina/core/json_reader.h"
#include "lamina/spectral/sampled_wavelengths.h"

namespace lamina::experiments {

namespace {

/// A model's build with the wavelengths it reads kept alive beside it.
template <std::floating_point T>
struct SpectralBuild {
    SampledWavelengths<T> lambda = SampledWavelengths<T>::fixed({450, 520, 600, 680});
    std::unique_ptr<Bxdf<SampledSpectrum<T>>> bxdf;
};

/// One matrix of a probe point, with what it is, so that neighbours compare like with like.
template <std::floating_point T>
struct Entry {
    int slot = 0;             ///< which direction or random numbers made it
    std::uint32_t flags = 0;  ///< a sample's lobe (0 for an evaluation)
    Vec3<T> wi;
    MuellerMatrix<SampledSpectrum<T>> m;
};

/// Every matrix the audit computes with wo at the cosine `c` (negative: inside) in the xz plane.
template <std::floating_point T>
std::vector<Entry<T>> entriesAt(const Bxdf<SampledSpectrum<T>>& b, T c,
                                const std::vector<double>& indices) {
    using V = Vec3<T>;
    c = clamp(c, T(-1), T(1));  // the neighbour of +-1 beyond it is +-1 itself
    const V wo(std::sqrt(std::max(T(0), T(1) - c * c)), T(0), c);
    std::vector<V> wis = {V(-wo.x, T(0), wo.z), -wo, V(0, 0, 1), V(0, 0, -1)};
    for (const double eta : indices) {
        // The refraction of wo through the normal on the side it lies.
        const T e = wo.z > T(0) ? T(eta) : T(1 / eta);
        const T sinT = wo.x / e;
        if (sinT < T(1))
            wis.emplace_back(-sinT, T(0), -std::copysign(std::sqrt(T(1) - sinT * sinT), wo.z));
    }
    std::vector<Entry<T>> out;
    int slot = 0;
    for (const V& wi : wis)
        for (const auto mode : {TransportMode::Radiance, TransportMode::Importance})
            out.push_back({slot++, 0u, wi, b.evalMueller(wo, wi, mode)});
    const T edge = T(1) - std::numeric_limits<T>::epsilon();
    for (const T uc : {T(0), T(0.5), edge})
        for (const T u : {T(0), T(0.5), edge})
            for (const auto mode : {TransportMode::Radiance, TransportMode::Importance}) {
                const auto s = b.sample(wo, uc, Vec2<T>(u, u), mode);
                if (s) out.push_back({slot, s->flags, s->wi, b.sampleMueller(wo, *s, mode)});
                ++slot;
            }
    return out;
}

template <std::floating_point T>
void countNonFinite(const std::vector<Entry<T>>& entries, PolarisedProbe& p) {
    for (const Entry<T>& e : entries) {
        bool nan = false, inf = false;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                for (int k = 0; k < SampledSpectrum<T>::kSize; ++k) {
                    nan |= std::isnan(e.m(i, j)[k]);
                    inf |= std::isinf(e.m(i, j)[k]);
                }
        p.nan += nan;
        p.inf += inf;
        ++p.evaluations;
    }
}

/// The largest change of an element between matching entries of two neighbouring points, over
/// the largest [0][0] among them (the probe's scale: a transmission vanishing at the critical
/// angle changes relative to itself by 1, and is compared with the light that is reflected).
/// Entries match when the same direction or random numbers made them, with the same lobe, in
/// nearly the same direction: a sample's direction may jump where the sampling's own frame
/// around wo turns (at the pole), which changes the configuration, not the matrix of one.
constexpr double kSameDirection = 1e-2;  // neighbours' directions move by O(sqrt(ulp))

template <std::floating_point T>
double jumpBetween(const std::vector<Entry<T>>& a, const std::vector<Entry<T>>& b) {
    double scale = 0;
    for (const auto* list : {&a, &b})
        for (const Entry<T>& e : *list)
            for (int k = 0; k < SampledSpectrum<T>::kSize; ++k)
                if (std::isfinite(e.m(0, 0)[k]))
                    scale = std::max(scale, std::abs(double(e.m(0, 0)[k])));
    if (!(scale > 0)) return 0;
    double jump = 0;
    for (const Entry<T>& x : a)
        for (const Entry<T>& y : b) {
            if (x.slot != y.slot || x.flags != y.flags ||
                glm::length(Vec3<double>(x.wi) - Vec3<double>(y.wi)) > kSameDirection)
                continue;
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j)
                    for (int k = 0; k < SampledSpectrum<T>::kSize; ++k) {
                        const double d = std::abs(double(x.m(i, j)[k]) - double(y.m(i, j)[k]));
                        if (std::isfinite(d)) jump = std::max(jump, d / scale);
                    }
        }
    return jump;
}

/// The probe in precision T: NaN and Inf at c and its neighbours one ulp away, and (with
/// `neighbours`) the jump across them.
template <std::floating_point T>
double probe(const Bxdf<SampledSpectrum<T>>& b, double cosTheta, bool neighbours,
             const std::vector<double>& indices, PolarisedProbe& p) {
    const T c = T(cosTheta);
    const auto centre = entriesAt(b, c, indices);
    countNonFinite(centre, p);
    if (!neighbours) return 0;
    double jump = 0;
    for (const T towards : {T(-2), T(2)}) {
        const auto side = entriesAt(b, std::nextafter(c, towards), indices);
        countNonFinite(side, p);
        jump = std::max(jump, jumpBetween(centre, side));
    }
    return jump;
}

struct Special {
    std::string what;
    double cosTheta;
    bool neighbours;
};

std::vector<Special> specialAngles(const std::vector<double>& indices) {
    // Along the normal every plane contains wo and the s axis is a convention (stokesAxis);
    // one ulp off it the plane of incidence is xz: a frame error would jump there.
    std::vector<Special> s = {{"wo along the normal", 1.0, true},
                              {"wo along the normal, inside", -1.0, true},
                              {"grazing, cos 1e-8", 1e-8, false},
                              {"grazing, cos 0", 0.0, false},
                              {"grazing inside, cos -1e-8", -1e-8, false}};
    for (const double eta : indices)
        for (const int side : {1, -1}) {
            const double e = side > 0 ? eta : 1 / eta;  // the relative index seen from wo's side
            const std::string where = side > 0 ? "outside" : "inside";
            s.push_back({"Brewster's angle, " + where, side / std::sqrt(1 + e * e), true});
            if (e < 1) s.push_back({"critical angle, " + where, side * std::sqrt(1 - e * e), true});
        }
    return s;
}

}  // namespace

std::vector<double> probedIndices(const std::string& materialJson) {
    const Json j = Json::parse(materialJson, nullptr, false);
    if (!j.is_object() || !j.contains("type")) return {};
    if (j["type"] == "dielectric" && j.contains("ior") && j["ior"].is_number())
        return {j["ior"].get<double>()};
    if (j["type"] == "conductor" && j.contains("eta") && j["eta"].is_number() && j.contains("k") &&
        j["k"].is_number() && j["k"].get<double>() == 0)
        return {j["eta"].get<double>()};
    return {};
}

PolarisedStabilityReport auditPolarisedStability(const PolarisedStabilityModel& model,
                                                 const std::vector<double>& alphas,
                                                 const std::vector<double>& indices) {
    PolarisedStabilityReport r;
    for (const double alpha : alphas) {
        SpectralBuild<double> d;
        d.bxdf = model.makeDouble(alpha, d.lambda);
        SpectralBuild<float> f;
        f.bxdf = model.makeFloat(alpha, f.lambda);
        for (const Special& s : specialAngles(indices)) {
            PolarisedProbe p;
            p.what = s.what;
            p.cosTheta = s.cosTheta;
            p.alpha = alpha;
            p.jumpDouble = probe(*d.bxdf, s.cosTheta, s.neighbours, indices, p);
            p.jumpFloat = probe(*f.bxdf, s.cosTheta, s.neighbours, indices, p);
            r.evaluations += p.evaluations;
            r.nan += p.nan;
            r.inf += p.inf;
            r.worstJumpFloat = std::max(r.worstJumpFloat, p.jumpFloat);
            r.worstJumpDouble = std::max(r.worstJumpDouble, p.jumpDouble);
            r.discontinuities += (p.jumpFloat > kPolarisedJumpBound<float>)+(
                p.jumpDouble > kPolarisedJumpBound<double>);
            r.probes.push_back(std::move(p));
        }
    }
    return r;
}

PolarisedStabilityReport auditPolarisedStability(
    const std::function<MaterialDesc(double alpha)>& materialAt, const std::vector<double>& alphas,
    const std::vector<double>& indices) {
    PolarisedStabilityModel model;
    model.makeDouble = [&](double alpha, SampledWavelengths<double>& lambda) {
        return buildBxdf(materialAt(alpha), SpectrumContext<SampledSpectrum<double>>{lambda});
    };
    model.makeFloat = [&](double alpha, SampledWavelengths<float>& lambda) {
        return buildBxdf(materialAt(alpha), SpectrumContext<SampledSpectrum<float>>{lambda});
    };
    return auditPolarisedStability(model, alphas, indices);
}

}  // namespace lamina::experiments
