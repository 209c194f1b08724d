// Drawing a report's figures and writing its page: the figure module (python/lamina/figures.py)
// and the page module (python/lamina/report_page.py) run on the report's directory by Python.
// The interpreter is $LAMINA_PYTHON, else the one the build found (CMake,
// experiments/CMakeLists.txt: for figures one with matplotlib; the page needs only the standard
// library); where there is none, or figures lack matplotlib, the data stays written and one
// note line says why.
#pragma once

#include <filesystem>
#include <string>

namespace lamina::experiments {

/// Draws every DIRECTORY/NAME.figure.json (or the one spec file named) into NAME.png and
/// NAME.pdf. Returns "" when they were drawn, else the note to print (one line: why not, and
/// where the data is). The module's own notes (a figure's problems) go to stderr as it prints
/// them.
std::string drawFigures(const std::filesystem::path& specs);

/// Writes DIRECTORY/index.html from its summary.md, figures and image pairs (figure_spec.h).
/// Returns "" when written, else the note to print.
std::string writeReportPage(const std::filesystem::path& directory);

/// Writes the viewer of one image pair (NAME.pair.json) as the page `out`. Returns "" when
/// written, else the note to print.
std::string writePairPage(const std::filesystem::path& spec, const std::filesystem::path& out);

}  // namespace lamina::experiments
