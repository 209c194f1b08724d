#include "lamina/render/lights.h"

#include <algorithm>

#include "lamina/core/warp.h"
#include "lamina/render/environment_map.h"
#include "lamina/render/ray_offset.h"

namespace lamina::render {

namespace {

using Vec3d = Vec3<double>;

// Converts an area density at a light point to solid angle at `ref`.
float areaToSolidAngle(float pdfArea, const Vec3f& ref, const Vec3f& p, const Vec3f& n) {
    const Vec3f d = p - ref;
    const float dist2 = glm::dot(d, d);
    const float cosLight = std::abs(glm::dot(n, d)) / std::sqrt(dist2);
    if (!(cosLight > 0.0f)) return 0.0f;
    return pdfArea * dist2 / cosLight;
}

/// Particles from infinite lights start on a disk of the scene's bounding radius, centred
/// on the bounding sphere's tangent plane on the light's side and perpendicular to their
/// direction, so every one of them crosses the scene's bounds (pbrt-v4 section 12.5).
struct SceneDisk {
    Vec3f center;
    float radius;
    Vec3f pointFacing(const Vec3f& direction, const Vec2f& u) const {
        const Vec2f d = squareToUniformDiskConcentric(u) * radius;
        return center - radius * direction +
               Frame<float>::fromNormal(direction).toWorld(Vec3f(d.x, d.y, 0.0f));
    }
    float pdf() const { return 1.0f / (kPi<float> * radius * radius); }
};

/// What every emitting surface shares: its colour, one- or two-sided emission, and a power
/// of (1 or 2) pi A L for area A and radiance L.
class AreaLight : public Light {
  public:
    Emission radiance(const SurfaceHit& hit, const Vec3f& w) const override {
        if (twoSided_ || glm::dot(hit.ng, w) > 0.0f) return {&color_, 1.0f};
        return {};
    }

    double power() const override {
        return (twoSided_ ? 2.0 : 1.0) * kPi<double> * area_ * luminance(color_.rgbDouble());
    }

    // Particles: a point uniform by area, a cosine-distributed direction about the normal
    // (on a side chosen with probability 1/2 when two-sided).
    std::optional<EmissionSample> sampleEmission(const Vec2f& uPosition,
                                                 const Vec2f& uDirection) const override {
        if (!(area_ > 0)) return std::nullopt;
        const auto [p, n] = samplePoint(uPosition);
        Vec2f u = uDirection;
        Vec3f normal = n;
        if (twoSided_) {
            const bool back = u.x >= 0.5f;
            u.x = std::min(2.0f * (back ? u.x - 0.5f : u.x), kOneMinusEpsilon<float>);
            if (back) normal = -n;
        }
        const Vec3f local = squareToCosineHemisphere(u);
        if (!(local.z > 0.0f)) return std::nullopt;
        EmissionSample e;
        e.point = p;
        e.normal = normal;
        e.direction = Frame<float>::fromNormal(normal).toWorld(local);
        e.radiance = {&color_, 1.0f};
        e.pdfPosition = float(1.0 / area_);
        e.pdfDirection = local.z * kInvPi<float> * (twoSided_ ? 0.5f : 1.0f);
        return e;
    }

    EmissionPdf emissionPdf(const Vec3f&, const Vec3f& normal,
                            const Vec3f& direction) const override {
        const float c = glm::dot(normal, direction);
        if (!twoSided_ && !(c > 0.0f)) return {float(1.0 / area_), 0.0f};
        return {float(1.0 / area_), std::abs(c) * kInvPi<float> * (twoSided_ ? 0.5f : 1.0f)};
    }

  protected:
    struct AreaPoint {
        Vec3f p, n;  ///< the point and the front normal
    };
    /// A point uniform by area.
    virtual AreaPoint samplePoint(const Vec2f& u) const = 0;

    AreaLight(const EmissionDesc& e, double area)
        : twoSided_(e.twoSided), color_(e.radiance, e.spectrum), area_(area) {}

