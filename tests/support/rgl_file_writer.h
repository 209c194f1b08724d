// Writes RGL material files (.bsdf tensor files, renderer/scene rgl_bsdf_file.h) for the tests:
// the container (any fields, so that tests can break one), and a whole measured file tabulated
// from one of lamina's own microfacet BSDFs in the parameterisation of Dupuy and Jakob 2018
// (measured_table.h), with the layout the RGL database's files have: theta_i, phi_i, ndf,
// sigma, vndf, luminance, rgb or spectra with wavelengths, description and jacobian.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "lamina/bsdf/bxdf.h"
#include "lamina/bsdf/measured_table.h"
#include "lamina/bsdf/microfacet_distribution.h"
#include "lamina/core/marginal_warp_2d.h"
#include "lamina/core/math.h"

namespace lamina::testing {

/// One field of a tensor file: its name, type code (1 uint8, 10 float32, ...), shape and bytes.
struct TensorField {
    std::string name;
    std::uint8_t type = 10;
    std::vector<std::uint64_t> shape;
    std::string data;

    static TensorField floats(std::string name, std::vector<std::uint64_t> shape,
                              const std::vector<float>& values) {
        TensorField f{std::move(name), 10, std::move(shape), {}};
        f.data.assign(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float));
        return f;
    }
    static TensorField bytes(std::string name, const std::string& text) {
        return {std::move(name), 1, {text.size()}, text};
    }
};

/// The bytes of a tensor file of version 1.0 holding `fields`, each field's data 8-byte
/// aligned after the header.
inline std::string tensorFileBytes(const std::vector<TensorField>& fields) {
    std::string header("tensor_file\0", 12);
    header += char(1);
    header += char(0);
    auto put = [](std::string& s, auto v) {
        s.append(reinterpret_cast<const char*>(&v), sizeof v);
    };
    put(header, std::uint32_t(fields.size()));
    std::size_t headerSize = header.size();
    for (const TensorField& f : fields)
        headerSize += 2 + f.name.size() + 2 + 1 + 8 + 8 * f.shape.size();
    std::uint64_t offset = (headerSize + 7) / 8 * 8;
    std::string data;
    for (const TensorField& f : fields) {
        put(header, std::uint16_t(f.name.size()));
        header += f.name;
        put(header, std::uint16_t(f.shape.size()));
        put(header, f.type);
        put(header, std::uint64_t(offset + data.size()));
        for (std::uint64_t s : f.shape)
            put(header, s);
        data += f.data;
        data.resize((data.size() + 7) / 8 * 8, '\0');
    }
    header.resize(std::size_t(offset), '\0');
    return header + data;
}

inline void writeTensorFile(const std::filesystem::path& path,
                            const std::vector<TensorField>& fields) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    const std::string bytes = tensorFileBytes(fields);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

struct RglTabulation {
    int thetaCount = 12;  ///< theta_i, from 0 to maxThetaDeg, evenly in u = sqrt(2 theta / pi)
    double maxThetaDeg = 85;
    int phiCount = 1;    ///< 1: isotropic; more: phi_i over the whole turn [-pi, pi]
    int ndfSize = 64;    ///< ndf and sigma: ndfSize x ndfSize
    int vndfSize = 48;   ///< vndf: vndfSize x vndfSize per direction
    int valueSize = 32;  ///< luminance and the values: valueSize x valueSize per direction
    /// Spectra at 450, 550 and 650 nm holding the BSDF's blue, green and red channels (else
    /// the rgb field).
    bool spectral = false;
};

