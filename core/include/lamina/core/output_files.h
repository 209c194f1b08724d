// The files a command writes: checked before the work that produces them starts (so a long
// render never ends in "cannot write"), written under a temporary name beside the final one
// and renamed when complete (so a reader never sees half a file), and the temporary removed on
// every way out: an exception (the destructor), or a signal that ends the process
// (removeTemporaryFilesNow, from the signal handler).
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

namespace lamina {

/// `path` can be created or replaced: its directory exists and is writable, it is not a
/// directory, its name and the temporary name beside it fit the file system's limit, and it is
/// none of `inputs` (the same file by identity, not by name: a link or another spelling of an
/// input counts). InputError naming `path` otherwise.
void checkOutputFile(const std::filesystem::path& path,
                     const std::vector<std::filesystem::path>& inputs = {});

/// `directory` is a writable directory, or can be created: it is not a file, and its nearest
/// existing ancestor is a writable directory. InputError naming `directory` otherwise.
void checkOutputDirectory(const std::filesystem::path& directory);

/// A file being written: write to path(), then commit() renames it to the final path. Until
/// then the temporary exists only under the hidden name ".STEM.tmpPID.EXT" (the stem shortened
/// so that the name fits), and is removed if the writer is destroyed without committing.
class TemporaryFile {
  public:
    explicit TemporaryFile(std::filesystem::path finalPath);
    ~TemporaryFile();
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    const std::filesystem::path& path() const { return temporary_; }
    /// Renames the temporary to the final path; InputError naming the final path if it fails.
    void commit();

  private:
    std::filesystem::path final_, temporary_;
    int slot_ = -1;  // its entry for removeTemporaryFilesNow, -1 if none was free
};

/// Writes `text` to `path` through a TemporaryFile: the file is complete or not there at all.
/// InputError naming `path` if it cannot be written.
void writeTextFile(const std::filesystem::path& path, std::string_view text);

/// Removes the temporaries of every write in progress. Async-signal-safe: for a signal
/// handler that is about to end the process.
void removeTemporaryFilesNow() noexcept;

}  // namespace lamina