    bool twoSided_;
    EmitterColor color_;
    double area_;
};

/// One emitting triangle of a mesh, sampled uniformly by area.
class TriangleLight final : public AreaLight {
  public:
    TriangleLight(const MeshDesc& mesh, std::size_t triangle) : AreaLight(*mesh.emission, 0.0) {
        const auto& t = mesh.triangles[triangle];
        p0_ = mesh.positions[t[0]];
        p1_ = mesh.positions[t[1]];
        p2_ = mesh.positions[t[2]];
        const Vec3d c = glm::cross(Vec3d(p1_ - p0_), Vec3d(p2_ - p0_));
        area_ = 0.5 * glm::length(c);
        n_ = Vec3f(glm::normalize(c));
    }

    std::optional<LightSample> sample(const Vec3f& ref, const Vec2f& u) const override {
        if (!(area_ > 0)) return std::nullopt;
        const Vec2f b = squareToUniformTriangle(u);
        const Vec3f p = b.x * p0_ + b.y * p1_ + (1.0f - b.x - b.y) * p2_;
        const Vec3f d = p - ref;
        const float dist = glm::length(d);
        if (!(dist > 0.0f)) return std::nullopt;
        const Vec3f wi = d / dist;
        const float cosLight = glm::dot(n_, -wi);
        if (!twoSided_ && !(cosLight > 0.0f)) return std::nullopt;
        const float pdf = areaToSolidAngle(float(1.0 / area_), ref, p, n_);
        if (!(pdf > 0.0f) || !std::isfinite(pdf)) return std::nullopt;
        return LightSample{wi, dist, {&color_, 1.0f}, pdf, false, p, cosLight > 0 ? n_ : -n_};
    }

    float pdf(const Vec3f& ref, const SurfaceHit& hit) const override {
        return areaToSolidAngle(float(1.0 / area_), ref, hit.p, hit.ng);
    }

  private:
    AreaPoint samplePoint(const Vec2f& u) const override {
        const Vec2f b = squareToUniformTriangle(u);
        return {b.x * p0_ + b.y * p1_ + (1.0f - b.x - b.y) * p2_, n_};
    }

    Vec3f p0_, p1_, p2_, n_;
};

/// An emitting rectangle, sampled uniformly in the solid angle it subtends (Urena, Fajardo
/// and King 2013, "An Area-Preserving Parametrization for Spherical Rectangles", EGSR; the
/// algorithm of their section 4, in double precision), or by area when the solid angle is
/// too small for that to be accurate (below 1e-4 sr the spherical quantities cancel).
class RectangleLight final : public AreaLight {
  public:
    explicit RectangleLight(const MeshDesc& mesh) : AreaLight(*mesh.emission, 0.0) {
        corner_ = Vec3d(mesh.positions[0]);
        const Vec3d ex = Vec3d(mesh.positions[1]) - corner_,
                    ey = Vec3d(mesh.positions[3]) - corner_;
        lx_ = glm::length(ex);
        ly_ = glm::length(ey);
        x_ = ex / lx_;
        y_ = ey / ly_;
        n_ = glm::normalize(glm::cross(ex, ey));
        // The winding of (0, 1, 2) gives the front side, as for the triangles.
        const Vec3d winding =
            glm::cross(Vec3d(mesh.positions[1]) - corner_, Vec3d(mesh.positions[2]) - corner_);
        if (glm::dot(winding, n_) < 0) n_ = -n_;
        area_ = lx_ * ly_;
    }

    static bool isRectangle(const MeshDesc& m) {
        if (!m.isRectangle || m.positions.size() != 4) return false;
        const Vec3d ex = Vec3d(m.positions[1] - m.positions[0]),
                    ey = Vec3d(m.positions[3] - m.positions[0]);
        return std::abs(glm::dot(ex, ey)) <= 1e-6 * glm::length(ex) * glm::length(ey);
    }