/// The fields of an RGL file tabulating `bxdf`, a reflection whose microfacets follow `d`: the
/// NDF and its projected area sigma = cos theta (1 + Lambda) (Heitz 2014, "Understanding the
/// Masking-Shadowing Function", eq. 2 and 8), the visible-normal density in the unit square,
/// and the values fr = eval 4 sigma / D at the points whose visible-normal warp lands on the
/// value grid, with the interpolants of the written ndf and sigma (so that the reader gives
/// eval back exactly on the grid).
inline std::vector<TensorField> rglFields(const Bxdf<Rgb<double>>& bxdf,
                                          const MicrofacetDistribution<double>& d,
                                          const RglTabulation& t) {
    const double pi = kPi<double>;
    auto u2theta = [&](double u) { return u * u * pi / 2; };
    auto u2phi = [&](double u) { return (2 * u - 1) * pi; };
    auto theta2u = [&](double theta) { return std::sqrt(theta * 2 / pi); };
    auto phi2u = [&](double phi) { return (phi + pi) / (2 * pi); };
    auto dir = [](double theta, double phi) {
        return Vec3d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                     std::cos(theta));
    };
    const bool isotropic = t.phiCount == 1;
    std::vector<float> thetaI, phiI;
    for (int k = 0; k < t.thetaCount; ++k)
        thetaI.push_back(float(u2theta(theta2u(radians(t.maxThetaDeg)) * k / (t.thetaCount - 1))));
    for (int k = 0; k < t.phiCount; ++k)
        phiI.push_back(isotropic ? 0.0f : float(-pi + 2 * pi * k / (t.phiCount - 1)));

    const int n = t.ndfSize;
    std::vector<float> ndf, sigma;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double ux = double(x) / (n - 1), uy = double(y) / (n - 1);
            ndf.push_back(float(d.D(dir(u2theta(ux), u2phi(uy)))));
            // At the horizon cos theta (1 + Lambda) tends to a finite limit; stop just short.
            const Vec3d w = dir(std::min(u2theta(ux), radians(89.99)), u2phi(uy));
            sigma.push_back(float(w.z * (1 + d.lambda(w))));
        }
    const MarginalWarp2D ndfTable(n, n, {}, ndf, MarginalWarp2D::Kind::Values);
    const MarginalWarp2D sigmaTable(n, n, {}, sigma, MarginalWarp2D::Kind::Values);

    const int nv = t.vndfSize, nu = t.valueSize;
    std::vector<float> vndf;
    for (float phiO : phiI)
        for (float thetaO : thetaI) {
            const Vec3d wo = dir(thetaO, phiO);
            for (int y = 0; y < nv; ++y)
                for (int x = 0; x < nv; ++x) {
                    const double ux = double(x) / (nv - 1), uy = double(y) / (nv - 1);
                    const double thetaM = u2theta(ux);
                    const Vec3d m = dir(thetaM, u2phi(uy) + (isotropic ? phiO : 0.0));
                    vndf.push_back(float(d.D(m) * std::max(0.0, glm::dot(wo, m)) * 2 * pi * pi *
                                         ux * std::sin(thetaM)));
                }
        }
    const MarginalWarp2D vndfTable(nv, nv, {phiI, thetaI}, vndf, MarginalWarp2D::Kind::Density);

    std::vector<float> luminance, values;
    for (float phiO : phiI)
        for (float thetaO : thetaI) {
            const Vec3d wo = dir(thetaO, phiO);
            const double params[2] = {phiO, thetaO};
            std::vector<Rgb<double>> fr;
            for (int y = 0; y < nu; ++y)
                for (int x = 0; x < nu; ++x) {
                    const Vec2d ui(double(x) / (nu - 1), double(y) / (nu - 1));
                    const Vec2d uM = vndfTable.sample(ui, params).first;
                    const Vec3d m = dir(u2theta(uM.x), u2phi(uM.y) + (isotropic ? phiO : 0.0));
                    const Vec3d wi = reflect(wo, m);
                    const double scale =
                        ndfTable.eval(uM, {}) /
                        (4 * sigmaTable.eval(Vec2d(theta2u(thetaO), phi2u(phiO)), {}));
                    Rgb<double> v(0.0);
                    if (wi.z > 0 && scale > 0)
                        v = bxdf.eval(wo, wi, TransportMode::Radiance) / scale;
                    fr.push_back(v);
                    luminance.push_back(float(lamina::luminance(v)));
                }
            for (int c = 0; c < 3; ++c)
                for (const Rgb<double>& v : fr)
                    values.push_back(float(v[t.spectral ? 2 - c : c]));
        }

    const auto np = std::uint64_t(phiI.size()), nt = std::uint64_t(thetaI.size());
    std::vector<TensorField> f{
        TensorField::bytes("description", "lamina test: a microfacet BSDF tabulated"),
        TensorField::bytes("jacobian", std::string(1, '\1')),
        TensorField::floats("theta_i", {nt}, thetaI),
        TensorField::floats("phi_i", {np}, phiI),
        TensorField::floats("ndf", {std::uint64_t(n), std::uint64_t(n)}, ndf),
        TensorField::floats("sigma", {std::uint64_t(n), std::uint64_t(n)}, sigma),
        TensorField::floats("vndf", {np, nt, std::uint64_t(nv), std::uint64_t(nv)}, vndf),
        TensorField::floats("luminance", {np, nt, std::uint64_t(nu), std::uint64_t(nu)},
                            luminance)};
    const std::vector<std::uint64_t> valueShape{np, nt, 3, std::uint64_t(nu), std::uint64_t(nu)};
    if (t.spectral) {
        f.push_back(TensorField::floats("wavelengths", {3}, {450.0f, 550.0f, 650.0f}));
        f.push_back(TensorField::floats("spectra", valueShape, values));
    } else {
        f.push_back(TensorField::floats("rgb", valueShape, values));
    }
    return f;
}

/// The fields as the RGL file reader hands them to the table (renderer/scene rgl_bsdf_file.h),
/// for the tests that link the bsdf library alone.
inline MeasuredBsdfFields measuredFields(const std::vector<TensorField>& fields) {
    MeasuredBsdfFields out;
    for (const TensorField& f : fields) {
        if (f.type == 1) {
            if (f.name == "description") out.description = f.data;
            if (f.name == "jacobian") out.jacobian = f.data.at(0) != 0;
            continue;
        }
        MeasuredTensor t;
        t.shape.assign(f.shape.begin(), f.shape.end());
        t.values.resize(f.data.size() / sizeof(float));
        std::memcpy(t.values.data(), f.data.data(), t.values.size() * sizeof(float));
        if (f.name == "theta_i") out.thetaI = t;
        if (f.name == "phi_i") out.phiI = t;
        if (f.name == "ndf") out.ndf = t;
        if (f.name == "sigma") out.sigma = t;
        if (f.name == "vndf") out.vndf = t;
        if (f.name == "luminance") out.luminance = t;
        if (f.name == "spectra") out.spectra = t;
        if (f.name == "wavelengths") out.wavelengths = t;
        if (f.name == "rgb") out.rgb = t;
    }
    return out;
}

}  // namespace lamina::testing
