#include "lamina/bsdf/bsdf_sample.h"

#include <algorithm>

namespace lamina {

std::string describeLobes(std::uint32_t flags) {
    std::string out;
    for (const auto& [kind, name] : kLobeKindNames.entries()) {
        if ((flags & kind) != kind) continue;
        if (!out.empty()) out += ", ";
        std::string words(name);
        std::replace(words.begin(), words.end(), '_', ' ');
        out += words;
    }
    return out.empty() ? "none (black)" : out;
}

}  // namespace lamina
