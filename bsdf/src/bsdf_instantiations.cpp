// Explicit instantiations of the templates that are not BSDFs of one material type: the
// microfacet distributions. The BSDF class templates and every material type's builder are
// compiled in the file the build writes from their headers' marks (bsdf_instantiations.cpp in
// the build's generated/ folder, cmake/GenerateBsdfRegistry.cmake): every model in the four
// variants of the dual-mode design, so a change that breaks one variant fails the build, not a
// later render.
#include "lamina/bsdf/microfacet_distribution.h"

namespace lamina {

template class MicrofacetDistribution<float>;
template class MicrofacetDistribution<double>;

}  // namespace lamina
