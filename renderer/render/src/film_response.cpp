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
    // Multiplying by a ratio of 1 changes no bit.
    if (maxComponent_) c *= clampRatio(c);
    if (balance_) c = *balance_ * c;
    return {c.x, c.y, c.z};
}

double FilmResponse::clampRatio(const Vec3d& c) const {
    if (!maxComponent_) return 1.0;
    const Vec3d xyz = toXyz_ * c;
    const double m = std::max({xyz.x, xyz.y, xyz.z});
    return m > *maxComponent_ ? *maxComponent_ / m : 1.0;
}

Rgb<double> FilmResponse::applyAlongside(const Rgb<double>& v, const Rgb<double>& other) const {
    if (identity_) return other;
    const double k = scaleAlongside(v);
    Vec3d c(other[0] * k, other[1] * k, other[2] * k);
    if (balance_) c = *balance_ * c;
    return {c.x, c.y, c.z};
}

double FilmResponse::scaleAlongside(const Rgb<double>& v) const {
    if (identity_) return 1.0;
    return scale_ * clampRatio(Vec3d(v[0] * scale_, v[1] * scale_, v[2] * scale_));
}

}  // namespace lamina::render
