#include "lamina/geometry/quadric.h"

#include <algorithm>
#include <cmath>

namespace lamina::render {

namespace {

constexpr double kTwoPi = 2 * kPi<double>;

// phi = atan2(y, x) in [0, 2 pi), turning from +x towards +y.
double azimuth(const Vec3d& p) {
    const double phi = std::atan2(p.y, p.x);
    return phi < 0 ? phi + kTwoPi : phi;
}

// `p` (in the frame) moved onto the surface along the normal: to the sphere's radius, the
// cylinder's radius about z, the disk's plane.
Vec3d project(const QuadricDesc& q, Vec3d p) {
    switch (q.kind) {
        case Quadric::Sphere: {
            const double length = glm::length(p);
            return length > 0 ? p * (q.radius / length) : Vec3d(0, 0, q.radius);
        }
        case Quadric::Cylinder: {
            const double rho = std::hypot(p.x, p.y);
            if (rho > 0) {
                p.x *= q.radius / rho;
                p.y *= q.radius / rho;
            }
            return p;
        }
        case Quadric::Disk:
            p.z = 0;
            return p;
    }
    return p;
}

// Whether a point on the surface lies within the clipping. The sphere is clipped in z only
// where z_min or z_max cut it (pbrt-v4's test: a pole's rounding never clips a whole sphere's
// end), and in phi only when phi_max < 2 pi.
bool inside(const QuadricDesc& q, const Vec3d& p) {
    switch (q.kind) {
        case Quadric::Sphere:
            if ((q.zMin > -q.radius && p.z < q.zMin) || (q.zMax < q.radius && p.z > q.zMax))
                return false;
            break;
        case Quadric::Cylinder:
            if (p.z < q.zMin || p.z > q.zMax) return false;
            break;
        case Quadric::Disk: {
            const double rho2 = p.x * p.x + p.y * p.y;
            if (rho2 > q.radius * q.radius || rho2 < q.innerRadius * q.innerRadius) return false;
            break;
        }
    }
    return q.phiMax >= kTwoPi || azimuth(p) <= q.phiMax;
}

// The roots t0 <= t1 of a t^2 + 2 h t + c = 0, whose discriminant h^2 - a c is a * disc;
// false without real roots. q = -(h + sign(h) sqrt(h^2 - a c)) avoids the cancellation of the
// textbook formula (Numerical Recipes 5.6): t0 = q / a, t1 = c / q.
bool solveQuadratic(double a, double h, double c, double disc, double& t0, double& t1) {
    if (!(a > 0) || !(disc >= 0)) return false;
    const double q = -(h + std::copysign(std::sqrt(a * disc), h));
    if (q == 0) {  // a ray tangent at its own origin
        t0 = t1 = 0;
        return true;
    }
    t0 = q / a;
    t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

}  // namespace

int intersectQuadric(const QuadricDesc& q, const Vec3d& oWorld, const Vec3d& dWorld, double tMin,
                     double tMax, QuadricHit hits[2]) {
    const Vec3d o = q.toLocal(oWorld), d = glm::transpose(q.axes) * dWorld;
    double t[2];
    int candidates = 0;
    const double r = q.radius;
    if (q.kind == Quadric::Disk) {
        if (d.z == 0) return 0;  // parallel to the plane
        t[0] = -o.z / d.z;
        candidates = 1;
    } else {
        // |o + t d|^2 = r^2 (in x and y only for the cylinder). Its discriminant is a (r^2 -
        // |f|^2) with f the ray's point closest to the centre (the axis): pbrt-v4's form, which
        // keeps its precision when |o| is large against r.
        const Vec3d dd = q.kind == Quadric::Sphere ? d : Vec3d(d.x, d.y, 0);
        const Vec3d oo = q.kind == Quadric::Sphere ? o : Vec3d(o.x, o.y, 0);
        const double a = glm::dot(dd, dd), h = glm::dot(oo, dd);
        if (!(a > 0)) return 0;  // along the cylinder's axis
        const double fLength = glm::length(oo - (h / a) * dd);
        if (!solveQuadratic(a, h, glm::dot(oo, oo) - r * r, (r - fLength) * (r + fLength), t[0],
                            t[1]))
            return 0;
        candidates = 2;
    }
    int n = 0;
    for (int i = 0; i < candidates; ++i) {
        if (!(t[i] > tMin && t[i] < tMax)) continue;
        const Vec3d p = project(q, o + t[i] * d);
        if (!inside(q, p)) continue;
        hits[n++] = {t[i], p};
    }
    return n;
}

Vec3d quadricNormal(const QuadricDesc& q, const Vec3d& local) {
    Vec3d n(0, 0, 1);
    if (q.kind == Quadric::Sphere) n = glm::normalize(local);
    if (q.kind == Quadric::Cylinder) n = glm::normalize(Vec3d(local.x, local.y, 0));
    return q.axes * (q.flipNormals ? -n : n);
}

QuadricSurface quadricSurface(const QuadricDesc& q, const Vec3d& near) {
    const Vec3d p = project(q, near);
    const double r = q.radius, phi = azimuth(p), rho = std::hypot(p.x, p.y);
    QuadricSurface s;
    s.uv.x = phi / q.phiMax;
    Vec3d n(0, 0, 1), dpdu(0.0), dpdv(0.0), dndu(0.0), dndv(0.0);
    // dp/du is the same for the three: p turns about z at phi_max per unit of u.
    if (rho > 0) dpdu = q.phiMax * Vec3d(-p.y, p.x, 0);
    switch (q.kind) {
        case Quadric::Sphere: {
            const double thetaZMin = std::acos(std::clamp(q.zMin / r, -1.0, 1.0));
            const double thetaZMax = std::acos(std::clamp(q.zMax / r, -1.0, 1.0));
            const double theta = std::acos(std::clamp(p.z / r, -1.0, 1.0));
            s.uv.y = (theta - thetaZMin) / (thetaZMax - thetaZMin);
            n = p / r;
            if (rho > 0)
                dpdv = (thetaZMax - thetaZMin) *
                       Vec3d(p.z * p.x / rho, p.z * p.y / rho, -r * (rho / r));
            dndu = dpdu / r;
            dndv = dpdv / r;
            break;
        }
        case Quadric::Cylinder:
            s.uv.y = (p.z - q.zMin) / (q.zMax - q.zMin);
            n = Vec3d(p.x, p.y, 0) / r;
            dpdv = Vec3d(0, 0, q.zMax - q.zMin);
            dndu = dpdu / r;
            break;
        case Quadric::Disk:
            s.uv.y = (r - rho) / (r - q.innerRadius);
            if (rho > 0) dpdv = Vec3d(p.x, p.y, 0) * ((q.innerRadius - r) / rho);
            break;
    }
    if (!(rho > 0)) dpdu = dpdv = dndu = dndv = Vec3d(0.0);  // u is undefined on the axis
    const double sign = q.flipNormals ? -1.0 : 1.0;
    s.p = q.toShapeSpace(p);
    s.n = q.axes * (sign * n);
    s.dpdu = q.axes * dpdu;
    s.dpdv = q.axes * dpdv;
    s.dndu = q.axes * (sign * dndu);
    s.dndv = q.axes * (sign * dndv);
    return s;
}

Vec3d sampleQuadric(const QuadricDesc& q, const Vec2<double>& u) {
    const double phi = u.y * q.phiMax;
    const double c = std::cos(phi), s = std::sin(phi), r = q.radius;
    switch (q.kind) {
        case Quadric::Sphere: {
            const double z = lerp(u.x, q.zMin, q.zMax);
            const double rho = std::sqrt(std::max(0.0, (r - z) * (r + z)));
            return {rho * c, rho * s, z};
        }
        case Quadric::Cylinder:
            return {r * c, r * s, lerp(u.x, q.zMin, q.zMax)};
        case Quadric::Disk: {
            const double ri = q.innerRadius;
            const double rho = std::sqrt(lerp(u.x, ri * ri, r * r));
            return {rho * c, rho * s, 0.0};
        }
    }
    return Vec3d(0.0);
}

}  // namespace lamina::render
