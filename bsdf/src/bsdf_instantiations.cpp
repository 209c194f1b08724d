// Explicit instantiations of the BSDF templates for the four variants of the dual-mode design
// (RGB/float, RGB/double, spectral/float, spectral/double): every model is compiled in all
// of them, so a change that breaks one variant fails the build, not a later render.
#include "lamina/bsdf/coated.h"
#include "lamina/bsdf/conductor.h"
#include "lamina/bsdf/dielectric.h"
#include "lamina/bsdf/diffuse.h"
#include "lamina/bsdf/diffuse_transmission.h"
#include "lamina/bsdf/layered.h"
#include "lamina/bsdf/material_builder.h"
#include "lamina/bsdf/optical_sheet.h"
#include "lamina/bsdf/thin_dielectric.h"

namespace lamina {

#define LAMINA_INSTANTIATE_BSDF(Class)            \
    template class Class<Rgb<float>>;             \
    template class Class<Rgb<double>>;            \
    template class Class<SampledSpectrum<float>>; \
    template class Class<SampledSpectrum<double>>;

LAMINA_INSTANTIATE_BSDF(DiffuseBxdf)
LAMINA_INSTANTIATE_BSDF(ConductorBxdf)
LAMINA_INSTANTIATE_BSDF(DielectricBxdf)
LAMINA_INSTANTIATE_BSDF(DiffuseTransmissionBxdf)
LAMINA_INSTANTIATE_BSDF(ThinDielectricBxdf)
LAMINA_INSTANTIATE_BSDF(OpticalSheetBxdf)
LAMINA_INSTANTIATE_BSDF(LayeredBxdf)
LAMINA_INSTANTIATE_BSDF(MicrofacetReflectionLobe)
LAMINA_INSTANTIATE_BSDF(MixBxdf)
LAMINA_INSTANTIATE_BSDF(CoatedBxdf)
template class MaterialBuilder<Rgb<float>>;
template class MaterialBuilder<Rgb<double>>;
template class MaterialBuilder<SampledSpectrum<float>>;
template class MaterialBuilder<SampledSpectrum<double>>;

template class MicrofacetDistribution<float>;
template class MicrofacetDistribution<double>;

}  // namespace lamina
