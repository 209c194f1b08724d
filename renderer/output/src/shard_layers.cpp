#include "shard_layers.h"

#include "lamina/output/spectral_layout.h"

namespace lamina::render {

namespace {

/// "S0.Sum.550,000000nm": a spectral layer's channel with the kind of sum after its component.
std::string spectralSumName(const std::string& channel, const char* kind) {
    const std::size_t dot = channel.find('.');
    return channel.substr(0, dot) + "." + kind + channel.substr(dot);
}

}  // namespace

std::vector<std::string> layerSumNames(const Film& film) {
    std::vector<std::string> names;
    if (film.hasStokes())
        for (const char* kind : {"Sum", "Splat"})
            for (int k = 1; k <= 3; ++k)
                for (const char* c : {"R", "G", "B"}) {
                    // Appended piece by piece: GCC 12 warns (-Wrestrict) on "S" + string.
                    std::string name = "S";
                    name += std::to_string(k);
                    names.push_back(name + "." + kind + "." + c);
                }
    if (const SpectralFilm* s = film.spectralFilm()) {
        const std::vector<std::string> channels = spectralChannelNames(s->bins(), s->components());
        for (const std::string& c : channels)
            names.push_back(spectralSumName(c, "Sum"));
        if (s->splats())
            for (const std::string& c : channels)
                names.push_back(spectralSumName(c, "Splat"));
    }
    return names;
}

void appendLayerSums(const Film& film, int x, int y, std::vector<double>& out) {
    if (film.hasStokes())
        for (const StokesSums* sums : {&film.stokesCameraSums(x, y), &film.stokesSplatSums(x, y)})
            for (std::size_t k = 0; k < 3; ++k)
                for (int c = 0; c < 3; ++c)
                    out.push_back((*sums)[k][c]);
    if (const SpectralFilm* s = film.spectralFilm()) {
        const std::size_t pixel = std::size_t(y) * std::size_t(film.width()) + std::size_t(x);
        const std::size_t n = s->valuesPerPixel();
        out.insert(out.end(), s->cameraSums(pixel), s->cameraSums(pixel) + n);
        if (s->splats()) out.insert(out.end(), s->splatSums(pixel), s->splatSums(pixel) + n);
    }
}

void addLayerSums(Film& film, int x, int y, const double* values) {
    if (film.hasStokes()) {
        StokesSums camera, splat;
        for (std::size_t i = 0; i < 18; ++i)
            (i < 9 ? camera : splat)[(i % 9) / 3][int(i % 3)] = values[i];
        film.addStokesSums(x, y, camera, splat);
        values += 18;
    }
    if (const SpectralFilm* s = film.spectralFilm())
        film.addSpectralSums(x, y, values, s->splats() ? values + s->valuesPerPixel() : nullptr);
}

}  // namespace lamina::render
