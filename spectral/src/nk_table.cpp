#include "lamina/spectral/nk_table.h"

#include <cmath>

namespace lamina {

NkTable::NkTable(std::shared_ptr<const IorSpectrum> ior) : ior_(std::move(ior)) {
    const auto count =
        static_cast<std::size_t>(std::lround((kLambdaMax - kLambdaMin) / kStepNm)) + 1;
    samples_.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const double nm = kLambdaMin + kStepNm * static_cast<double>(i);
        samples_.push_back({ior_->n(nm), ior_->k(nm)});
    }
    last_ = static_cast<double>(count - 1);
}

}  // namespace lamina