    std::optional<LightSample> sample(const Vec3f& refF, const Vec2f& u) const override {
        const Vec3d ref(refF);
        Vec3d p;
        double pdf;
        const Spherical sph = spherical(ref);
        if (sph.solidAngle > kMinSolidAngle) {
            // Section 4 of the paper: invert the area of the sub-rectangle left of x_u, then
            // the height along y at that x.
            const double au = double(u.x) * sph.solidAngle + sph.k;
            const double fu = (std::cos(au) * sph.b0 - sph.b1) / std::sin(au);
            double cu = (fu > 0 ? 1.0 : -1.0) / std::sqrt(fu * fu + sph.b0 * sph.b0);
            cu = std::clamp(cu, -1.0, 1.0);
            double xu = -(cu * sph.z0) / std::sqrt(std::max(1e-300, 1.0 - cu * cu));
            xu = std::clamp(xu, sph.x0, sph.x1);
            const double dd = std::sqrt(xu * xu + sph.z0 * sph.z0);
            const double h0 = sph.y0 / std::sqrt(dd * dd + sph.y0 * sph.y0);
            const double h1 = sph.y1 / std::sqrt(dd * dd + sph.y1 * sph.y1);
            const double hv = h0 + double(u.y) * (h1 - h0), hv2 = hv * hv;
            const double yv = hv2 < 1.0 - 1e-12 ? hv * dd / std::sqrt(1.0 - hv2) : sph.y1;
            p = ref + xu * sph.x + yv * sph.y + sph.z0 * sph.z;
            pdf = 1.0 / sph.solidAngle;
        } else {
            p = corner_ + double(u.x) * lx_ * x_ + double(u.y) * ly_ * y_;
            const Vec3d d = p - ref;
            const double dist2 = glm::dot(d, d);
            const double cosL = std::abs(glm::dot(n_, d)) / std::sqrt(dist2);
            if (!(cosL > 0)) return std::nullopt;
            pdf = dist2 / (cosL * area_);
        }
        const Vec3d d = p - ref;
        const double dist = glm::length(d);
        if (!(dist > 0) || !(pdf > 0) || !std::isfinite(pdf)) return std::nullopt;
        const Vec3f wi = Vec3f(d / dist);
        const bool front = glm::dot(n_, -d) > 0;
        if (!front && !twoSided_) return std::nullopt;
        return LightSample{wi,    float(dist), {&color_, 1.0f},        float(pdf),
                           false, Vec3f(p),    Vec3f(front ? n_ : -n_)};
    }

    float pdf(const Vec3f& refF, const SurfaceHit& hit) const override {
        const Spherical sph = spherical(Vec3d(refF));
        if (sph.solidAngle > kMinSolidAngle) return float(1.0 / sph.solidAngle);
        return areaToSolidAngle(float(1.0 / area_), refF, hit.p, hit.ng);
    }

  private:
    AreaPoint samplePoint(const Vec2f& u) const override {
        return {Vec3f(corner_ + double(u.x) * lx_ * x_ + double(u.y) * ly_ * y_), Vec3f(n_)};
    }

    static constexpr double kMinSolidAngle = 1e-4;

    // The rectangle seen from `ref`, in the local frame of the paper (z towards the plane).
    struct Spherical {
        Vec3d x, y, z;
        double x0, x1, y0, y1, z0;
        double b0, b1, k, solidAngle = 0;
    };
    Spherical spherical(const Vec3d& ref) const {
        Spherical s;
        s.x = x_;
        s.y = y_;
        s.z = glm::cross(x_, y_);
        const Vec3d d = corner_ - ref;
        s.x0 = glm::dot(d, s.x);
        s.y0 = glm::dot(d, s.y);
        s.z0 = glm::dot(d, s.z);
        if (s.z0 > 0) {
            s.z0 = -s.z0;
            s.z = -s.z;
        }
        if (!(std::abs(s.z0) > 0)) return s;  // in the plane: nothing subtended
        s.x1 = s.x0 + lx_;
        s.y1 = s.y0 + ly_;
        const Vec3d v00(s.x0, s.y0, s.z0), v01(s.x0, s.y1, s.z0), v10(s.x1, s.y0, s.z0),
            v11(s.x1, s.y1, s.z0);
        const Vec3d n0 = glm::normalize(glm::cross(v00, v10));
        const Vec3d n1 = glm::normalize(glm::cross(v10, v11));
        const Vec3d n2 = glm::normalize(glm::cross(v11, v01));
        const Vec3d n3 = glm::normalize(glm::cross(v01, v00));
        const double g0 = std::acos(std::clamp(-glm::dot(n0, n1), -1.0, 1.0));
        const double g1 = std::acos(std::clamp(-glm::dot(n1, n2), -1.0, 1.0));
        const double g2 = std::acos(std::clamp(-glm::dot(n2, n3), -1.0, 1.0));
        const double g3 = std::acos(std::clamp(-glm::dot(n3, n0), -1.0, 1.0));
        s.b0 = n0.z;
        s.b1 = n2.z;
        s.k = 2 * kPi<double> - g2 - g3;
        s.solidAngle = g0 + g1 - s.k;
        if (!std::isfinite(s.solidAngle)) s.solidAngle = 0;
        return s;
    }

