#include "lamina/experiments/figure_drawing.h"

#include <spawn.h>
#include <sys/wait.h>

#include <cerrno>
#include <cstdlib>
#include <vector>

#include "lamina/experiments/text_format.h"

extern char** environ;

// Set by experiments/CMakeLists.txt for this file alone.
#ifndef LAMINA_FIGURES_PYTHON
#define LAMINA_FIGURES_PYTHON ""
#endif
#ifndef LAMINA_FIGURES_SCRIPT
#define LAMINA_FIGURES_SCRIPT ""
#endif

namespace lamina::experiments {

namespace {

// figures.py's exit status when it cannot import matplotlib.
constexpr int kNoMatplotlib = 3;

std::string interpreter() {
    const char* env = std::getenv("LAMINA_PYTHON");
    return env && *env ? env : LAMINA_FIGURES_PYTHON;
}

}  // namespace

std::string drawFigures(const std::filesystem::path& specs) {
    const std::string python = interpreter();
    const std::string where =
        "their data is in " +
        (std::filesystem::is_directory(specs) ? specs / "*.figure.json" : specs).string();
    if (python.empty())
        return "figures not drawn (the build found no Python with matplotlib; set "
               "LAMINA_PYTHON): " +
               where;
    const std::string script = LAMINA_FIGURES_SCRIPT, dir = specs.string();
    std::vector<char*> argv{const_cast<char*>(python.c_str()), const_cast<char*>(script.c_str()),
                            const_cast<char*>(dir.c_str()), nullptr};
    pid_t pid = 0;
    const int spawned =
        ::posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ);
    if (spawned != 0)
        return "figures not drawn (cannot run " + python + "; set LAMINA_PYTHON): " + where;
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return "figures not drawn (lost " + python + "): " + where;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
    if (WIFEXITED(status) && WEXITSTATUS(status) == kNoMatplotlib)
        return "figures not drawn (" + python + " has no matplotlib; set LAMINA_PYTHON): " + where;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
        return "figures not drawn (cannot run " + python + "; set LAMINA_PYTHON): " + where;
    return formatText("figures not drawn (%s %s exited with status %d): ", python.c_str(),
                      script.c_str(), WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
           where;
}

}  // namespace lamina::experiments
