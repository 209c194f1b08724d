// Where the tests find files of the source tree (scenes, test data): one spelling of
// "LAMINA_SOURCE_DIR/relative" for every test. It appends into one string instead of writing
// `std::string(dir) + "/x"`, on which GCC 12 warns falsely (-Warray-bounds) once inlined.
#pragma once

#include <string>
#include <string_view>

namespace lamina::testing {

/// The path of `relative` (e.g. "scenes/cornell-box.json") inside the source tree.
inline std::string sourceFile(std::string_view relative) {
    std::string path = LAMINA_SOURCE_DIR;
    path += '/';
    path += relative;
    return path;
}

}  // namespace lamina::testing
