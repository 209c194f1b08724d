#include "lamina/core/gzip_file.h"

#include <zlib.h>

#include "lamina/core/error.h"
#include "lamina/core/input_file.h"

namespace lamina {

bool isGzipPath(const std::filesystem::path& file) {
    return file.extension() == ".gz";
}

std::string readGzipFile(const std::filesystem::path& file, std::uintmax_t compressedLimit,
                         std::uintmax_t decompressedLimit, const std::string& what) {
    checkInputFile(file, compressedLimit);
    gzFile in = gzopen(file.string().c_str(), "rb");
    if (!in) throw InputError(file.string() + ": cannot open the " + what + " file");
    std::string data;
    char buffer[1 << 16];
    while (true) {
        const int n = gzread(in, buffer, sizeof buffer);
        if (n < 0) {
            int code = 0;
            const std::string why = gzerror(in, &code);
            gzclose(in);
            throw InputError(file.string() + ": not a valid gzip file (" + why + ")");
        }
        if (n == 0) break;
        if (data.size() + std::size_t(n) > decompressedLimit) {
            gzclose(in);
            throw InputError(file.string() + ": decompresses to more than " +
                             std::to_string(decompressedLimit / kMiB) + " MiB");
        }
        data.append(buffer, std::size_t(n));
    }
    gzclose(in);
    return data;
}

}  // namespace lamina
