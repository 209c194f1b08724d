// The four variants every BSDF is compiled in (RGB/float, RGB/double, spectral/float,
// spectral/double; the polarised mode wraps the spectral ones), and the mark that compiles a
// BSDF class template once for all of them.
#pragma once

#include "lamina/core/spectrum.h"

// Marks a BSDF class template as compiled once for the four variants, in one optimised file the
// build writes (cmake/GenerateBsdfInstantiations.cmake finds the marks in bsdf/include): files
// that use the class do not compile it again. Put it in the class's header, after the class.
#define LAMINA_EXTERN_BSDF_VARIANTS(Class)               \
    extern template class Class<Rgb<float>>;             \
    extern template class Class<Rgb<double>>;            \
    extern template class Class<SampledSpectrum<float>>; \
    extern template class Class<SampledSpectrum<double>>;
