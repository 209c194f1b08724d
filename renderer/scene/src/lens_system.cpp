#include "lamina/scene/lens_system.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "lamina/core/error.h"

namespace lamina::render {

namespace {

constexpr int kPupilRings = 32;
constexpr int kPupilTrials = 16384;

struct SurfaceHit {
    glm::dvec3 point, normal;  ///< the normal faces the incoming ray
};

// The interface's sphere (vertex on the axis at zVertex, centre at zVertex - radius: a positive
// radius curves towards the film) met on the vertex's side of its centre.
std::optional<SurfaceHit> hitSphere(const LensRay& r, double zVertex, double radius) {
    const glm::dvec3 centre(0, 0, zVertex - radius);
    const glm::dvec3 oc = r.origin - centre;
    const double b = glm::dot(oc, r.direction);
    const double disc = b * b - (glm::dot(oc, oc) - radius * radius);
    if (!(disc >= 0)) return std::nullopt;
    const double s = std::sqrt(disc);
    for (const double t : {-b - s, -b + s}) {
        if (!(t > 0)) continue;
        const glm::dvec3 p = r.origin + t * r.direction;
        if ((p.z - centre.z) * radius <= 0) continue;
        glm::dvec3 n = (p - centre) / std::abs(radius);
        if (glm::dot(n, r.direction) > 0) n = -n;
        return SurfaceHit{p, n};
    }
    return std::nullopt;
}

// Where `r` meets interface `e` (its vertex on the axis at z), inside its aperture: the point
// and the normal there (zero on the aperture stop, a plane that only clips). nullopt: the ray
// misses it or is stopped.
std::optional<SurfaceHit> crossInterface(const LensInterface& e, const LensRay& r, double z) {
    SurfaceHit hit{glm::dvec3(0.0), glm::dvec3(0.0)};
    if (e.isStop()) {
        const double t = (z - r.origin.z) / r.direction.z;
        if (!(t > 0)) return std::nullopt;
        hit.point = r.origin + t * r.direction;
    } else {
        const auto sphere = hitSphere(r, z, e.curvatureRadius);
        if (!sphere) return std::nullopt;
        hit = *sphere;
    }
    const glm::dvec3& p = hit.point;
    if (p.x * p.x + p.y * p.y > e.apertureRadius * e.apertureRadius) return std::nullopt;
    return hit;
}

// Snell's law for unit `d` through a surface of normal `n` (facing against d), eta the ratio
// of the indices on the incident and transmitted sides; nullopt: total internal reflection.
std::optional<glm::dvec3> refract(const glm::dvec3& d, const glm::dvec3& n, double eta) {
    const double cosI = -glm::dot(n, d);
    const double sin2T = eta * eta * std::max(0.0, 1 - cosI * cosI);
    if (sin2T >= 1) return std::nullopt;
    const double cosT = std::sqrt(1 - sin2T);
    return glm::normalize(eta * d + (eta * cosI - cosT) * n);
}

// The radical inverse of i in `base` (Halton 1960): the trial points of the exit pupil.
double radicalInverse(int base, int i) {
    double inverse = 0, digit = 1.0 / base;
    for (int k = i; k > 0; k /= base, digit /= base)
        inverse += digit * (k % base);
    return inverse;
}

}  // namespace

LensSystem::LensSystem(std::vector<LensInterface> interfaces, double apertureDiameter,
                       double focusDistance, double filmDiagonal, bool* clamped)
    : interfaces_(std::move(interfaces)), filmDiagonal_(filmDiagonal) {
    if (clamped) *clamped = false;
    for (LensInterface& e : interfaces_)
        if (e.isStop() && apertureDiameter > 0) {
            if (apertureDiameter / 2 > e.apertureRadius) {
                if (clamped) *clamped = true;
            } else {
                e.apertureRadius = apertureDiameter / 2;
            }
        }
    focus(focusDistance);
    const double ringWidth = filmDiagonal_ / 2 / kPupilRings;
    bool any = false;
    for (int k = 0; k < kPupilRings; ++k) {
        pupil_.push_back(boundExitPupil(k * ringWidth, (k + 1) * ringWidth));
        any = any || !pupil_.back().empty();
    }
    if (!any) throw InputError("no ray from the film passes the lens system");
}

std::optional<LensRay> LensSystem::traceFromFilm(LensRay r) const {
    double z = 0;
    for (int i = int(interfaces_.size()) - 1; i >= 0; --i) {
        const LensInterface& e = interfaces_[std::size_t(i)];
        z += e.thickness;
        const auto hit = crossInterface(e, r, z);
        if (!hit) return std::nullopt;
        r.origin = hit->point;
        if (e.isStop()) continue;
        // From the medium behind the interface into the one in front of it.
        const double etaFront = i > 0 ? interfaces_[std::size_t(i) - 1].eta : 1.0;
        const auto d = refract(r.direction, hit->normal, e.eta / etaFront);
        if (!d) return std::nullopt;
        r.direction = *d;
    }
    return r;
}

std::optional<LensRay> LensSystem::traceFromScene(LensRay r) const {
    double z = frontZ_;
    for (std::size_t i = 0; i < interfaces_.size(); ++i) {
        const LensInterface& e = interfaces_[i];
        const auto hit = crossInterface(e, r, z);
        if (!hit) return std::nullopt;
        r.origin = hit->point;
        z -= e.thickness;
        if (e.isStop()) continue;
        const double etaFront = i > 0 ? interfaces_[i - 1].eta : 1.0;
        const auto d = refract(r.direction, hit->normal, etaFront / e.eta);
        if (!d) return std::nullopt;
        r.direction = *d;
    }
    return r;
}

std::optional<double> LensSystem::imageZ(double distance) const {
    if (!(distance > frontZ_)) return std::nullopt;
    // A paraxial ray: a thousandth of the narrowest aperture off the axis at the front.
    double narrowest = interfaces_.front().apertureRadius;
    for (const LensInterface& e : interfaces_)
        narrowest = std::min(narrowest, e.apertureRadius);
    const glm::dvec3 from(0, 0, distance), to(1e-3 * narrowest, 0, frontZ_);
    const auto out = traceFromScene({from, glm::normalize(to - from)});
    if (!out || !(out->direction.x != 0)) return std::nullopt;
    const double t = -out->origin.x / out->direction.x;
    if (!(t > 0)) return std::nullopt;  // diverging: no real image
    return out->origin.z + t * out->direction.z;
}

void LensSystem::focus(double focusDistance) {
    double length = 0;  // from the front vertex to the rear one
    for (std::size_t i = 0; i + 1 < interfaces_.size(); ++i)
        length += interfaces_[i].thickness;
    // Move the lens until the image of the axis point lands on the film: each step shifts it
    // by the image's distance from the film (the image moves with the lens, less the
    // longitudinal magnification squared, which is small for a distant plane).
    double b = std::max(interfaces_.back().thickness, 1e-6);
    for (int step = 0; step < 200; ++step) {
        interfaces_.back().thickness = b;
        frontZ_ = b + length;
        const auto z = imageZ(focusDistance);
        if (!z) break;
        if (std::abs(*z) <= 1e-12 * std::max(1.0, b)) return;
        b -= *z;
        if (!(b > 0 && b < 1e5)) break;
    }
    throw InputError(
        "the lens system cannot focus at this distance (too near, or no real "
        "image: the plane in focus must be beyond twice the focal length)");
}

LensSystem::Bounds LensSystem::boundExitPupil(double r0, double r1) const {
    const double rear = 1.5 * interfaces_.back().apertureRadius;
    const double b = filmDistance();
    Bounds bounds;
    for (int i = 0; i < kPupilTrials; ++i) {
        const glm::dvec3 film(r0 + (i + 0.5) / kPupilTrials * (r1 - r0), 0, 0);
        const glm::dvec3 p((2 * radicalInverse(2, i) - 1) * rear,
                           (2 * radicalInverse(3, i) - 1) * rear, b);
        if (p.x >= bounds.lo.x && p.x <= bounds.hi.x && p.y >= bounds.lo.y && p.y <= bounds.hi.y)
            continue;
        if (!traceFromFilm({film, glm::normalize(p - film)})) continue;
        bounds.lo = glm::min(bounds.lo, glm::dvec2(p));
        bounds.hi = glm::max(bounds.hi, glm::dvec2(p));
    }
    if (bounds.empty()) return bounds;
    // Grown by twice the trials' spacing, so that the pupil's edge between them is kept.
    const double spacing = 2 * rear * std::sqrt(2.0) / std::sqrt(double(kPupilTrials));
    bounds.lo -= glm::dvec2(2 * spacing);
    bounds.hi += glm::dvec2(2 * spacing);
    return bounds;
}

std::optional<PupilSample> LensSystem::sampleExitPupil(const glm::dvec2& film,
                                                       const glm::dvec2& u) const {
    const double r = glm::length(film);
    const int ring = std::min(kPupilRings - 1, int(r / (filmDiagonal_ / 2) * kPupilRings));
    const Bounds& bounds = pupil_[std::size_t(ring)];
    if (bounds.empty()) return std::nullopt;
    const glm::dvec2 p = bounds.lo + u * (bounds.hi - bounds.lo);
    const double area = (bounds.hi.x - bounds.lo.x) * (bounds.hi.y - bounds.lo.y);
    // The rings were bounded along +x: turned to the film point's angle.
    const double c = r > 0 ? film.x / r : 1, s = r > 0 ? film.y / r : 0;
    return PupilSample{{c * p.x - s * p.y, s * p.x + c * p.y, filmDistance()}, 1 / area};
}

}  // namespace lamina::render
