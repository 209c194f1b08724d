// Error metrics between two images of the same size (the experiments' yardsticks), over the
// RGB channels of every pixel (N = 3 x pixels):
//   mse    = mean((a - b)^2)              rmse = sqrt(mse)
//   relmse = mean((a - b)^2 / (b^2 + eps)), eps = 1e-2 (b is the reference; the epsilon keeps
//            black reference pixels from dominating, as in Rousselle et al. 2011's relMSE)
//   mae    = mean(|a - b|)                max  = max |a - b|
// and the standard error of relmse as the mean of its N terms, sqrt(var(terms) / N): how far
// this image's relMSE is known, with the pixels' errors taken as independent (a pixel filter
// wider than a pixel correlates neighbours a little).
#pragma once

#include <string>
#include <vector>

#include "lamina/core/name_table.h"
#include "lamina/experiments/figure_spec.h"
#include "lamina/output/image_output.h"
#include "lamina/render/film.h"

namespace lamina::experiments {

inline constexpr double kRelMseEpsilon = 1e-2;

/// Over the channel values finite in both images: a NaN or infinite value (of a broken or
/// unfinished render) would make every mean NaN, and would vanish from the max.
struct ImageMetrics {
    double mse = 0, rmse = 0, relmse = 0, mae = 0, max = 0;
    double relmseStandardError = 0;
    std::size_t compared = 0;   ///< channel values finite in both images
    std::size_t nonFinite = 0;  ///< channel values left out: NaN or infinite in either
};

enum class Metric { Mse, Rmse, Relmse, Mae, Max };
inline constexpr NameTable kMetricNames{
    std::array{NameEntry{Metric::Mse, "mse"}, NameEntry{Metric::Rmse, "rmse"},
               NameEntry{Metric::Relmse, "relmse"}, NameEntry{Metric::Mae, "mae"},
               NameEntry{Metric::Max, "max"}}};

/// One of the metrics by its name in the table.
double metricValue(const ImageMetrics& metrics, Metric metric);

/// InputError if the sizes differ.
ImageMetrics compareImages(const render::RgbImage& a, const render::RgbImage& reference);

/// InputError when `m` compared nothing: naming the image with no finite value (`nameA` for a,
/// `nameB` for the reference), or saying that no value is finite in both. A metric of no values
/// would print as 0, a perfect match.
void requireComparedValues(const ImageMetrics& m, const render::RgbImage& a,
                           const std::string& nameA, const render::RgbImage& reference,
                           const std::string& nameB);

/// "N of M channel values are NaN or infinite ...": what compare says when it left values out;
/// empty when it left none out.
std::string nonFiniteNote(const ImageMetrics& m);

/// The map of the mean absolute channel difference |a - b| per pixel (linear radiance, a
/// sequential scale from 0: figure_spec.h), titled `title`.
MapFigure differenceFigure(const render::RgbImage& a, const render::RgbImage& b,
                           const std::string& title);

/// The two images as a pair for a report page's viewer (figure_spec.h), A named `labelA`.
ImagePair imagePair(const render::RgbImage& a, const std::string& labelA, const render::RgbImage& b,
                    const std::string& labelB, const std::string& title);

/// The false-colour image alone of the mean absolute channel difference |a - b| in any format
/// lamina writes (`compare --diff NAME.tif`, ...; a PNG gets the figure of differenceFigure
/// instead): black, blue, magenta, yellow, white from 0 to `scale`, one pixel per pixel, grey
/// where the difference is not finite.
void writeDifferenceImage(const std::filesystem::path& path, const render::RgbImage& a,
                          const render::RgbImage& b, double scale);

/// The CIEDE2000 of each pixel of a against b (linear Rec.709, the same size), row-major from
/// the top row: the colour difference maps of `fresnel --scene` and `polarisation`.
std::vector<float> ciede2000Map(const render::RgbImage& a, const render::RgbImage& b);

/// Black, for relativeDifferenceMap: a luminance of at most this times the brightest pixel's.
/// Light that cancels (crossed mirrors at Brewster's angle) leaves about 1e-15 of the light from
/// float rounding, whose relative difference would be O(1) of nothing.
inline constexpr double kNoLight = 1e-6;

/// The luminance Y of pixel i (linear Rec.709).
double pixelLuminance(const render::RgbImage& image, std::size_t i);

/// The symmetric relative difference of the luminance of each pixel, |Y_a - Y_b| / ((Y_a + Y_b)
/// / 2), in [0, 2], NaN where both are black (kNoLight of the brightest pixel of the two images;
/// a negative luminance, of a colour outside the gamut, counts as 0): `polarisation`'s and
/// `media`'s relative difference maps.
std::vector<float> relativeDifferenceMap(const render::RgbImage& a, const render::RgbImage& b);

/// The mean of the finite values; 0 when none is finite.
double meanOfFinite(const std::vector<float>& values);

/// The p-th percentile (0-100) of the finite values, interpolated linearly between the two
/// nearest ranks (NumPy's default, which the figure module uses); 0 when none is finite.
double percentileOf(std::vector<float> values, double p);

/// The film's current image (linear Rec.709) as an RgbImage.
render::RgbImage filmImage(const render::Film& film);

/// Error against a reference after every pass of a render (render --error-log, convergence):
/// one row per pass of seconds, samples per pixel, MSE, relMSE and MAE.
class ErrorLog {
  public:
    struct Row {
        double seconds;
        int spp;
        ImageMetrics metrics;
    };
    explicit ErrorLog(render::RgbImage reference) : reference_(std::move(reference)) {}
    /// Rows measured before (a finished run read back: convergence_runs.h).
    ErrorLog(render::RgbImage reference, std::vector<Row> rows)
        : reference_(std::move(reference)), rows_(std::move(rows)) {}
    /// Measures the film; InputError if its size differs from the reference's.
    void record(double seconds, int spp, const render::Film& film);
    const std::vector<Row>& rows() const { return rows_; }
    const render::RgbImage& reference() const { return reference_; }
    /// CSV with a header: seconds,spp,mse,relmse,mae (prefixed by `columns` when given).
    static std::string csvHeader(const std::string& columns = "");
    std::string csvRows(const std::string& prefix = "") const;

  private:
    render::RgbImage reference_;
    std::vector<Row> rows_;
};

}  // namespace lamina::experiments
