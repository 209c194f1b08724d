// A small matplotlib script written beside each CSV table an experiment writes, so a user
// can turn the table into a publication figure (PDF, PGF, PNG, with their own styling)
// with their own choices: `python3 convergence.py [out.pdf]`. The script reads the
// CSV next to it by name, so the two can be moved together.
#pragma once

#include <string>
#include <vector>

namespace lamina::experiments {

/// What the script draws: the `y` columns against `x`, one line per distinct value of the
/// `groupBy` columns (and per y column when there are several), with axis labels and units. A
/// column NAME_se is drawn as the standard-error band around NAME, not as a line of its own.
struct TablePlot {
    std::string title;
    std::string x;               ///< column name
    std::vector<std::string> y;  ///< column names; empty: every column but x and groupBy
    std::vector<std::string> groupBy;
    std::string xLabel, yLabel;  ///< with units
    bool logX = false, logY = false;
};

/// The Python source of the script for the table `csvName` (a file name, no directory).
std::string tablePlotScript(const std::string& csvName, const TablePlot& plot);

}  // namespace lamina::experiments
