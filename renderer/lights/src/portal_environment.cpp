#include "lamina/lights/portal_environment.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lamina::render {

PortalMapping::PortalMapping(const std::array<Vec3<double>, 4>& c)
    : corner0_(c[0]), corner2_(c[2]), edgeX_(c[3] - c[0]), edgeY_(c[1] - c[0]) {
    // pbrt-v4's frame: x along c3 - c0, y along c1 - c0 (the scene reader has checked that
    // they are perpendicular), z = x cross y.
    x_ = glm::normalize(edgeX_);
    y_ = glm::normalize(edgeY_);
    z_ = glm::normalize(glm::cross(x_, y_));
    area_ = glm::length(edgeX_) * glm::length(edgeY_);
}

std::optional<Vec2d> PortalMapping::toUv(const Vec3d& w) const {
    const double x = glm::dot(w, x_), y = glm::dot(w, y_), z = glm::dot(w, z_);
    if (!(z > 0.0)) return std::nullopt;
    return Vec2d((std::atan2(x, z) + kPi<double> / 2) / kPi<double>,
                 (std::atan2(y, z) + kPi<double> / 2) / kPi<double>);
}

Vec3d PortalMapping::fromUv(const Vec2d& uv) const {
    const double a = std::tan((uv.x - 0.5) * kPi<double>), b = std::tan((uv.y - 0.5) * kPi<double>);
    return glm::normalize(a * x_ + b * y_ + z_);
}

double PortalMapping::jacobian(const Vec3d& w) const {
    const double x = glm::dot(w, x_), y = glm::dot(w, y_), z = glm::dot(w, z_);
    if (!(z > 0.0)) return 0.0;
    return kPi<double> * kPi<double> * (1 - x * x) * (1 - y * y) / z;
}

std::optional<UnitWindow> PortalMapping::windowFrom(const Vec3d& p) const {
    if (!(glm::dot(p - corner0_, z_) < 0.0)) return std::nullopt;
    const auto a = toUv(glm::normalize(corner0_ - p)), b = toUv(glm::normalize(corner2_ - p));
    if (!a || !b) return std::nullopt;
    return UnitWindow{glm::min(*a, *b), glm::max(*a, *b)};
}

Vec3d PortalMapping::pointAt(const Vec2d& st) const {
    return corner0_ + st.x * edgeX_ + st.y * edgeY_;
}

namespace {

bool inside(const Vec2d& uv, const UnitWindow& w) {
    return uv.x >= w.lo.x && uv.x <= w.hi.x && uv.y >= w.lo.y && uv.y <= w.hi.y;
}

}  // namespace

PortalEnvironment::PortalEnvironment(std::unique_ptr<EnvironmentLight> environment,
                                     const std::array<Vec3<double>, 4>& corners, const Geometry& g)
    : InfiniteLight(g), environment_(std::move(environment)), mapping_(corners) {
    // Each cell's weight: the luminance times d omega / d(u, v), averaged over 2 x 2 points of
    // the cell, plus a thousandth of the mean so that no direction the environment lights is
    // left to BSDF sampling alone. The flux through the rectangle integrates the same points
    // with cos theta.
    const int n =
        std::clamp(environment_->pixelsAroundTheHorizon(), kMinResolution, kMaxResolution);
    std::vector<double> weights(std::size_t(n) * n);
    double flux = 0, sum = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            double w = 0;
            for (int k = 0; k < 4; ++k) {
                const Vec2d uv((i + 0.25 + 0.5 * (k & 1)) / n, (j + 0.25 + 0.5 * (k >> 1)) / n);
                const Vec3d d = mapping_.fromUv(uv);
                const double jac = mapping_.jacobian(d);
                const double lum =
                    luminance(Rgb<double>(environment_->radianceTowards(Vec3f(d)).rgb()));
                w += std::max(lum, 0.0) * jac / 4;
                flux += std::max(lum, 0.0) * jac * glm::dot(d, mapping_.normal()) / 4;
            }
            weights[std::size_t(j) * n + std::size_t(i)] = w;
            sum += w;
        }
    const double floor = 1e-3 * sum / (double(n) * n);
    for (double& w : weights)
        w += floor;
    grid_ = WindowedDistribution2D(n, n, std::move(weights));
    power_ = mapping_.area() * flux / (double(n) * n);
}

