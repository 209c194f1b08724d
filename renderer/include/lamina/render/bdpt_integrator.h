// The `bdpt` integrator: Veach's bidirectional path tracer (Veach 1997, chapter 10; Veach and
// Guibas 1995). Per camera sample it traces a camera subpath and a light subpath and combines
// every (s, t) connection, s light vertices and t camera vertices:
//   s = 0       the camera subpath hits an emitter (or escapes to an infinite light);
//   s = 1       next-event estimation from camera vertex t-1 (a fresh light sample);
//   t = 1       light vertex s-1 connected to the lens and splatted (light tracing);
//   s, t >= 2   a deterministic connection of the two subpath ends.
// Each contribution is weighted by multiple importance sampling over all strategies that
// could have produced the same path (power heuristic, beta = 2; balance as an option), from
// the ratios of the forward and reverse densities (area measure) stored on the vertices, in
// O(s + t) per connection (Veach 1997, section 10.2.3). Delta lobes and delta lights have no
// density and are skipped as connection points. Light subpaths use the adjoint BSDF with the
// shading-normal correction (shading_normals.h), camera subpaths the BSDF.
#pragma once

#include <vector>

#include "lamina/render/integrator_common.h"
#include "lamina/render/pixel_filter.h"
#include "lamina/render/splat.h"

namespace lamina::render {

/// Per-(s, t) images for study (--strategies): every strategy's contribution with and
/// without its MIS weight, up to a path depth.
class StrategyImages {
  public:
    static constexpr int kMaxDepth = 4;  ///< s + t - 2 <= 4: 19 strategies

    StrategyImages(int width, int height)
        : width_(width), height_(height), weightSums_(std::size_t(width) * height, 0.0) {
        for (int depth = 0; depth <= kMaxDepth; ++depth)
            for (int t = 1; t <= depth + 2; ++t)
                if (!(depth == 0 && t == 1)) strategies_.push_back({depth + 2 - t, t});
        for (auto& b : buffers_)
            b.resize(2 * strategies_.size());
        for (auto& b : buffers_[0])
            b.assign(std::size_t(width) * height, Rgb<double>(0.0));
        for (auto& b : buffers_[1])
            b.assign(std::size_t(width) * height, Rgb<double>(0.0));
    }
    /// The strategy's slot, or -1 beyond kMaxDepth.
    int slot(int s, int t) const {
        for (std::size_t i = 0; i < strategies_.size(); ++i)
            if (strategies_[i].first == s && strategies_[i].second == t) return int(i);
        return -1;
    }
    const std::vector<std::pair<int, int>>& strategies() const { return strategies_; }
    /// A camera-side contribution (t >= 2) of a sample with filter weight w.
    void addCamera(int slot, int x, int y, const Rgb<double>& weighted,
                   const Rgb<double>& unweighted, double w) {
        at(0, 2 * slot, x, y) += weighted * w;
        at(0, 2 * slot + 1, x, y) += unweighted * w;
    }
    void addWeight(int x, int y, double w) { weightSums_[std::size_t(y) * width_ + x] += w; }
    /// A splat (t = 1), thread-safe.
    void addSplat(int slot, int x, int y, const Rgb<double>& weighted,
                  const Rgb<double>& unweighted) {
        for (int c = 0; c < 3; ++c) {
            std::atomic_ref<double>(at(1, 2 * slot, x, y)[c]).fetch_add(weighted[c]);
            std::atomic_ref<double>(at(1, 2 * slot + 1, x, y)[c]).fetch_add(unweighted[c]);
        }
    }
    /// The image of a strategy (`weighted` or not), in the film's space, after `particles`
    /// light paths in total.
    std::vector<Rgb<double>> image(int slot, bool weighted, double particles) const {
        std::vector<Rgb<double>> out(std::size_t(width_) * height_);
        const int b = 2 * slot + (weighted ? 0 : 1);
        for (std::size_t i = 0; i < out.size(); ++i) {
            const double w = weightSums_[i];
            out[i] = (w > 0 ? buffers_[0][std::size_t(b)][i] / w : Rgb<double>(0.0)) +
                     buffers_[1][std::size_t(b)][i] / particles;
        }
        return out;
    }
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    Rgb<double>& at(int part, int b, int x, int y) {
        return buffers_[std::size_t(part)][std::size_t(b)][std::size_t(y) * width_ + x];
    }
    int width_, height_;
    std::vector<std::pair<int, int>> strategies_;
    std::array<std::vector<std::vector<Rgb<double>>>, 2> buffers_;  ///< camera, splat
    std::vector<double> weightSums_;
};

template <SpectrumType S>
class BdptIntegrator {
  public:
    using Mode = RenderMode<S>;

