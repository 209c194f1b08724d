// The metadata lamina writes into its images and reads back: every key is stored as the
// attribute "lamina:<key>" with its type (string, float, int, or a 4x4 float matrix).
#pragma once

#include <array>
#include <map>
#include <string>

namespace lamina::render {

struct ImageMetadata {
    std::map<std::string, std::string> strings;  ///< written as "lamina:<key>"
    std::map<std::string, float> floats;
    std::map<std::string, int> ints;
    std::map<std::string, std::array<float, 16>> matrices;  ///< row-major 4x4 (M44f)
};

}  // namespace lamina::render
