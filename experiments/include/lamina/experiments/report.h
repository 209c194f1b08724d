// Where an experiment's report goes: one output directory with summary.md, CSV tables,
// figures and images, index.html (the same report as a page, with a viewer for every pair of
// images compared), and the console (stdout) that echoes the summary. Every experiment writes
// its report through one of these, so they share one ending: finish() writes summary.md and
// the page and prints the summary.
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

#include "lamina/experiments/figure_spec.h"
#include "lamina/experiments/table_plot_script.h"

namespace lamina::experiments {

class Report {
  public:
    /// `console`: where print() and finish() echo (nullptr: nowhere). The directory is
    /// checked now (checkOutputDirectory: InputError before the experiment runs if it cannot
    /// be written) and created when the first file is written.
    explicit Report(std::filesystem::path directory, std::FILE* console = stdout);

    const std::filesystem::path& directory() const { return directory_; }
    /// The path of a file of the report (the directory created if need be).
    std::filesystem::path file(const std::string& name) const;

    /// Text for the console now (an experiment whose output is a running log).
    void print(std::string_view text) const;
    /// Appends Markdown to the summary.
    void addSummary(std::string_view markdown) { summary_ += markdown; }
    const std::string& summary() const { return summary_; }

    /// Writes a text file; InputError if it cannot be written.
    void writeText(const std::string& name, std::string_view text) const;
    /// Writes a CSV table and, beside it (same stem, .py), the matplotlib script that draws
    /// it as `plot` says (table_plot_script.h).
    void writeTable(const std::string& name, std::string_view csv, const TablePlot& plot) const;
    /// A figure's data, NAME.figure.json (figure_spec.h), drawn into NAME.png and NAME.pdf by
    /// finish(); InputError if it cannot be written.
    template <class Figure>
    void addFigure(const std::string& name, const Figure& figure) {
        writeFigureSpec(file(""), name, figure);
        figures_ = true;
    }

    /// Two images the experiment compared, for the page's viewer (figure_spec.h).
    void addImagePair(const std::string& name, const ImagePair& pair) {
        writeImagePairSpec(file(""), name, pair);
    }

    /// The ending: the figures drawn (figure_drawing.h; one note line on stderr where they
    /// cannot be), summary.md, index.html, and the summary on the console. Nothing without a
    /// summary.
    void finish() const;

  private:
    std::filesystem::path directory_;
    std::FILE* console_;
    std::string summary_;
    bool figures_ = false;
};

}  // namespace lamina::experiments
