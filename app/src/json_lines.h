// The pieces of the JSON Lines the commands print (`lamina bsdf eval|sample|albedo`,
// `lamina spectrum`): numbers that are always valid JSON (a value that is not finite prints
// as null, never as "nan" or "inf"), arrays of them, and strings with JSON escapes.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

#include "lamina/core/vector.h"

namespace lamina::app {

/// `v` with `digits` significant digits, or null if it is NaN or infinite.
inline std::string jsonNumber(double v, int digits = 9) {
    if (!std::isfinite(v)) return "null";
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

/// A spectrum's first `channels` values as a JSON array.
template <typename S>
std::string jsonArray(const S& s, int channels, int digits = 9) {
    std::string out = "[";
    for (int i = 0; i < channels; ++i)
        out += (i ? "," : "") + jsonNumber(double(s[i]), digits);
    return out + "]";
}

inline std::string jsonVec(const Vec3d& v, int digits = 9) {
    return "[" + jsonNumber(v.x, digits) + "," + jsonNumber(v.y, digits) + "," +
           jsonNumber(v.z, digits) + "]";
}

/// `text` as a JSON string literal (quotes, backslashes and control characters escaped).
inline std::string jsonString(std::string_view text) {
    std::string out = "\"";
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += ch;
        } else if (c < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
        } else {
            out += ch;
        }
    }
    return out + "\"";
}

}  // namespace lamina::app