    Vec3d corner_, x_, y_, n_;
    double lx_ = 0, ly_ = 0;
};

/// An emitting disk, sampled uniformly by area (the concentric mapping).
class DiskLight final : public AreaLight {
  public:
    explicit DiskLight(const DiskDesc& d)
        : AreaLight(*d.emission, kPi<double> * d.radius * d.radius),
          disk_(d),
          frame_(Frame<double>::fromNormal(d.normal)) {}

    std::optional<LightSample> sample(const Vec3f& refF, const Vec2f& u) const override {
        const Vec2<double> q = squareToUniformDiskConcentric(Vec2<double>(u)) * disk_.radius;
        const Vec3<double> p = disk_.center + frame_.toWorld(Vec3<double>(q.x, q.y, 0.0));
        const Vec3<double> d = p - Vec3<double>(refF);
        const double dist = glm::length(d);
        if (!(dist > 0)) return std::nullopt;
        const double cosL = glm::dot(disk_.normal, -d) / dist;
        if (!twoSided_ && !(cosL > 0)) return std::nullopt;
        if (cosL == 0) return std::nullopt;
        const double pdf = dist * dist / (std::abs(cosL) * area_);
        if (!std::isfinite(pdf)) return std::nullopt;
        const Vec3f n = Vec3f(cosL > 0 ? disk_.normal : -disk_.normal);
        return LightSample{
            Vec3f(d / dist), float(dist), {&color_, 1.0f}, float(pdf), false, Vec3f(p), n};
    }
    float pdf(const Vec3f& ref, const SurfaceHit& hit) const override {
        return areaToSolidAngle(float(1.0 / area_), ref, hit.p, hit.ng);
    }

  private:
    AreaPoint samplePoint(const Vec2f& u) const override {
        const Vec2<double> q = squareToUniformDiskConcentric(Vec2<double>(u)) * disk_.radius;
        return {Vec3f(disk_.center + frame_.toWorld(Vec3<double>(q.x, q.y, 0.0))),
                Vec3f(disk_.normal)};
    }

    DiskDesc disk_;
    Frame<double> frame_;
};

/// An emitting sphere: sampled uniformly in the cone it subtends when seen from outside
/// (emitting outwards), uniformly by area otherwise.
class SphereLight final : public AreaLight {
  public:
    explicit SphereLight(const SphereDesc& s)
        : AreaLight(*s.emission, 4.0 * kPi<double> * s.radius * s.radius), sphere_(s) {}

    std::optional<LightSample> sample(const Vec3f& refF, const Vec2f& u) const override {
        const Vec3d ref(refF), c = sphere_.center;
        const double r = sphere_.radius;
        const double dc2 = glm::dot(ref - c, ref - c);
        Vec3d p;
        double pdf;
        if (useCone(dc2)) {
            const double dc = std::sqrt(dc2);
            const double sin2Max = r * r / dc2;
            const double cosMax = std::sqrt(std::max(0.0, 1.0 - sin2Max));
            const double oneMinusCos = sin2Max / (1.0 + cosMax);  // stable for small cones
            // Uniform in the cone: 1 - cos(theta) uniform in [0, 1 - cos(theta_max)].
            const double omc = double(u.x) * oneMinusCos;
            const double cosT = 1.0 - omc;
            const double sinT = std::sqrt(std::max(0.0, omc * (2.0 - omc)));
            const double phi = 2.0 * kPi<double> * double(u.y);
            const Frame<double> frame = Frame<double>::fromNormal((c - ref) / dc);
            const Vec3d dir =
                frame.toWorld(Vec3d(sinT * std::cos(phi), sinT * std::sin(phi), cosT));
            // The nearer intersection of the ray with the sphere (tangent: the closest point).
            const double b = glm::dot(dir, c - ref);
            const double disc = std::max(0.0, r * r - (dc2 - b * b));
            const double t = b - std::sqrt(disc);
            p = ref + t * dir;
            pdf = 1.0 / (2.0 * kPi<double> * oneMinusCos);
        } else {
            const Vec3d n = Vec3d(squareToUniformSphere(Vec2<double>(u)));
            p = c + r * n;
            const Vec3d d = p - ref;
            const double dist2 = glm::dot(d, d);
            const double cosL = std::abs(glm::dot(n, d)) / std::sqrt(dist2);
            if (!(cosL > 0.0)) return std::nullopt;
            pdf = dist2 / (cosL * area_);
        }
        Vec3d n = glm::normalize(p - c);
        if (sphere_.flipNormals) n = -n;
        const Vec3d d = p - ref;
        const double dist = glm::length(d);
        if (!(dist > 0.0) || !(pdf > 0.0) || !std::isfinite(pdf)) return std::nullopt;
        const Vec3f wi = Vec3f(d / dist);
        const bool front = glm::dot(Vec3f(n), -wi) > 0.0f;
        if (!front && !twoSided_) return std::nullopt;
        return LightSample{wi,
                           float(dist),
                           {&color_, 1.0f},
                           float(pdf),
                           false,
                           Vec3f(p),
                           front ? Vec3f(n) : -Vec3f(n)};
    }

