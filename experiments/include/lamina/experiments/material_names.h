// The materials the Fresnel experiments take by name (`lamina fresnel`, `lamina polarisation
// MATERIAL...`): a named metal or glass (ior_spectrum.h's presets) or an n/k file.
#pragma once

#include <string>

#include "lamina/spectral/ior_spectrum.h"

namespace lamina::experiments {

/// The complex index of `name`: a preset (Au, Cu, bk7, ...) or an n/k file (YAML or CSV).
/// InputError naming the presets for anything else.
IorSpectrum loadNamedMaterial(const std::string& name);

/// True when `name` is a preset or an existing file (what loadNamedMaterial may read).
bool mayBeMaterial(const std::string& name);

/// "Au Ag ... bk7 ...": every preset's name, for messages.
std::string knownMaterialNames();

/// True when the material absorbs somewhere in 380-780 nm (k > 0): a conductor.
bool isConductor(const IorSpectrum& ior);

}  // namespace lamina::experiments
