#include "stderr_capture.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace lamina::render {

namespace {
std::recursive_mutex descriptor2;
}  // namespace

StderrCapture::StderrCapture() : turn_(descriptor2) {
    std::fflush(stderr);
    char name[] = "/tmp/lamina-stderr-XXXXXX";
    file_ = ::mkstemp(name);
    if (file_ < 0) return;  // no capture: the library's text reaches stderr as before
    ::unlink(name);
    saved_ = ::dup(STDERR_FILENO);
    if (saved_ < 0 || ::dup2(file_, STDERR_FILENO) < 0) {
        if (saved_ >= 0) ::close(saved_);
        saved_ = -1;
    }
}

StderrCapture::~StderrCapture() {
    std::fflush(stderr);
    if (saved_ >= 0) {
        ::dup2(saved_, STDERR_FILENO);
        ::close(saved_);
    }
    if (file_ >= 0) ::close(file_);
}

std::string StderrCapture::text() const {
    if (saved_ < 0) return {};
    std::fflush(stderr);
    std::string out;
    char buf[512];
    for (off_t at = 0;;) {
        const ssize_t n = ::pread(file_, buf, sizeof buf, at);
        if (n <= 0) break;
        out.append(buf, std::size_t(n));
        at += n;
        if (out.size() > 4096) break;  // the first lines say enough
    }
    while (!out.empty() && (out.back() == '\n' || out.back() == '\r'))
        out.pop_back();
    for (std::size_t i; (i = out.find('\n')) != std::string::npos;)
        out.replace(i, 1, "; ");
    return out;
}

}  // namespace lamina::render