    BdptIntegrator(const SceneContext& context, const Mode& mode, const RenderSettings& settings,
                   const PixelFilter& filter, const TransportAblations& ablations,
                   MisHeuristic heuristic)
        : c_(context),
          mode_(mode),
          settings_(settings),
          filter_(filter),
          ablations_(ablations),
          heuristic_(heuristic) {}

    /// One camera sample through film position `raster` (lens point `lens`): returns the
    /// camera-side estimate for its pixel and splats the t = 1 strategies on `film`.
    S sample(const Vec2f& raster, const Vec2f& lens, PixelSampler& sampler,
             typename Mode::Path& path, Film& film, PathStatistics& stats,
             StrategyImages* strategies = nullptr, int px = 0, int py = 0,
             double filterWeight = 1) const {
        thread_local std::vector<Vertex> cameraPath, lightPath;
        cameraPath.clear();
        lightPath.clear();
        generateCameraSubpath(raster, lens, sampler, path, cameraPath, stats);
        generateLightSubpath(sampler, path, lightPath, stats);

        S L(0.0f);
        const int nc = int(cameraPath.size()), nl = int(lightPath.size());
        for (int t = 1; t <= nc; ++t) {
            for (int s = 0; s <= nl; ++s) {
                const int depth = s + t - 2;
                // (1, 1) would connect a light point to the lens: the emitter seen directly,
                // which (0, 2) already counts with weight 1 (pbrt-v3 does the same).
                if (depth < 0 || depth > settings_.maxDepth || (s == 1 && t == 1)) continue;
                Vec2f splatAt(0.0f);
                float weight = 0.0f;
                const S c =
                    connect(lightPath, s, cameraPath, t, sampler, path, stats, splatAt, weight);
                if (c.maxValue() <= 0.0f || !c.isFinite()) continue;
                const S weighted = c * weight;
                if (t == 1)
                    splatFiltered(film, filter_, splatAt, mode_.filmValue(weighted, path));
                else
                    L += weighted;
                if (!strategies) continue;
                const int slot = strategies->slot(s, t);
                if (slot < 0) continue;
                const Rgb<double> wv = mode_.filmValue(weighted, path),
                                  uv = mode_.filmValue(c, path);
                if (!wv.isFinite() || !uv.isFinite() || wv.hasNegative() || uv.hasNegative())
                    continue;
                if (t == 1) {
                    forEachFilteredPixel(filter_, splatAt, strategies->width(),
                                         strategies->height(), [&](int x, int y, double w) {
                                             strategies->addSplat(slot, x, y, wv * w, uv * w);
                                         });
                } else {
                    strategies->addCamera(slot, px, py, wv, uv, filterWeight);
                }
            }
        }
        if (strategies) strategies->addWeight(px, py, filterWeight);
        return L;
    }

  private:
    enum class VertexType { Camera, Light, Surface };

    struct Vertex {
        VertexType type = VertexType::Surface;
        Vec3f p{0.0f}, ng{0.0f}, ns{0.0f};
        Vec2f uv{0.0f};
        int material = -1;
        int light = -1;           ///< the light of an emitter (Light vertices, emissive surfaces)
        bool infinite = false;    ///< a Light vertex at infinity; `p` holds its direction
        bool deltaLight = false;  ///< a Light vertex with a delta position or direction
        bool delta = false;       ///< scattered by a delta lobe
        S beta{0.0f};
        float pdfFwd = 0, pdfRev = 0;  ///< area densities (solid angle for infinite vertices)

        /// Surfaces and area-light points (not lenses, point lights or infinity).
        bool onSurface() const { return !infinite && ng != Vec3f(0.0f); }
    };