    float pdf(const Vec3f& refF, const SurfaceHit& hit) const override {
        const Vec3d ref(refF), c = sphere_.center;
        const double r = sphere_.radius;
        const double dc2 = glm::dot(ref - c, ref - c);
        if (useCone(dc2)) {
            const double sin2Max = r * r / dc2;
            const double cosMax = std::sqrt(std::max(0.0, 1.0 - sin2Max));
            return float(1.0 / (2.0 * kPi<double> * sin2Max / (1.0 + cosMax)));
        }
        return areaToSolidAngle(float(1.0 / area_), refF, hit.p, hit.ng);
    }

  private:
    AreaPoint samplePoint(const Vec2f& u) const override {
        const Vec3d n = Vec3d(squareToUniformSphere(Vec2<double>(u)));
        return {Vec3f(sphere_.center + sphere_.radius * n), Vec3f(sphere_.flipNormals ? -n : n)};
    }

    // The cone is only valid for points outside; an inward-emitting sphere is seen from
    // inside, where its whole surface is visible.
    bool useCone(double dc2) const {
        return !sphere_.flipNormals && dc2 > sqr(sphere_.radius) * (1.0 + 1e-6);
    }

    SphereDesc sphere_;
};

class PointLight final : public Light {
  public:
    explicit PointLight(const LightDesc& d)
        : position_(Vec3f(d.position)), color_(d.intensity, d.spectrum) {}

    std::optional<LightSample> sample(const Vec3f& ref, const Vec2f&) const override {
        const Vec3f d = position_ - ref;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return std::nullopt;
        const float dist = std::sqrt(dist2);
        return LightSample{d / dist,  dist,     {&color_, 1.0f / dist2}, 1.0f, true,
                           position_, -d / dist};
    }
    float pdf(const Vec3f&, const SurfaceHit&) const override { return 0.0f; }
    Emission radiance(const SurfaceHit&, const Vec3f&) const override { return {}; }
    double power() const override { return 4.0 * kPi<double> * luminance(color_.rgbDouble()); }
    bool isDelta() const override { return true; }

    std::optional<EmissionSample> sampleEmission(const Vec2f&, const Vec2f& u) const override {
        EmissionSample e;
        e.point = position_;
        e.direction = e.normal = squareToUniformSphere(u);
        e.radiance = {&color_, 1.0f};
        e.pdfDirection = uniformSpherePdf<float>();
        e.deltaPosition = true;
        return e;
    }
    EmissionPdf emissionPdf(const Vec3f&, const Vec3f&, const Vec3f&) const override {
        return {1.0f, uniformSpherePdf<float>()};
    }

  private:
    Vec3f position_;
    EmitterColor color_;
};

/// A spot light (pbrt-v4's convention): intensity I inside a cone, with a smoothstep falloff
/// in cos(theta) between the falloff start and the cone's edge.
class SpotLight final : public Light {
  public:
    explicit SpotLight(const LightDesc& d)
        : position_(Vec3f(d.position)),
          axis_(Vec3f(d.direction)),
          color_(d.intensity, d.spectrum),
          cosEdge_(float(std::cos(radians(d.coneAngle)))),
          cosStart_(float(std::cos(radians(d.falloffStart)))) {}

