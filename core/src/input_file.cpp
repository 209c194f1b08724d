#include "lamina/core/input_file.h"

#include <fstream>
#include <sstream>

#include "lamina/core/error.h"

namespace lamina {

namespace {

std::string mib(std::uintmax_t bytes) {
    std::ostringstream s;
    s.precision(bytes >= 10 * kMiB ? 0 : 1);
    s << std::fixed << double(bytes) / double(kMiB) << " MiB";
    return s.str();
}

}  // namespace

std::string notARegularFile(const std::filesystem::path& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::file_status st = fs::status(path, ec);
    switch (st.type()) {
        case fs::file_type::regular:
            return {};
        case fs::file_type::not_found:
            return "no such file";
        case fs::file_type::directory:
            return "is a directory, not a regular file";
        case fs::file_type::fifo:
            return "is a FIFO, not a regular file";
        case fs::file_type::character:
        case fs::file_type::block:
            return "is a device, not a regular file";
        case fs::file_type::socket:
            return "is a socket, not a regular file";
        default:
            return ec ? "cannot be read (" + ec.message() + ")" : "is not a regular file";
    }
}

std::uintmax_t checkInputFile(const std::filesystem::path& path, std::uintmax_t limit) {
    if (const std::string why = notARegularFile(path); !why.empty())
        throw InputError(path.string() + ": " +
                         (std::filesystem::exists(path) ? why : "cannot open file (" + why + ")"));
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throw InputError(path.string() + ": cannot read the file size (" + ec.message() + ")");
    if (size > limit)
        throw InputError(path.string() + ": the file is " + mib(size) +
                         ", more than the limit of " + mib(limit) + " for this kind of file");
    return size;
}

std::string readInputFile(const std::filesystem::path& path, std::uintmax_t limit) {
    const std::uintmax_t size = checkInputFile(path, limit);
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string() + ": cannot open the file");
    std::string text(std::size_t(size), '\0');
    in.read(text.data(), std::streamsize(size));
    // A file that shrank while being read is read as far as it goes; one that grew is cut
    // at the size checked, so the limit holds either way.
    text.resize(std::size_t(in.gcount()));
    if (in.bad()) throw InputError(path.string() + ": cannot read the file");
    return text;
}

}  // namespace lamina
