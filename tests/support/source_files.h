// Where the tests find files of the source tree (scenes, test data): one spelling of
// "LAMINA_SOURCE_DIR/relative" for every test. A path built with `/`, not a string built with
// `std::string(dir) + "/x"`: on the latter, and on a moved string becoming a path, GCC 12
// warns falsely (-Warray-bounds) once inlined under precompiled headers.
#pragma once

#include <filesystem>
#include <string_view>

namespace lamina::testing {

/// The path of `relative` (e.g. "scenes/cornell-box.json") inside the source tree.
inline std::filesystem::path sourceFile(std::string_view relative) {
    return std::filesystem::path(LAMINA_SOURCE_DIR) / relative;
}

}  // namespace lamina::testing
