// A function of wavelength given at equally spaced samples, interpolated linearly between
// them and zero outside the tabulated range.
#pragma once

#include <cmath>
#include <span>
#include <string_view>

namespace lamina {

struct TabulatedCurve {
    double startNm = 0.0;  ///< wavelength of values[0]
    double stepNm = 1.0;   ///< spacing of the samples
    std::span<const double> values;

    double endNm() const { return startNm + stepNm * static_cast<double>(values.size() - 1); }

    /// Linear interpolation between the two neighbouring samples; 0 outside [start, end].
    double operator()(double nm) const {
        const double x = (nm - startNm) / stepNm;
        if (!(x >= 0.0) || x > static_cast<double>(values.size() - 1)) return 0.0;
        const auto i = static_cast<std::size_t>(x);
        if (i + 1 >= values.size()) return values.back();
        const double t = x - static_cast<double>(i);
        return (1.0 - t) * values[i] + t * values[i + 1];
    }
};

struct NamedCurve {
    std::string_view name;
    TabulatedCurve curve;
};

}  // namespace lamina
