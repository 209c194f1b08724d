// libFuzzer target: the n/k readers (refractiveindex.info YAML and [nm, n, k] CSV). The first
// byte chooses the format, the rest is the file.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.h"
#include "lamina/spectral/ior_spectrum.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const lamina::fuzz::InputFile file(data + 1, size - 1, (data[0] & 1) ? ".yml" : ".csv");
    return lamina::fuzz::readOrRefuse([&] {
        const lamina::IorSpectrum ior = lamina::loadIorFile(file.path());
        // Every wavelength lamina renders must give finite, non-negative n and k.
        for (double nm = 360; nm <= 830; nm += 10) {
            const double n = ior.n(nm), k = ior.k(nm);
            if (!(n >= 0) || !(k >= 0) || !std::isfinite(n) || !std::isfinite(k)) __builtin_trap();
        }
    });
}
