#include "lamina/experiments/text_format.h"

#include <cstdarg>
#include <cstdio>

namespace lamina::experiments {

std::string formatText(const char* format, ...) {
    va_list args;
    va_start(args, format);
    va_list again;
    va_copy(again, args);
    const int size = std::vsnprintf(nullptr, 0, format, args);
    va_end(args);
    std::string out(std::size_t(size > 0 ? size : 0), '\0');
    if (size > 0) std::vsnprintf(out.data(), out.size() + 1, format, again);
    va_end(again);
    return out;
}

}  // namespace lamina::experiments