    // --- densities -------------------------------------------------------------------------

    /// Converts a solid-angle density at `from` towards `to` into an area density at `to`.
    static float toArea(float pdfSolidAngle, const Vertex& from, const Vertex& to) {
        if (to.infinite) return pdfSolidAngle;
        const Vec3f d = to.p - from.p;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return 0.0f;
        float pdf = pdfSolidAngle / dist2;
        if (to.onSurface()) pdf *= std::abs(glm::dot(to.ng, d)) / std::sqrt(dist2);
        return pdf;
    }

    static Vec3f directionTo(const Vertex& from, const Vertex& to) {
        if (to.infinite) return to.p;
        if (from.infinite) return -from.p;
        return glm::normalize(to.p - from.p);
    }

    /// Density (area measure at `next`) with which a light subpath starting at light vertex
    /// `v` reaches `next`.
    float pdfLight(const Vertex& v, const Vertex& next) const {
        if (v.infinite) {
            // From the disk every infinite light shares: its density projected on the
            // surface at `next`.
            const Vec3f d = -v.p;
            const Light& any = c_.lights.light(c_.lights.infiniteLights().front());
            const EmissionPdf e = any.emissionPdf(Vec3f(0.0f), Vec3f(0.0f), d);
            return e.position * (next.onSurface() ? std::abs(glm::dot(next.ng, d)) : 1.0f);
        }
        const Light& light = c_.lights.light(std::size_t(v.light));
        const Vec3f d = directionTo(v, next);
        const EmissionPdf e = light.emissionPdf(v.p, v.ng, d);
        return toArea(e.direction, v, next);
    }

    /// Density with which a light subpath starts at light vertex `v` (towards `next`).
    float pdfLightOrigin(const Vertex& v) const {
        if (v.infinite && v.deltaLight) return c_.lights.probability(std::size_t(v.light));
        if (v.infinite) return infiniteLightDensity(-v.p);
        const Light& light = c_.lights.light(std::size_t(v.light));
        return c_.lights.probability(std::size_t(v.light)) *
               light.emissionPdf(v.p, v.ng, Vec3f(0.0f, 0.0f, 1.0f)).position;
    }

    /// All environment lights start particles along `direction` (they cannot be told apart);
    /// directional lights are deltas, never hit.
    float infiniteLightDensity(const Vec3f& direction) const {
        float pdf = 0.0f;
        for (std::size_t i : c_.lights.infiniteLights())
            if (!c_.lights.light(i).isDelta())
                pdf +=
                    c_.lights.probability(i) *
                    c_.lights.light(i).emissionPdf(Vec3f(0.0f), Vec3f(0.0f), direction).direction;
        return pdf;
    }

    /// Density (area at `next`) with which vertex `v`, reached from `prev`, samples `next`.
    float pdf(const Vertex& v, const Vertex* prev, const Vertex& next,
              typename Mode::Path& path) const {
        if (v.type == VertexType::Light) return pdfLight(v, next);
        const Vec3f wn = directionTo(v, next);
        if (v.type == VertexType::Camera) return toArea(c_.camera.rayPdf(wn).direction, v, next);
        const Frame<float> frame = Frame<float>::fromNormal(v.ns);
        const Vec3f wp = directionTo(v, *prev);
        const Bxdf<S>& bsdf = mode_.bsdf(v.material, v.uv, path);
        return toArea(bsdf.pdf(frame.toLocal(wp), frame.toLocal(wn)), v, next);
    }

    // --- subpaths ----------------------------------------------------------------------------

    void generateCameraSubpath(const Vec2f& raster, const Vec2f& lens, PixelSampler& sampler,
                               typename Mode::Path& path, std::vector<Vertex>& out,
                               PathStatistics& stats) const {
        const auto ray = c_.camera.generateRay(raster.x, raster.y, lens);
        Vertex v;
        v.type = VertexType::Camera;
        v.p = ray.origin;
        v.beta = S(1.0f);
        out.push_back(v);
        const float pdfDir = c_.camera.rayPdf(ray.direction).direction;
        randomWalk(ray.origin, ray.direction, S(1.0f), pdfDir, settings_.maxDepth + 1,
                   TransportMode::Radiance, sampler, path, out, stats);
    }

