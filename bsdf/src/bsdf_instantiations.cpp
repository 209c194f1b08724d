// Explicit instantiations of the BSDF templates for the four variants of DESIGN.md
// (RGB/float, RGB/double, spectral/float, spectral/double): every model is compiled in all
// of them, so a change that breaks one variant fails the build, not a later render.
#include "lamina/bsdf/lambert.h"

namespace lamina {

#define LAMINA_INSTANTIATE_BSDF(Class)                   \
    template class Class<Rgb<float>>;                    \
    template class Class<Rgb<double>>;                   \
    template class Class<SampledSpectrum<float>>;        \
    template class Class<SampledSpectrum<double>>;

LAMINA_INSTANTIATE_BSDF(LambertBxdf)

}  // namespace lamina
