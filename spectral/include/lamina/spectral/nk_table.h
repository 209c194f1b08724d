// A conductor's complex index n + i k tabulated at 1 nm over the rendered range [360, 830] nm
// and interpolated linearly. The Lorentz-Drude model (six complex oscillator terms and a
// complex square root) and the measured tables (a binary search) cost far more per wavelength
// than a table lookup, and spectral mode evaluates a metal's n and k at four wavelengths every
// time a path meets it. Outside the range the table falls back to the spectrum itself.
//
// Accuracy: for the smooth Lorentz-Drude curves linear interpolation at spacing h = 1 nm errs
// by at most h^2/8 max|f''|; for a measured table the error is where its knots fall between
// the 1 nm samples. tests/spectral/nk_table_test.cpp bounds both against direct evaluation.
#pragma once

#include <algorithm>
#include <memory>
#include <vector>

#include "lamina/spectral/cie.h"
#include "lamina/spectral/ior_spectrum.h"

namespace lamina {

class NkTable {
  public:
    static constexpr double kStepNm = 1.0;

    struct Nk {
        double n, k;
    };

    /// Samples `ior` at every whole nanometre of [kLambdaMin, kLambdaMax].
    explicit NkTable(std::shared_ptr<const IorSpectrum> ior);

    /// n and k at `nm`: linear between the two neighbouring samples inside the range, the
    /// spectrum's own value outside it.
    Nk operator()(double nm) const {
        const double x = (nm - kLambdaMin) / kStepNm;
        if (!(x >= 0.0) || !(x <= last_)) return {ior_->n(nm), ior_->k(nm)};
        const auto i = std::min(static_cast<std::size_t>(x), samples_.size() - 2);
        const double t = x - static_cast<double>(i);
        const Nk& a = samples_[i];
        const Nk& b = samples_[i + 1];
        return {a.n + t * (b.n - a.n), a.k + t * (b.k - a.k)};
    }

    const IorSpectrum& spectrum() const { return *ior_; }

  private:
    std::shared_ptr<const IorSpectrum> ior_;
    std::vector<Nk> samples_;
    double last_ = 0.0;  ///< index of the last sample
};

}  // namespace lamina
