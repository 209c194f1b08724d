// Libraries that talk on stderr (used inside lamina's OpenImageIO module, oiio_images.cpp):
// OpenImageIO creates libpng's reader and writer with libpng's default handlers, which print
// "libpng warning: ..." and "libpng error: ..." straight to file descriptor 2, past lamina's
// one-line error policy. While a StderrCapture is alive, whatever is written to descriptor 2 goes
// to a temporary file instead; text() returns it, so a failed read can name the library's reason on
// lamina's own line, and a successful one stays quiet.
#pragma once

#include <mutex>
#include <string>

namespace lamina::render {

class StderrCapture {
  public:
    StderrCapture();
    ~StderrCapture();  // restores descriptor 2
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;

    /// What was written so far, on one line ("; " between lines), empty if nothing.
    std::string text() const;

  private:
    // Descriptor 2 is one per process: captures in two threads would restore each other's
    // descriptors, so they take turns (nested ones in one thread restore in order).
    std::unique_lock<std::recursive_mutex> turn_;
    int saved_ = -1;  // the original descriptor 2, -1 if the capture could not start
    int file_ = -1;   // the unlinked temporary file descriptor 2 points at
};

}  // namespace lamina::render
