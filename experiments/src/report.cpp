#include "lamina/experiments/report.h"

#include <unistd.h>

#include "lamina/core/output_files.h"
#include "lamina/experiments/figure_drawing.h"
#include "lamina/experiments/progress.h"

namespace lamina::experiments {

void printToStderr(const std::string& text) {
    static const bool terminal = ::isatty(STDERR_FILENO) != 0;
    if (!terminal && !text.empty() && text.front() == '\r') {
        if (text.back() != '\n') return;  // transient: a log keeps only the final line
        std::fputs(text.c_str() + 1, stderr);
        return;
    }
    std::fputs(text.c_str(), stderr);
}

Report::Report(std::filesystem::path directory, std::FILE* console)
    : directory_(std::move(directory)), console_(console) {
    checkOutputDirectory(directory_);
}

std::filesystem::path Report::file(const std::string& name) const {
    std::filesystem::create_directories(directory_);
    return directory_ / name;
}

void Report::print(std::string_view text) const {
    if (console_) std::fwrite(text.data(), 1, text.size(), console_);
}

void Report::writeText(const std::string& name, std::string_view text) const {
    writeTextFile(file(name), text);
}

void Report::writeTable(const std::string& name, std::string_view csv,
                        const TablePlot& plot) const {
    writeText(name, csv);
    writeText(std::filesystem::path(name).replace_extension(".py").string(),
              tablePlotScript(name, plot));
}

void Report::finish() const {
    if (figures_) {
        const std::string note = drawFigures(directory_);
        if (!note.empty()) std::fprintf(stderr, "lamina: note: %s\n", note.c_str());
    }
    if (summary_.empty()) return;
    writeText("summary.md", summary_);
    if (const std::string note = writeReportPage(directory_); !note.empty())
        std::fprintf(stderr, "lamina: note: %s\n", note.c_str());
    print(summary_);
}

}  // namespace lamina::experiments
