// A function of wavelength given at equally spaced samples, interpolated linearly between
// them and zero outside the tabulated range.
#pragma once

#include <cmath>
#include <optional>
#include <span>
#include <string_view>

namespace lamina {

struct TabulatedCurve {
    double startNm = 0.0;  ///< wavelength of values[0]
    double stepNm = 1.0;   ///< spacing of the samples
    std::span<const double> values;

    double endNm() const { return startNm + stepNm * static_cast<double>(values.size() - 1); }

    /// Where a wavelength falls among the samples: between values[i] and values[i + 1], at
    /// fraction t of the way (t = 0 at the last sample).
    struct Position {
        std::size_t i;
        double t;
    };

    /// The position of `nm`, or none outside [start, end]. Curves on the same grid share it
    /// (the CIE colour matching functions: cieXyz).
    std::optional<Position> locate(double nm) const {
        const double x = (nm - startNm) / stepNm;
        if (!(x >= 0.0) || x > static_cast<double>(values.size() - 1)) return std::nullopt;
        const auto i = static_cast<std::size_t>(x);
        return Position{i, x - static_cast<double>(i)};
    }

    /// Linear interpolation between the two samples around `p`.
    double at(const Position& p) const {
        if (p.i + 1 >= values.size()) return values.back();
        return (1.0 - p.t) * values[p.i] + p.t * values[p.i + 1];
    }

    /// Linear interpolation between the two neighbouring samples; 0 outside [start, end].
    double operator()(double nm) const {
        const std::optional<Position> p = locate(nm);
        return p ? at(*p) : 0.0;
    }
};

struct NamedCurve {
    std::string_view name;
    TabulatedCurve curve;
};

}  // namespace lamina
