// User text in a message: a name, key or path echoed on lamina's one error line may hold any
// bytes, and a newline or a terminal escape in it must not break that line or the terminal.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace lamina {

/// `text` with every control character written as an escape (\n, \r, \t, \xHH); everything
/// else (printable ASCII, UTF-8) unchanged.
inline std::string escapeControl(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c == '\n') {
            out += "\\n";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c < 0x20 || c == 0x7f) {
            char buf[5];
            std::snprintf(buf, sizeof buf, "\\x%02x", c);
            out += buf;
        } else {
            out += ch;
        }
    }
    return out;
}

}  // namespace lamina
