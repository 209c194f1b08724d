#include "lamina/spectral/cie.h"

#include "lamina/spectral/cie_tables.h"
#include "lamina/spectral/cie_xyz_table.h"

namespace lamina {

double cieX(double nm) {
    return cie_data::kCmfX(nm);
}
double cieY(double nm) {
    return cie_data::kCmfY(nm);
}
double cieZ(double nm) {
    return cie_data::kCmfZ(nm);
}

Vec3d cieXyz(double nm) {
    // The three functions come from one table of colord-data (generate_cie_tables.cpp), so
    // they share start, step and length: one position serves all three.
    const std::optional<TabulatedCurve::Position> p = cie_data::kCmfY.locate(nm);
    if (!p) return Vec3d(0.0);
    return {cie_data::kCmfX.at(*p), cie_data::kCmfY.at(*p), cie_data::kCmfZ.at(*p)};
}

double cieYIntegral() {
    static const double integral = integrateAgainstCmf([](double) { return 1.0; }).y;
    return integral;
}

CieXyzTable::CieXyzTable(ResampledSpectrum xBar, ResampledSpectrum yBar, ResampledSpectrum zBar)
    : x(xBar), y(yBar), z(zBar) {
    for (int i = 0; i < ResampledSpectrum::kSamples; ++i)
        rows[std::size_t(i)] = {x.value(i), y.value(i), z.value(i), 0.0f};
}

const CieXyzTable& CieXyzTable::normalized() {
    static const CieXyzTable table = [] {
        const double inverse = 1.0 / cieYIntegral();
        return CieXyzTable{ResampledSpectrum([&](double nm) { return cieX(nm) * inverse; }),
                           ResampledSpectrum([&](double nm) { return cieY(nm) * inverse; }),
                           ResampledSpectrum([&](double nm) { return cieZ(nm) * inverse; })};
    }();
    return table;
}

const TabulatedCurve* findCieIlluminant(std::string_view name) {
    for (const NamedCurve& c : cie_data::kIlluminantList)
        if (c.name == name) return &c.curve;
    return nullptr;
}

std::vector<std::string> cieIlluminantNames() {
    std::vector<std::string> names;
    for (const NamedCurve& c : cie_data::kIlluminantList)
        names.emplace_back(c.name);
    return names;
}

}  // namespace lamina
