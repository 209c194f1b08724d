// printf-style formatting into a string: the reports keep the number formats (%.4g, %.2f, ...)
// the experiments have always printed, without fixed-size buffers.
#pragma once

#include <string>

namespace lamina::experiments {

std::string formatText(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace lamina::experiments