    void generateLightSubpath(PixelSampler& sampler, typename Mode::Path& path,
                              std::vector<Vertex>& out, PathStatistics& stats) const {
        const float uLight = sampler.get1D();
        const Vec2f uPosition = sampler.get2D(), uDirection = sampler.get2D();
        if (c_.lights.empty()) return;
        const auto [index, pmf] = c_.lights.choose(uLight);
        const Light& light = c_.lights.light(index);
        const auto e = light.sampleEmission(uPosition, uDirection);
        if (!e || !(e->pdfPosition > 0.0f) || !(e->pdfDirection > 0.0f) || e->radiance.isZero())
            return;
        Vertex v;
        v.type = VertexType::Light;
        v.light = int(index);
        v.infinite = light.isInfinite();
        v.deltaLight = light.isDelta();
        v.p = v.infinite ? -e->direction : e->point;
        v.ng = v.ns = (e->deltaPosition || v.infinite) ? Vec3f(0.0f) : e->normal;
        v.beta = S(1.0f / (pmf * e->pdfPosition));
        v.pdfFwd = pdfLightOrigin(v);
        out.push_back(v);

        const S Le = mode_.emission(e->radiance, path);
        const S beta = Le * (std::abs(glm::dot(e->normal, e->direction)) /
                             (pmf * e->pdfPosition * e->pdfDirection));
        const bool onSurface = !e->deltaPosition && !v.infinite;
        const Vec3f origin =
            onSurface ? offsetRayOrigin(e->point, facing(e->normal, e->direction)) : e->point;
        const std::size_t first = out.size();
        randomWalk(origin, e->direction, beta, e->pdfDirection, settings_.maxDepth,
                   TransportMode::Importance, sampler, path, out, stats);
        // From infinity the first vertex's density is the disk's, projected (not 1/d^2).
        if (v.infinite && out.size() > first) {
            Vertex& v1 = out[first];
            v1.pdfFwd = e->pdfPosition * std::abs(glm::dot(v1.ng, e->direction));
        }
    }

    /// Extends a subpath from its last vertex along (o, d) with throughput `beta` and the
    /// solid-angle density `pdfDir` of d, until `maxScatter` surface vertices are added.
    void randomWalk(Vec3f o, Vec3f d, S beta, float pdfDir, int maxSurfaces, TransportMode mode,
                    PixelSampler& sampler, typename Mode::Path& path, std::vector<Vertex>& out,
                    PathStatistics& stats) const {
        const float beta0 = beta.maxValue();
        if (!(beta0 > 0.0f)) return;
        const bool lightPath = mode == TransportMode::Importance;
        const TransportMode bsdfMode =
            lightPath && ablations_.radianceOnLightPaths ? TransportMode::Radiance : mode;
        for (int surfaces = 0; surfaces < maxSurfaces; ++surfaces) {
            ++stats.rays;
            const auto hit = c_.geometry.intersect(o, d);
            if (!hit) {
                if (!lightPath && !c_.lights.infiniteLights().empty()) {
                    Vertex v;
                    v.type = VertexType::Light;
                    v.infinite = true;
                    v.p = d;
                    v.beta = beta;
                    v.pdfFwd = pdfDir;
                    out.push_back(v);
                }
                return;
            }
            Vertex v;
            v.p = hit->p;
            v.ng = hit->ng;
            v.ns = hit->ns;
            v.uv = hit->uv;
            v.material = c_.geometry.shapes()[std::size_t(hit->shape)].material;
            v.light = c_.lights.lightAt(*hit);
            v.beta = beta;
            Vertex& prev = out.back();
            v.pdfFwd = toArea(pdfDir, prev, v);
            out.push_back(v);
            Vertex& cur = out.back();
            Vertex& before = out[out.size() - 2];
            if (surfaces + 1 >= maxSurfaces) return;

            const Bxdf<S>& bsdf = mode_.bsdf(cur.material, cur.uv, path);
            const Frame<float> frame = Frame<float>::fromNormal(cur.ns);
            const Vec3f woWorld = -d;
            const Vec3f wo = frame.toLocal(woWorld);
            const float uc = sampler.get1D();
            const Vec2f u = sampler.get2D();
            const auto s = bsdf.sample(wo, uc, u, bsdfMode);
            if (!s || !(s->pdf > 0.0f)) return;
            const Vec3f wi = frame.toWorld(s->wi);
            if (!sidesAgree(woWorld, wi, cur.ng, cur.ns)) return;
            beta *= s->weight;
            if (lightPath) beta *= correction(woWorld, wi, cur);
            float pdfRev;
            if (s->isSpecular()) {
                cur.delta = true;
                pdfDir = pdfRev = 0.0f;
            } else {
                pdfDir = s->pdf;
                pdfRev = bsdf.pdf(s->wi, wo);
            }
            before.pdfRev = toArea(pdfRev, cur, before);

            const float uRoulette = sampler.get1D();
            if (!russianRoulette(beta, beta.maxValue() / beta0, surfaces + 1,
                                 settings_.russianRouletteDepth, uRoulette))
                return;
            if (!beta.isFinite() || beta.maxValue() <= 0.0f) return;
            o = offsetRayOrigin(cur.p, facing(cur.ng, wi));
            d = wi;
        }
    }