    std::optional<LightSample> sample(const Vec3f& ref, const Vec2f&) const override {
        const Vec3f d = position_ - ref;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) return std::nullopt;
        const float dist = std::sqrt(dist2);
        const float falloff = this->falloff(glm::dot(-d / dist, axis_));
        if (!(falloff > 0.0f)) return std::nullopt;
        return LightSample{d / dist,  dist,     {&color_, falloff / dist2}, 1.0f, true,
                           position_, -d / dist};
    }
    float pdf(const Vec3f&, const SurfaceHit&) const override { return 0.0f; }
    Emission radiance(const SurfaceHit&, const Vec3f&) const override { return {}; }
    double power() const override {
        // Integral of the falloff over the sphere: full inside the start, half the smoothstep
        // band on average (pbrt-v4, SpotLight::Phi).
        return 2.0 * kPi<double> * luminance(color_.rgbDouble()) *
               ((1.0 - cosStart_) + (cosStart_ - cosEdge_) / 2.0);
    }
    bool isDelta() const override { return true; }

    // Directions uniform in the cone (the falloff is in the weight).
    std::optional<EmissionSample> sampleEmission(const Vec2f&, const Vec2f& u) const override {
        const Vec3f local = squareToUniformCone(u, cosEdge_);
        EmissionSample e;
        e.point = position_;
        e.direction = e.normal = Frame<float>::fromNormal(axis_).toWorld(local);
        const float f = falloff(local.z);
        if (!(f > 0.0f)) return std::nullopt;
        e.radiance = {&color_, f};
        e.pdfDirection = uniformConePdf(local, cosEdge_);
        e.deltaPosition = true;
        return e;
    }
    EmissionPdf emissionPdf(const Vec3f&, const Vec3f&, const Vec3f& direction) const override {
        const float c = glm::dot(direction, axis_);
        return {1.0f, c > cosEdge_ ? uniformConePdf(Vec3f(0, 0, c), cosEdge_) : 0.0f};
    }

  private:
    float falloff(float cosTheta) const {
        if (cosTheta >= cosStart_) return 1.0f;
        if (cosTheta <= cosEdge_) return 0.0f;
        const float t = (cosTheta - cosEdge_) / (cosStart_ - cosEdge_);
        return t * t * (3.0f - 2.0f * t);
    }

    Vec3f position_, axis_;
    EmitterColor color_;
    float cosEdge_, cosStart_;
};

class DirectionalLight final : public Light {
  public:
    DirectionalLight(const LightDesc& d, const Geometry& g)
        : direction_(Vec3f(d.direction)),
          color_(d.intensity, d.spectrum),
          radius_(g.boundsRadius()),
          disk_{g.boundsCenter(), g.boundsRadius()} {}

    std::optional<LightSample> sample(const Vec3f&, const Vec2f&) const override {
        return LightSample{-direction_,
                           std::numeric_limits<float>::infinity(),
                           {&color_, 1.0f},
                           1.0f,
                           true,
                           Vec3f(0.0f),
                           direction_};
    }
    float pdf(const Vec3f&, const SurfaceHit&) const override { return 0.0f; }
    Emission radiance(const SurfaceHit&, const Vec3f&) const override { return {}; }
    double power() const override {
        return kPi<double> * sqr(double(radius_)) * luminance(color_.rgbDouble());
    }
    bool isDelta() const override { return true; }
    bool isInfinite() const override { return true; }

    std::optional<EmissionSample> sampleEmission(const Vec2f& u, const Vec2f&) const override {
        EmissionSample e;
        e.point = disk_.pointFacing(direction_, u);
        e.direction = e.normal = direction_;
        e.radiance = {&color_, 1.0f};
        e.pdfPosition = disk_.pdf();
        e.deltaDirection = true;
        return e;
    }
    EmissionPdf emissionPdf(const Vec3f&, const Vec3f&, const Vec3f&) const override {
        return {disk_.pdf(), 1.0f};
    }

