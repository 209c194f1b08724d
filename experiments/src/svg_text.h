// Text inside the SVG figures the experiments write (internal to lamina_experiments).
#pragma once

#include <string>

namespace lamina::experiments {

/// `s` with the characters XML gives a meaning (<, >, &, ") escaped.
inline std::string svgEscape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else if (c == '"')
            out += "&quot;";
        else
            out += c;
    }
    return out;
}

}  // namespace lamina::experiments