    float correction(const Vec3f& wo, const Vec3f& wi, const Vertex& v) const {
        if (ablations_.noAdjointCorrection) return 1.0f;
        return adjointShadingCorrection(wo, wi, v.ng, v.ns);
    }

    // --- connections ---------------------------------------------------------------------------

    /// The BSDF of surface vertex `v` for light arriving from `from` (a point, or a direction
    /// when infinite) and leaving to `to`, in the subpath's transport mode, with the sides
    /// rule and (light subpaths) the adjoint correction. `wPrev` points to the subpath's
    /// previous vertex.
    S evalAt(const Vertex& v, const Vec3f& wPrev, const Vec3f& wNext, bool lightSubpath,
             typename Mode::Path& path) const {
        if (!sidesAgree(wPrev, wNext, v.ng, v.ns)) return S(0.0f);
        const Frame<float> frame = Frame<float>::fromNormal(v.ns);
        const Bxdf<S>& bsdf = mode_.bsdf(v.material, v.uv, path);
        const TransportMode m = lightSubpath && !ablations_.radianceOnLightPaths
                                    ? TransportMode::Importance
                                    : TransportMode::Radiance;
        const Vec3f prev = frame.toLocal(wPrev), next = frame.toLocal(wNext);
        S f = lightSubpath && ablations_.swappedConnections ? bsdf.eval(next, prev, m)
                                                            : bsdf.eval(prev, next, m);
        if (lightSubpath) f *= correction(wPrev, wNext, v);
        return f;
    }

    /// Radiance emitted by emitter vertex `v` towards `w`.
    S emitted(const Vertex& v, const Vec3f& w, typename Mode::Path& path) const {
        if (v.infinite) {
            S Le(0.0f);
            for (std::size_t i : c_.lights.infiniteLights())
                Le += mode_.emission(c_.lights.light(i).environment(-w), path);
            return Le;
        }
        if (v.light < 0) return S(0.0f);
        SurfaceHit at;
        at.p = v.p;
        at.ng = at.ns = v.ng;
        return mode_.emission(c_.lights.light(std::size_t(v.light)).radiance(at, w), path);
    }

    bool unoccluded(const Vertex& a, const Vertex& b, PathStatistics& stats) const {
        return segmentUnoccluded(c_.geometry, a.p, a.ng, b.p, b.ng, stats);
    }