Emission PortalEnvironment::environment(const Vec3f& origin, const Vec3f& w) const {
    const auto window = mapping_.windowFrom(Vec3d(origin));
    if (!window) return {};
    const auto uv = mapping_.toUv(Vec3d(w));
    if (!uv || !inside(*uv, *window)) return {};
    return environment_->radianceTowards(w);
}

float PortalEnvironment::environmentPdf(const Vec3f& origin, const Vec3f& w) const {
    const auto window = mapping_.windowFrom(Vec3d(origin));
    if (!window) return 0.0f;
    const Vec3d d(w);
    const auto uv = mapping_.toUv(d);
    if (!uv) return 0.0f;
    const double jac = mapping_.jacobian(d);
    return jac > 0 ? float(grid_.pdf(*uv, *window) / jac) : 0.0f;
}

std::optional<LightSample> PortalEnvironment::sample(const Vec3f& ref, const Vec2f& u) const {
    const auto window = mapping_.windowFrom(Vec3d(ref));
    if (!window) return std::nullopt;
    double pdfUv;
    const auto uv = grid_.sample(Vec2d(u), *window, pdfUv);
    if (!uv) return std::nullopt;
    const Vec3d d = mapping_.fromUv(*uv);
    const double jac = mapping_.jacobian(d);
    const float pdf = float(pdfUv / jac);
    if (!(jac > 0) || !(pdf > 0.0f) || !std::isfinite(pdf)) return std::nullopt;
    const Vec3f wi(d);
    return LightSample{wi,
                       std::numeric_limits<float>::infinity(),
                       environment_->radianceTowards(wi),
                       pdf,
                       false,
                       Vec3f(0.0f),
                       -wi};
}

std::optional<EmissionSample> PortalEnvironment::sampleEmission(const Vec2f& uPosition,
                                                                const Vec2f& uDirection) const {
    double pdfUv;
    const auto uv = grid_.sample(Vec2d(uDirection), UnitWindow{}, pdfUv);
    if (!uv) return std::nullopt;
    const Vec3d w = mapping_.fromUv(*uv);
    const double jac = mapping_.jacobian(w), cosTheta = glm::dot(w, mapping_.normal());
    if (!(jac > 0) || !(cosTheta > 0)) return std::nullopt;
    // Beyond the bounding sphere on the line through the rectangle's point.
    const Vec3d crossing = mapping_.pointAt(Vec2d(uPosition));
    const double far = 2.0 * disk_.radius + glm::length(crossing - Vec3d(disk_.center));
    EmissionSample e;
    e.point = Vec3f(crossing + far * w);
    e.direction = e.normal = Vec3f(-w);
    e.radiance = environment_->radianceTowards(Vec3f(w));
    e.pdfPosition = float(1.0 / (mapping_.area() * cosTheta));
    e.pdfDirection = float(pdfUv / jac);
    if (!std::isfinite(e.pdfPosition) || !(e.pdfDirection > 0.0f) || !std::isfinite(e.pdfDirection))
        return std::nullopt;
    return e;
}

EmissionPdf PortalEnvironment::emissionPdf(const Vec3f& point, const Vec3f&,
                                           const Vec3f& direction) const {
    const Vec3d w = -Vec3d(direction);
    const auto uv = mapping_.toUv(w);
    if (!uv) return {};
    const double jac = mapping_.jacobian(w);
    EmissionPdf e;
    e.direction = jac > 0 ? float(grid_.pdf(*uv, UnitWindow{}) / jac) : 0.0f;
    // The particle's line passes through `point` (the zero vector: only the direction asked
    // for); it came through the rectangle if the ray from there back towards the light does.
    const auto window = mapping_.windowFrom(Vec3d(point));
    if (window && inside(*uv, *window))
        e.position = float(1.0 / (mapping_.area() * glm::dot(w, mapping_.normal())));
    return e;
}

}  // namespace lamina::render
