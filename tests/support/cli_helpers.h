// Running the `lamina` binary from tests, and a fixture with a scratch directory.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace lamina {

namespace fs = std::filesystem;

struct CommandRun {
    int exitCode;
    std::string output;  // stdout and stderr
};

/// `streams`: which of its output the run captures (default stdout and stderr).
inline CommandRun runLamina(const std::string& args, const std::string& input = "",
                            const std::string& streams = " 2>&1") {
    std::string redirect;
    if (!input.empty()) {
        const fs::path in =
            fs::temp_directory_path() / ("lamina-cli-stdin-" + std::to_string(::getpid()));
        std::ofstream(in) << input << "\n";
        redirect = " < " + in.string();
    }
    const std::string cmd =
        std::string(LAMINA_BINARY_DIR) + "/app/lamina " + args + redirect + streams;
    FILE* pipe = ::popen(cmd.c_str(), "r");
    std::string out;
    std::array<char, 4096> buf{};
    while (pipe && std::fgets(buf.data(), int(buf.size()), pipe))
        out += buf.data();
    const int status = pipe ? ::pclose(pipe) : -1;
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

/// Runs lamina with stdout discarded: `output` is what it printed on stderr alone.
inline CommandRun runLaminaStderr(const std::string& args, const std::string& input = "") {
    return runLamina(args, input, " 2>&1 >/dev/null");
}

/// The numeric rows of a CSV file an experiment wrote, its header line skipped.
inline std::vector<std::vector<double>> readCsv(const fs::path& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);  // header
    std::vector<std::vector<double>> rows;
    while (std::getline(in, line)) {
        std::stringstream s(line);
        std::vector<double> row;
        for (std::string field; std::getline(s, field, ',');)
            row.push_back(std::stod(field));
        rows.push_back(std::move(row));
    }
    return rows;
}

/// An 8 x 8 scene that renders in milliseconds: a Lambertian sphere under a rectangle light.
inline const char* const kLitSphereScene = R"({
  "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0]},
  "film": {"resolution": [8, 8]},
  "materials": {"m": {"type": "lambert"}},
  "shapes": [
    {"type": "sphere", "radius": 1, "material": "m"},
    {"type": "rectangle", "material": "m", "transform": [{"translate": [0, 3, 0]}],
     "emission": {"radiance": 1}}
  ]
})";

class CliTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("lamina-cli-" + std::to_string(::getpid()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        fs::remove_all(dir_);
        if (savedPython_) {
            if (savedPython_->empty())
                ::unsetenv("LAMINA_PYTHON");
            else
                ::setenv("LAMINA_PYTHON", savedPython_->c_str(), 1);
        }
    }

    /// For tests of an experiment's numbers and files, not of its figures: the runs of this
    /// test get `true` as their Python, so figures.py and report_page.py do nothing
    /// (tests/python/test_figures.py runs the same experiments, then draws and inspects every
    /// figure). Drawing took a third of these tests' time.
    void withoutDrawing() {
        const char* old = std::getenv("LAMINA_PYTHON");
        if (!savedPython_) savedPython_ = old ? old : "";
        ::setenv("LAMINA_PYTHON", "true", 1);
    }

    std::string write(const std::string& name, const std::string& text) {
        const fs::path p = dir_ / name;
        std::ofstream(p) << text;
        return p.string();
    }
    std::size_t filesIn() const {
        return std::size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
    }

    fs::path dir_;

  private:
    std::optional<std::string> savedPython_;  ///< LAMINA_PYTHON before withoutDrawing ("": unset)
};

}  // namespace lamina
