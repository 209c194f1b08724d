#include "lamina/spectral/cie.h"

#include "lamina/spectral/cie_tables.h"

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

double cieYIntegral() {
    static const double integral = integrateAgainstCmf([](double) { return 1.0; }).y;
    return integral;
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
