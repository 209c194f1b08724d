#include "lamina/output/image_output.h"

#include <algorithm>
#include <cmath>

#include "lamina/image/image_files.h"
#include "lamina/output/spectral_layout.h"
#include "lamina/spectral/color_space.h"

namespace lamina::render {

void writeExr(const std::filesystem::path& path, const Film& film, bool aovs,
              const ImageMetadata& metadata, bool variance) {
    const int w = film.width(), h = film.height();
    std::vector<std::string> channels = {"R", "G", "B"};
    if (aovs)
        channels.insert(channels.end(), {"Albedo.R", "Albedo.G", "Albedo.B", "N.X", "N.Y", "N.Z",
                                         "Z", "Variance.Y"});
    else if (variance)
        channels.push_back("Variance.Y");
    if (variance) channels.insert(channels.end(), {"Variance.R", "Variance.G", "Variance.B"});
    // The polarised mode's Stokes layers last (docs/polarisation.md, "Stokes images").
    const std::size_t stokesAt = channels.size();
    if (film.hasStokes())
        for (const char* s : {"S0", "S1", "S2", "S3"})
            for (const char* c : {".R", ".G", ".B"})
                channels.push_back(std::string(s) + c);
    // Then the spectral film's, in the spectral layout (spectral_layout.h).
    const std::size_t spectralAt = channels.size();
    const SpectralFilm* spectral = film.spectralFilm();
    if (spectral)
        for (const std::string& name :
             spectralChannelNames(spectral->bins(), spectral->components()))
            channels.push_back(name);
    std::vector<double> bins(spectral ? spectral->valuesPerPixel() : 0);
    const std::size_t nc = channels.size();
    std::vector<float> data(std::size_t(w) * h * nc);
    ImageToWrite image = floatImage(w, h, channels, data, metadata);
    setDataWindow(image, film.window(), film.fullWidth(), film.fullHeight());
    // The primaries and white of lamina's linear Rec.709 (the EXR "chromaticities" attribute).
    const RgbColorSpace& cs = RgbColorSpace::rec709();
    const Vec3d white = cs.whiteXyz();
    const double sum = white.x + white.y + white.z;
    image.chromaticities = std::array<float, 8>{
        float(cs.red().x),  float(cs.red().y),  float(cs.green().x),  float(cs.green().y),
        float(cs.blue().x), float(cs.blue().y), float(white.x / sum), float(white.y / sum)};
    if (spectral) image.attributes = spectralLayoutAttributes(spectral->components());

    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            float* p = &data[(std::size_t(y) * w + x) * nc];
            const Rgb<double> v = film.pixel(x, y);
            for (int c = 0; c < 3; ++c)
                p[c] = float(v[c]);
            if (variance) {
                const Rgb<double> var = film.varianceOfMeanRgb(x, y);
                for (int c = 0; c < 3; ++c)
                    p[stokesAt - 3 + std::size_t(c)] = float(var[c]);
            }
            if (film.hasStokes()) {
                const std::array<Rgb<double>, 4> s = film.stokes(x, y);
                for (std::size_t i = 0; i < 4; ++i)
                    for (std::size_t c = 0; c < 3; ++c)
                        p[stokesAt + 3 * i + c] = float(s[i][int(c)]);
            }
            if (spectral) {
                film.spectralMean(x, y, bins.data());
                for (std::size_t i = 0; i < bins.size(); ++i)
                    p[spectralAt + i] = float(bins[i]);
            }
            if (!aovs) {
                if (variance) p[3] = float(film.varianceOfMean(x, y));
                continue;
            }
            const PixelAovs a = film.aovs(x, y);
            for (int c = 0; c < 3; ++c) {
                p[3 + c] = float(a.albedo[c]);
                p[6 + c] = float(a.normal[c]);
            }
            p[9] = float(a.depth);
            p[10] = float(film.varianceOfMean(x, y));
        }
    writeImageFile(path, image);
}

void writePngPreview(const std::filesystem::path& path, const Film& film, double exposure) {
    const int w = film.width(), h = film.height();
    std::vector<float> data(std::size_t(w) * h * 3);
    const double scale = std::exp2(exposure);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Rgb<double> v = film.pixel(x, y);
            for (int c = 0; c < 3; ++c) {
                // The sRGB transfer function (IEC 61966-2-1).
                const double l = std::clamp(v[c] * scale, 0.0, 1.0);
                const double e = l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1 / 2.4) - 0.055;
                data[(std::size_t(y) * w + x) * 3 + std::size_t(c)] = float(e);
            }
        }
    writeImageFile(path, rgb8Image(w, h, data));
}

}  // namespace lamina::render
