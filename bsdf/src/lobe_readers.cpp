// Materials of one lobe: the diffuse models (`lambert`, `oren_nayar`, `burley`, `frostbite`),
// `diffuse_transmission` and the article's `phong` (docs/bsdf.md, "Materials").
#include "material_readers.h"

namespace lamina {

MaterialModel readDiffuse(const JsonReader& r, DiffuseModel model) {
    DiffuseMaterial d;
    d.model = model;
    d.reflectance = readColor(r, "reflectance", 0.5);
    if (model != DiffuseModel::Lambert) {
        MicrofacetParams m;
        readRoughness(r, 0.5, m);
        if (m.alphaX != m.alphaY) r.fail("diffuse roughness is isotropic");
        d.roughness = m.perceptualRoughness();
    }
    return d;
}

MaterialModel readDiffuseTransmission(const JsonReader& r) {
    DiffuseTransmissionMaterial d;
    d.reflectance = readColor(r, "reflectance", 0.25);
    d.transmittance = readColor(r, "transmittance", 0.25);
    return d;
}

MaterialModel readPhong(const JsonReader& r) {
    PhongMaterial p;
    p.reflectance = readColor(r, "reflectance", 0.5);
    if (r.has("shininess")) {
        if (r.has("roughness") || r.has("alpha"))
            r.fail("give either shininess or a roughness (roughness or alpha), not both");
        p.shininess = r.requiredNumber("shininess", {0.0, 1e6});
    } else {
        MicrofacetParams m;
        readRoughness(r, 0.5, m);
        if (m.alphaX != m.alphaY) r.fail("the Phong lobe is isotropic");
        p.shininess = PhongLobe<Rgb<double>>::shininessFromAlpha(m.alphaX);
    }
    return p;
}

}  // namespace lamina
