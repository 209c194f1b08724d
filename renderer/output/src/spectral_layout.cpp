#include "lamina/output/spectral_layout.h"

#include <algorithm>
#include <cstdio>

namespace lamina::render {

std::string spectralChannelName(int stokes, double nm) {
    char number[64];
    std::snprintf(number, sizeof number, "%.6f", nm);
    std::string text = number;
    // The layout's decimal separator is a comma, whatever the C locale wrote.
    std::replace(text.begin(), text.end(), '.', ',');
    // Appended piece by piece: GCC 12 warns (-Wrestrict) on "S" + string.
    std::string name = "S";
    name += std::to_string(stokes);
    return name + "." + text + "nm";
}

std::vector<std::string> spectralChannelNames(const SpectralBins& bins, int components) {
    std::vector<std::string> names;
    for (int c = 0; c < components; ++c)
        for (int b = 0; b < bins.count; ++b)
            names.push_back(spectralChannelName(c, bins.centre(b)));
    return names;
}

std::map<std::string, std::string> spectralLayoutAttributes(int components) {
    std::map<std::string, std::string> a = {{"spectralLayoutVersion", "1.0"},
                                            {"emissiveUnits", "W.m^-2.sr^-1"}};
    // lamina's S3 > 0 is a field that turns right-handedly about the direction the light
    // travels (docs/polarisation.md, "Stokes vectors and their frames").
    if (components == 4) a["polarisationHandedness"] = "right";
    return a;
}

}  // namespace lamina::render