  private:
    Vec3f direction_;
    EmitterColor color_;
    float radius_;
    SceneDisk disk_;
};

/// A constant environment: radiance L from every direction, sampled uniformly on the sphere.
class ConstantEnvironment final : public Light {
  public:
    ConstantEnvironment(const LightDesc& d, const Geometry& g)
        : color_(d.intensity, d.spectrum),
          radius_(g.boundsRadius()),
          disk_{g.boundsCenter(), g.boundsRadius()} {}

    std::optional<LightSample> sample(const Vec3f&, const Vec2f& u) const override {
        const Vec3f wi = squareToUniformSphere(u);
        return LightSample{wi,
                           std::numeric_limits<float>::infinity(),
                           {&color_, 1.0f},
                           uniformSpherePdf<float>(),
                           false,
                           Vec3f(0.0f),
                           -wi};
    }
    float pdf(const Vec3f&, const SurfaceHit&) const override { return 0.0f; }
    Emission radiance(const SurfaceHit&, const Vec3f&) const override { return {}; }
    double power() const override {
        // The flux through the scene's bounding disk from all directions (pbrt-v4's measure).
        return 4.0 * kPi<double> * kPi<double> * sqr(double(radius_)) *
               luminance(color_.rgbDouble());
    }
    bool isInfinite() const override { return true; }
    Emission environment(const Vec3f&) const override { return {&color_, 1.0f}; }
    float environmentPdf(const Vec3f&) const override { return uniformSpherePdf<float>(); }

    std::optional<EmissionSample> sampleEmission(const Vec2f& uPosition,
                                                 const Vec2f& uDirection) const override {
        const Vec3f toward = -squareToUniformSphere(uDirection);
        EmissionSample e;
        e.point = disk_.pointFacing(toward, uPosition);
        e.direction = e.normal = toward;
        e.radiance = {&color_, 1.0f};
        e.pdfPosition = disk_.pdf();
        e.pdfDirection = uniformSpherePdf<float>();
        return e;
    }
    EmissionPdf emissionPdf(const Vec3f&, const Vec3f&, const Vec3f&) const override {
        return {disk_.pdf(), uniformSpherePdf<float>()};
    }

  private:
    EmitterColor color_;
    float radius_;
    SceneDisk disk_;
};

/// An image around the scene (environment_map.h), importance-sampled.
class ImageEnvironment final : public Light {
  public:
    ImageEnvironment(const LightDesc& d, const Geometry& g)
        : map_(d.file, d.rotation),
          scale_(float(d.intensity[0])),
          radius_(g.boundsRadius()),
          disk_{g.boundsCenter(), g.boundsRadius()} {}

    std::optional<LightSample> sample(const Vec3f&, const Vec2f& u) const override {
        float pdf;
        const Vec3f wi = map_.sample(u, pdf);
        if (!(pdf > 0.0f)) return std::nullopt;
        return LightSample{
            wi, std::numeric_limits<float>::infinity(), environment(wi), pdf, false, Vec3f(0.0f),
            -wi};
    }
    float pdf(const Vec3f&, const SurfaceHit&) const override { return 0.0f; }
    Emission radiance(const SurfaceHit&, const Vec3f&) const override { return {}; }
    double power() const override {
        return 4.0 * kPi<double> * kPi<double> * sqr(double(radius_)) * scale_ *
               map_.averageLuminance();
    }
    bool isInfinite() const override { return true; }
    Emission environment(const Vec3f& w) const override {
        return Emission{nullptr, scale_, map_.lookup(w)};
    }
    float environmentPdf(const Vec3f& w) const override { return map_.pdf(w); }

    std::optional<EmissionSample> sampleEmission(const Vec2f& uPosition,
                                                 const Vec2f& uDirection) const override {
        float pdf;
        const Vec3f w = map_.sample(uDirection, pdf);
        if (!(pdf > 0.0f)) return std::nullopt;
        EmissionSample e;
        e.point = disk_.pointFacing(-w, uPosition);
        e.direction = e.normal = -w;
        e.radiance = environment(w);
        e.pdfPosition = disk_.pdf();
        e.pdfDirection = pdf;
        return e;
    }
    EmissionPdf emissionPdf(const Vec3f&, const Vec3f&, const Vec3f& direction) const override {
        return {disk_.pdf(), map_.pdf(-direction)};
    }