    /// The unweighted contribution of strategy (s, t) and its MIS weight.
    S connect(std::vector<Vertex>& lightPath, int s, std::vector<Vertex>& cameraPath, int t,
              PixelSampler& sampler, typename Mode::Path& path, PathStatistics& stats,
              Vec2f& raster, float& weight) const {
        Vertex& cv = cameraPath[std::size_t(t - 1)];
        Vertex sampled;  // the fresh vertex of s = 1 or t = 1
        S value(0.0f);
        if (s == 0) {
            // The camera subpath's end is an emitter.
            if (!(cv.infinite || (cv.type == VertexType::Surface && cv.light >= 0))) return value;
            const Vertex& prev = cameraPath[std::size_t(t - 2)];
            value = cv.beta * emitted(cv, cv.infinite ? -cv.p : directionTo(cv, prev), path);
        } else if (t == 1) {
            // Light vertex s-1 (a surface: s >= 2, since (1, 1) is skipped) seen by the camera.
            const Vertex& lv = lightPath[std::size_t(s - 1)];
            if (lv.delta) return value;
            const auto cc = c_.camera.sampleConnection(lv.p, sampler.get2D());
            if (!cc) return value;
            sampled.type = VertexType::Camera;
            sampled.p = cc->lensPoint;
            sampled.beta = S(cc->importance / cc->pdf);
            raster = cc->raster;
            const Vec3f wPrev = directionTo(lv, lightPath[std::size_t(s - 2)]);
            const S f = evalAt(lv, wPrev, cc->wi, true, path);
            if (f.maxValue() <= 0.0f) return value;
            value = lv.beta * f * sampled.beta;
            if (!unoccluded(lv, sampled, stats)) return S(0.0f);
        } else if (s == 1) {
            // Next-event estimation: a fresh point on a light.
            if (cv.type != VertexType::Surface || cv.delta) return value;
            const float uLight = sampler.get1D();
            const Vec2f uPoint = sampler.get2D();
            if (c_.lights.empty()) return value;
            const auto [index, pmf] = c_.lights.choose(uLight);
            const Light& light = c_.lights.light(index);
            const auto ls = light.sample(cv.p, uPoint);
            if (!ls || !(ls->pdf > 0.0f) || ls->radiance.isZero()) return value;
            sampled.type = VertexType::Light;
            sampled.light = int(index);
            sampled.infinite = light.isInfinite();
            sampled.deltaLight = light.isDelta();
            sampled.p = sampled.infinite ? ls->wi : ls->point;
            sampled.ng = sampled.ns =
                (light.isDelta() || sampled.infinite) ? Vec3f(0.0f) : ls->normal;
            sampled.pdfFwd = pdfLightOrigin(sampled);
            const Vec3f wPrev = directionTo(cv, cameraPath[std::size_t(t - 2)]);
            const S f = evalAt(cv, wPrev, ls->wi, false, path);
            if (f.maxValue() <= 0.0f) return value;
            sampled.beta = mode_.emission(ls->radiance, path) / (pmf * ls->pdf);
            value = cv.beta * f * sampled.beta;
            const bool visible = sampled.infinite
                                     ? directionUnoccluded(c_.geometry, cv.p, cv.ng, ls->wi, stats)
                                     : unoccluded(cv, sampled, stats);
            if (!visible) return S(0.0f);
        } else {
            // Both ends are surface vertices: connect them.
            const Vertex& lv = lightPath[std::size_t(s - 1)];
            if (cv.type != VertexType::Surface || lv.type != VertexType::Surface || cv.delta ||
                lv.delta)
                return value;
            const Vec3f d = lv.p - cv.p;
            const float dist2 = glm::dot(d, d);
            if (!(dist2 > 0.0f)) return value;
            const Vec3f w = d / std::sqrt(dist2);
            const S fc =
                evalAt(cv, directionTo(cv, cameraPath[std::size_t(t - 2)]), w, false, path);
            if (fc.maxValue() <= 0.0f) return value;
            const S fl = evalAt(lv, directionTo(lv, lightPath[std::size_t(s - 2)]), -w, true, path);
            if (fl.maxValue() <= 0.0f) return value;
            value = cv.beta * fc * fl * lv.beta * (1.0f / dist2);
            if (!unoccluded(cv, lv, stats)) return S(0.0f);
        }
        if (value.maxValue() <= 0.0f) return value;
        weight = misWeight(lightPath, s, cameraPath, t, sampled, path);
        return value;
    }

    // --- MIS ---------------------------------------------------------------------------------

    struct Densities {
        float pdfFwd, pdfRev;
        bool delta;
    };

