// What the fuzz targets share: the fuzzer's bytes as a regular file with the extension a
// reader dispatches on (the readers take paths, as the scene loader gives them), and the one
// rule every target checks: bad input is an InputError, never a crash, a hang or any other
// exception (which libFuzzer reports as a crash when it escapes).
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "lamina/core/error.h"

namespace lamina::fuzz {

/// Runs a reader on one input: an InputError (bad input refused with a message) is what bad
/// input must get; anything else escapes to libFuzzer, which reports it.
template <typename Read>
int readOrRefuse(Read&& read) {
    try {
        read();
    } catch (const InputError&) {
    }
    return 0;
}

/// A file in the temporary directory holding `size` bytes of `data`, removed on destruction.
class InputFile {
  public:
    InputFile(const std::uint8_t* data, std::size_t size, const std::string& extension)
        : path_(std::filesystem::temp_directory_path() /
                ("lamina-fuzz-" + std::to_string(::getpid()) + extension)) {
        std::ofstream out(path_, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    ~InputFile() {
        std::error_code ignored;
        std::filesystem::remove(path_, ignored);
    }
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

}  // namespace lamina::fuzz