  private:
    EnvironmentMap map_;
    float scale_;
    float radius_;
    SceneDisk disk_;
};

}  // namespace

LightSet::LightSet(const SceneDesc& scene, Geometry& geometry, bool uniformSelection)
    : geometry_(geometry) {
    const auto& shapes = geometry.shapes();
    for (std::size_t s = 0; s < shapes.size(); ++s) {
        const ShapeInfo& info = shapes[s];
        if (info.kind == ShapeInfo::Kind::Mesh) {
            const MeshDesc& m = scene.meshes[std::size_t(info.index)];
            if (!m.emission || (m.emission->radiance.maxValue() <= 0.0 && !m.emission->spectrum))
                continue;
            if (RectangleLight::isRectangle(m)) {
                geometry.setFirstLight(int(s), int(lights_.size()), false);
                lights_.push_back(std::make_unique<RectangleLight>(m));
                continue;
            }
            geometry.setFirstLight(int(s), int(lights_.size()));
            for (std::size_t t = 0; t < m.triangles.size(); ++t)
                lights_.push_back(std::make_unique<TriangleLight>(m, t));
        } else if (info.kind == ShapeInfo::Kind::Disk) {
            const DiskDesc& dk = scene.disks[std::size_t(info.index)];
            if (!dk.emission || (dk.emission->radiance.maxValue() <= 0.0 && !dk.emission->spectrum))
                continue;
            geometry.setFirstLight(int(s), int(lights_.size()), false);
            lights_.push_back(std::make_unique<DiskLight>(dk));
        } else {
            const SphereDesc& sp = scene.spheres[std::size_t(info.index)];
            if (!sp.emission || (sp.emission->radiance.maxValue() <= 0.0 && !sp.emission->spectrum))
                continue;
            geometry.setFirstLight(int(s), int(lights_.size()));
            lights_.push_back(std::make_unique<SphereLight>(sp));
        }
    }
    for (const LightDesc& d : scene.lights) {
        if (d.intensity.maxValue() <= 0.0 && !d.spectrum) continue;
        switch (d.kind) {
            case LightKind::Point:
                lights_.push_back(std::make_unique<PointLight>(d));
                break;
            case LightKind::Spot:
                lights_.push_back(std::make_unique<SpotLight>(d));
                break;
            case LightKind::Directional:
                lights_.push_back(std::make_unique<DirectionalLight>(d, geometry));
                break;
            case LightKind::Environment:
                infinite_.push_back(lights_.size());
                if (d.file.empty())
                    lights_.push_back(std::make_unique<ConstantEnvironment>(d, geometry));
                else
                    lights_.push_back(std::make_unique<ImageEnvironment>(d, geometry));
                break;
        }
        if (d.kind == LightKind::Directional) infinite_.push_back(lights_.size() - 1);
    }
    // Selection proportional to power (or uniform); a light of zero luminance but non-zero
    // colour (pure blue, say) still gets a share so it is never starved.
    double total = 0;
    std::vector<double> w(lights_.size());
    for (std::size_t i = 0; i < lights_.size(); ++i) {
        w[i] = uniformSelection ? 1.0 : std::max(lights_[i]->power(), 0.0);
        total += w[i];
    }
    pmf_.resize(lights_.size());
    cdf_.resize(lights_.size());
    double running = 0;
    for (std::size_t i = 0; i < lights_.size(); ++i) {
        const double p = total > 0 ? 0.99 * w[i] / total + 0.01 / double(lights_.size())
                                   : 1.0 / double(lights_.size());
        pmf_[i] = float(p);
        running += p;
        cdf_[i] = float(running);
    }
    if (!cdf_.empty()) cdf_.back() = 1.0f;
}

std::pair<std::size_t, float> LightSet::choose(float u) const {
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u);
    const std::size_t i = std::min(std::size_t(it - cdf_.begin()), cdf_.size() - 1);
    return {i, pmf_[i]};
}

int LightSet::lightAt(const SurfaceHit& hit) const {
    const ShapeInfo& info = geometry_.shapes()[std::size_t(hit.shape)];
    if (info.firstLight < 0) return -1;
    return info.firstLight +
           (info.kind == ShapeInfo::Kind::Mesh && info.lightPerPrimitive ? int(hit.primitive) : 0);
}

}  // namespace lamina::render
