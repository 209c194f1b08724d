#include "lamina/core/output_files.h"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>

#include "lamina/core/error.h"

namespace lamina {

namespace fs = std::filesystem;

namespace {

fs::path directoryOf(const fs::path& path) {
    return path.parent_path().empty() ? fs::path(".") : path.parent_path();
}

// The longest file name (one path component, in bytes) the directory accepts.
std::size_t nameLimit(const fs::path& directory) {
    const long limit = ::pathconf(directory.c_str(), _PC_NAME_MAX);
    return limit > 0 ? std::size_t(limit) : 255;
}

// ".STEM.tmpPID.EXT", the stem cut so that the name fits; empty if even the extension and the
// marker do not fit.
std::string temporaryName(const fs::path& path, std::size_t limit) {
    const std::string stem = path.stem().string();
    const std::string marker = ".tmp" + std::to_string(::getpid()) + path.extension().string();
    if (1 + marker.size() + 1 > limit) return {};
    std::string name = ".";
    name.append(stem, 0, std::min(stem.size(), limit - 1 - marker.size()));
    name += marker;
    return name;
}

void checkWritableDirectory(const fs::path& shown, const fs::path& directory) {
    std::error_code ec;
    if (!fs::is_directory(directory, ec))
        throw InputError(shown.string() + ": the directory " + directory.string() +
                         " does not exist");
    // Creating a file is the one test that holds for every user (root passes access(W_OK)
    // on a read-only mount or /proc) and every file system.
    const fs::path probe = directory / (".lamina-probe" + std::to_string(::getpid()));
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
    if (fd < 0)
        throw InputError(shown.string() + ": cannot create files in the directory " +
                         directory.string() + " (" + std::strerror(errno) + ")");
    ::close(fd);
    ::unlink(probe.c_str());
}

// The temporaries of the writes in progress, in storage a signal handler may read: a slot is
// free (0), being filled (1) or holds a path (2).
constexpr std::size_t kSlots = 8;
struct Slot {
    std::atomic<int> state{0};
    char path[PATH_MAX]{};
};
std::array<Slot, kSlots> slots;

int registerTemporary(const fs::path& path) {
    const std::string& s = path.native();
    if (s.size() >= PATH_MAX) return -1;
    for (std::size_t i = 0; i < kSlots; ++i) {
        int expected = 0;
        if (!slots[i].state.compare_exchange_strong(expected, 1)) continue;
        std::memcpy(slots[i].path, s.c_str(), s.size() + 1);
        slots[i].state.store(2);
        return int(i);
    }
    return -1;  // more writes at once than slots: the destructor still removes it
}

}  // namespace

void checkOutputFile(const fs::path& path, const std::vector<fs::path>& inputs) {
    const fs::path directory = directoryOf(path);
    checkWritableDirectory(path, directory);
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw InputError(path.string() + ": is a directory");
    const std::size_t limit = nameLimit(directory);
    if (path.filename().native().size() > limit || temporaryName(path, limit).empty())
        throw InputError(path.string() + ": the file name is longer than the " +
                         std::to_string(limit) + " bytes the file system allows");
    if (fs::exists(path, ec) && ::access(path.c_str(), W_OK) != 0)
        throw InputError(path.string() + ": the file exists and is not writable");
    for (const fs::path& input : inputs)
        if (fs::equivalent(path, input, ec))
            throw InputError(path.string() + ": is the input " + input.string() +
                             "; writing it would replace the input");
}

void checkOutputDirectory(const fs::path& directory) {
    std::error_code ec;
    if (fs::exists(directory, ec)) {
        if (!fs::is_directory(directory, ec))
            throw InputError(directory.string() + ": exists and is not a directory");
        checkWritableDirectory(directory, directory);
        return;
    }
    // It will be created (with its missing parents) inside its nearest existing ancestor.
    fs::path ancestor = fs::absolute(directory, ec).parent_path();
    while (!ancestor.empty() && !fs::exists(ancestor, ec) && ancestor != ancestor.parent_path())
        ancestor = ancestor.parent_path();
    checkWritableDirectory(directory, ancestor);
}

TemporaryFile::TemporaryFile(fs::path finalPath) : final_(std::move(finalPath)) {
    const fs::path directory = directoryOf(final_);
    const std::string name = temporaryName(final_, nameLimit(directory));
    if (name.empty())
        throw InputError(final_.string() + ": the file name is too long for a temporary name");
    temporary_ = final_.parent_path() / name;
    slot_ = registerTemporary(temporary_);
}

TemporaryFile::~TemporaryFile() {
    std::error_code ec;
    if (!temporary_.empty()) fs::remove(temporary_, ec);
    if (slot_ >= 0) slots[std::size_t(slot_)].state.store(0);
}

void TemporaryFile::commit() {
    std::error_code ec;
    fs::rename(temporary_, final_, ec);
    if (ec) throw InputError(final_.string() + ": cannot write: " + ec.message());
    temporary_.clear();
}

void writeTextFile(const fs::path& path, std::string_view text) {
    TemporaryFile tmp(path);
    {
        std::ofstream out(tmp.path(), std::ios::binary);
        out.write(text.data(), std::streamsize(text.size()));
        out.flush();
        if (!out) throw InputError(path.string() + ": cannot write");
    }
    tmp.commit();
}

void removeTemporaryFilesNow() noexcept {
    for (Slot& slot : slots)
        if (slot.state.load() == 2) ::unlink(slot.path);
}

}  // namespace lamina
