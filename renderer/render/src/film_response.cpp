#include "lamina/render/film_response.h"

#include <algorithm>

#include "lamina/scene/scene_description.h"
#include "lamina/spectral/white_balance.h"

namespace lamina::render {

FilmResponse::FilmResponse(const FilmDesc& film, FilmSpace space)
    : scale_(film.imagingRatio()), maxComponent_(film.maxComponentValue) {
    const RgbColorSpace& rec709 = RgbColorSpace::rec709();
    if (space == FilmSpace::Rec709) toXyz_ = rec709.rgbToXyz();
    if (film.whiteBalance > 0) {
        // The image's white is Rec.709's: the D65 table's XYZ, which RGB (1, 1, 1) is.
        const Mat3<double> xyz =
            bradfordAdaptation(daylightChromaticity(film.whiteBalance).toXyz(), rec709.whiteXyz());
        balance_ = space == FilmSpace::Xyz ? xyz : rec709.xyzToRgb() * xyz * rec709.rgbToXyz();
    }
    identity_ = scale_ == 1 && !maxComponent_ && !balance_;
}

Rgb<double> FilmResponse::apply(const Rgb<double>& v) const {
    if (identity_) return v;
    Vec3d c(v[0] * scale_, v[1] * scale_, v[2] * scale_);
    if (maxComponent_) {
        const Vec3d xyz = toXyz_ * c;
        const double m = std::max({xyz.x, xyz.y, xyz.z});
        if (m > *maxComponent_) c *= *maxComponent_ / m;
    }
    if (balance_) c = *balance_ * c;
    return {c.x, c.y, c.z};
}

}  // namespace lamina::render
