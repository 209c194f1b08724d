// Drawing a report's figures: the figure module (python/lamina/figures.py) run on the
// report's directory by a Python with matplotlib. The interpreter is $LAMINA_PYTHON, else the
// one the build found with matplotlib (CMake, experiments/CMakeLists.txt); where there is none,
// or it lacks matplotlib, the figures' data stays written and one note line says why.
#pragma once

#include <filesystem>
#include <string>

namespace lamina::experiments {

/// Draws every DIRECTORY/NAME.figure.json (or the one spec file named) into NAME.png and
/// NAME.pdf. Returns "" when they were drawn, else the note to print (one line: why not, and
/// where the data is). The module's own notes (a figure's problems) go to stderr as it prints
/// them.
std::string drawFigures(const std::filesystem::path& specs);

}  // namespace lamina::experiments
