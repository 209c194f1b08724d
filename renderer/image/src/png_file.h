// lamina's own PNG writer: 8-bit RGB, for previews and figures, without OpenImageIO.
#pragma once

#include <string>

namespace lamina::render {

/// The bytes of a PNG of width x height 8-bit RGB pixels (`rgb`: interleaved values in [0, 1],
/// rounded to the nearest of 0..255; NaN as 0), marked sRGB.
std::string encodePngRgb8(int width, int height, const float* rgb);

}  // namespace lamina::render
