#include "lamina/output/strategy_files.h"

#include <string>

#include "lamina/output/image_output.h"

namespace lamina::render {

void writeStrategyImages(const std::filesystem::path& directory, const StrategyImages& images,
                         const Film& like, int spp, const ImageMetadata& metadata) {
    std::filesystem::create_directories(directory);
    const double particles = double(images.width()) * images.height() * spp;
    for (std::size_t i = 0; i < images.strategies().size(); ++i) {
        const auto [s, t] = images.strategies()[i];
        for (const bool weighted : {true, false}) {
            Film film(images.width(), images.height(), like.space());
            const auto pixels = images.image(int(i), weighted, particles);
            for (int y = 0; y < film.height(); ++y)
                for (int x = 0; x < film.width(); ++x)
                    film.addSample(x, y, pixels[std::size_t(y) * film.width() + x], 1.0);
            ImageMetadata m = metadata;
            m.ints["s"] = s;
            m.ints["t"] = t;
            m.ints["mis_weighted"] = weighted ? 1 : 0;
            const std::string name = "s" + std::to_string(s) + "_t" + std::to_string(t) +
                                     (weighted ? "_weighted.exr" : "_unweighted.exr");
            writeExr(directory / name, film, false, m);
        }
    }
}

}  // namespace lamina::render