    /// The weight of strategy (s, t) among all strategies producing the same path: 1 / (1 +
    /// sum over the other strategies of (p_other / p_this)^beta), the ratios accumulated
    /// vertex by vertex outwards from the connection (Veach 1997, eq. 10.9).
    float misWeight(const std::vector<Vertex>& lightPath, int s,
                    const std::vector<Vertex>& cameraPath, int t, const Vertex& sampled,
                    typename Mode::Path& path) const {
        if (s + t == 2) return 1.0f;
        thread_local std::vector<Densities> lightD, cameraD;
        lightD.resize(std::size_t(s));
        cameraD.resize(std::size_t(t));
        for (int i = 0; i < s; ++i)
            lightD[std::size_t(i)] = {lightPath[std::size_t(i)].pdfFwd,
                                      lightPath[std::size_t(i)].pdfRev,
                                      lightPath[std::size_t(i)].delta};
        for (int i = 0; i < t; ++i)
            cameraD[std::size_t(i)] = {cameraPath[std::size_t(i)].pdfFwd,
                                       cameraPath[std::size_t(i)].pdfRev,
                                       cameraPath[std::size_t(i)].delta};
        // The path's end vertices as this strategy sees them.
        const bool freshLight = s == 1 && t > 1;  // next-event estimation's own light point
        const Vertex& qs = freshLight || s == 0 ? sampled : lightPath[std::size_t(s - 1)];
        const Vertex& pt = t == 1 ? sampled : cameraPath[std::size_t(t - 1)];
        const Vertex* qsMinus = s > 1 ? &lightPath[std::size_t(s - 2)] : nullptr;
        const Vertex* ptMinus = t > 1 ? &cameraPath[std::size_t(t - 2)] : nullptr;
        if (freshLight) lightD[0] = {sampled.pdfFwd, lightD[0].pdfRev, false};
        if (t == 1) cameraD[0] = {cameraD[0].pdfFwd, cameraD[0].pdfRev, false};
        if (s > 0) lightD[std::size_t(s - 1)].delta = false;
        cameraD[std::size_t(t - 1)].delta = false;

        // Reverse densities at the connection.
        if (s > 0) {
            cameraD[std::size_t(t - 1)].pdfRev = pdf(qs, qsMinus, pt, path);
        } else {
            cameraD[std::size_t(t - 1)].pdfRev = pdfLightOrigin(pt);
        }
        if (ptMinus) {
            cameraD[std::size_t(t - 2)].pdfRev =
                s > 0 ? pdf(pt, &qs, *ptMinus, path) : pdfLight(pt, *ptMinus);
        }
        if (s > 0) lightD[std::size_t(s - 1)].pdfRev = pdf(pt, ptMinus, qs, path);
        if (qsMinus) lightD[std::size_t(s - 2)].pdfRev = pdf(qs, &pt, *qsMinus, path);

        const auto ratio = [this](float num, float den) {
            const float r = (num != 0.0f ? num : 1.0f) / (den != 0.0f ? den : 1.0f);
            return heuristic_ == MisHeuristic::Power ? r * r : r;
        };
        float sum = 0.0f, r = 1.0f;
        for (int i = t - 1; i > 0; --i) {
            r *= ratio(cameraD[std::size_t(i)].pdfRev, cameraD[std::size_t(i)].pdfFwd);
            if (!cameraD[std::size_t(i)].delta && !cameraD[std::size_t(i - 1)].delta) sum += r;
        }
        r = 1.0f;
        for (int i = s - 1; i >= 0; --i) {
            r *= ratio(lightD[std::size_t(i)].pdfRev, lightD[std::size_t(i)].pdfFwd);
            const bool deltaBefore = i > 0 ? lightD[std::size_t(i - 1)].delta
                                           : (freshLight ? sampled : lightPath[0]).deltaLight;
            if (!lightD[std::size_t(i)].delta && !deltaBefore) sum += r;
        }
        return 1.0f / (1.0f + sum);
    }

    SceneContext c_;
    const Mode& mode_;
    RenderSettings settings_;
    const PixelFilter& filter_;
    TransportAblations ablations_;
    MisHeuristic heuristic_;
};

}  // namespace lamina::render
