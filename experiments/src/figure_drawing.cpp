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
#ifndef LAMINA_PAGE_PYTHON
#define LAMINA_PAGE_PYTHON ""
#endif
#ifndef LAMINA_PYTHON_PACKAGE
#define LAMINA_PYTHON_PACKAGE ""
#endif

namespace lamina::experiments {

namespace {

// figures.py's exit status when it cannot import matplotlib.
constexpr int kNoMatplotlib = 3;

std::string interpreter(const char* built) {
    const char* env = std::getenv("LAMINA_PYTHON");
    return env && *env ? env : built;
}

/// Runs `python SCRIPT ARGS...` (SCRIPT in python/lamina) and waits. Returns "" when it exited
/// with 0, else why not, in a few words ("cannot run X", "X script exited with status N");
/// `needs`: the package the script exits with kNoMatplotlib without ("" for none).
std::string runPython(const std::string& python, const std::string& scriptName,
                      std::vector<std::string> args, const std::string& needs) {
    if (python.empty())
        return "the build found no Python" + (needs.empty() ? "" : " with " + needs) +
               "; set LAMINA_PYTHON";
    const std::string script = std::string(LAMINA_PYTHON_PACKAGE) + "/" + scriptName;
    args.insert(args.begin(), {python, script});
    std::vector<char*> argv;
    for (std::string& a : args)
        argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (::posix_spawnp(&pid, python.c_str(), nullptr, nullptr, argv.data(), environ) != 0)
        return "cannot run " + python + "; set LAMINA_PYTHON";
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return "lost " + python;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
    if (WIFEXITED(status) && WEXITSTATUS(status) == kNoMatplotlib && !needs.empty())
        return python + " has no " + needs + "; set LAMINA_PYTHON";
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
        return "cannot run " + python + "; set LAMINA_PYTHON";
    return formatText("%s %s exited with status %d", python.c_str(), script.c_str(),
                      WIFEXITED(status) ? WEXITSTATUS(status) : -1);
}

}  // namespace

std::string drawFigures(const std::filesystem::path& specs) {
    const std::string why =
        runPython(interpreter(LAMINA_FIGURES_PYTHON), "figures.py", {specs.string()}, "matplotlib");
    if (why.empty()) return "";
    return "figures not drawn (" + why + "): their data is in " +
           (std::filesystem::is_directory(specs) ? specs / "*.figure.json" : specs).string();
}

std::string writeReportPage(const std::filesystem::path& directory) {
    const std::string why =
        runPython(interpreter(LAMINA_PAGE_PYTHON), "report_page.py", {directory.string()}, "");
    if (why.empty()) return "";
    return "index.html not written (" + why + "): the report is " +
           (directory / "summary.md").string();
}

std::string writePairPage(const std::filesystem::path& spec, const std::filesystem::path& out) {
    const std::string why = runPython(interpreter(LAMINA_PAGE_PYTHON), "report_page.py",
                                      {"--pair", spec.string(), "--out", out.string()}, "");
    if (why.empty()) return "";
    return out.string() + " not written (" + why + ")";
}

}  // namespace lamina::experiments
