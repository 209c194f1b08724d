// Ctrl-C and SIGTERM lose no work: the first signal finishes the pass
// in flight and writes the image, marked lamina:partial 1, and lamina exits with 128 + the
// signal (130 for SIGINT); a signal that arrives while the EXR is being written lets the write
// finish; no temporary file is ever left behind. The experiment commands stop before their
// report and write nothing (their results would be incomplete), with the same exit status,
// except what `convergence` has finished (its reference, its finished runs), which it keeps
// for --resume.
#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include "cli_helpers.h"
#include "lamina/image/image_io.h"
#include "lamina/output/image_output.h"
#include "source_files.h"

extern char** environ;

namespace lamina {
namespace {

using namespace std::chrono_literals;

// A scene that takes a while per pass at the resolution given.
std::string scene(int width, int height) {
    return R"({
  "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0]},
  "film": {"resolution": [)" +
           std::to_string(width) + ", " + std::to_string(height) + R"(]},
  "materials": {"m": {"type": "standard", "roughness": 0.3}},
  "shapes": [
    {"type": "sphere", "radius": 1, "material": "m"},
    {"type": "rectangle", "material": "m", "transform": [{"translate": [0, 3, 0]}],
     "emission": {"radiance": 1}}
  ]
})";
}

class Interruption : public CliTest {
  protected:
    void SetUp() override {
        CliTest::SetUp();
        withoutDrawing();
    }
    // Starts lamina with `args` (stdout and stderr to files in the scratch directory).
    pid_t start(const std::vector<std::string>& args) {
        std::vector<std::string> argv = {std::string(LAMINA_BINARY_DIR) + "/app/lamina"};
        argv.insert(argv.end(), args.begin(), args.end());
        std::vector<char*> cargv;
        for (auto& a : argv)
            cargv.push_back(a.data());
        cargv.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, 2, (dir_ / "stderr.txt").c_str(),
                                         O_WRONLY | O_CREAT | O_TRUNC, 0644);
        pid_t pid = -1;
        EXPECT_EQ(posix_spawn(&pid, cargv[0], &actions, nullptr, cargv.data(), environ), 0);
        posix_spawn_file_actions_destroy(&actions);
        return pid;
    }
    // Waits for the process; its exit status (-1 if a signal ended it).
    static int wait(pid_t pid) {
        int status = 0;
        ::waitpid(pid, &status, 0);
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }
    // Temporaries are the hidden files beside the image.
    bool temporaryPresent() const {
        for (const auto& e : fs::directory_iterator(dir_))
            if (e.path().filename().string().rfind(".out", 0) == 0) return true;
        return false;
    }
    std::string stderrText() const {
        std::ifstream in(dir_ / "stderr.txt");
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
};

TEST_F(Interruption, CtrlCDuringATimedRenderWritesAPartialImageAndExits130) {
    const auto s = write("scene.json", scene(32, 32));
    const auto out = dir_ / "out.exr";
    const pid_t pid = start({"render", s, "-o", out.string(), "--time", "60"});
    std::this_thread::sleep_for(1500ms);
    ::kill(pid, SIGINT);
    EXPECT_EQ(wait(pid), 130) << stderrText();
    ASSERT_TRUE(fs::exists(out)) << stderrText();
    const auto img = render::readRgbImage(out);
    EXPECT_EQ(img.metadata.at("lamina:partial"), "1");
    EXPECT_FALSE(temporaryPresent());
}

TEST_F(Interruption, SigtermDuringAnSppRenderWritesAPartialImageAndExits143) {
    const auto s = write("scene.json", scene(32, 32));
    const auto out = dir_ / "out.exr";
    const pid_t pid = start({"render", s, "-o", out.string(), "--spp", "16000000", "-q"});
    std::this_thread::sleep_for(1500ms);
    ::kill(pid, SIGTERM);
    EXPECT_EQ(wait(pid), 143) << stderrText();
    ASSERT_TRUE(fs::exists(out)) << stderrText();
    EXPECT_EQ(render::readRgbImage(out).metadata.at("lamina:partial"), "1");
    EXPECT_FALSE(temporaryPresent());
}

TEST_F(Interruption, ASignalDuringTheExrWriteLetsTheWriteFinish) {
    // A large image of one sample per pixel: the write takes long enough to be caught while
    // the temporary exists.
    const auto s = write("scene.json", scene(2048, 2048));
    const auto out = dir_ / "out.exr";
    const pid_t pid = start({"render", s, "-o", out.string(), "--spp", "1", "--aovs", "-q"});
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while (!temporaryPresent() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(1ms);
    ASSERT_TRUE(temporaryPresent()) << "the write was not seen";
    ::kill(pid, SIGTERM);
    EXPECT_EQ(wait(pid), 143) << stderrText();
    ASSERT_TRUE(fs::exists(out)) << stderrText();
    const auto img = render::readRgbImage(out);
    EXPECT_EQ(img.width, 2048);
    EXPECT_EQ(img.metadata.at("lamina:partial"), "0");  // every requested sample was taken
    EXPECT_FALSE(temporaryPresent());
}

TEST_F(Interruption, ASecondSignalEndsAtOnceAndLeavesNoTemporary) {
    const auto s = write("scene.json", scene(2048, 2048));
    const auto out = dir_ / "out.exr";
    const pid_t pid = start({"render", s, "-o", out.string(), "--spp", "1", "--aovs", "-q"});
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while (!temporaryPresent() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(1ms);
    ASSERT_TRUE(temporaryPresent()) << "the write was not seen";
    ::kill(pid, SIGINT);
    std::this_thread::sleep_for(5ms);
    ::kill(pid, SIGINT);
    int status = 0;
    ::waitpid(pid, &status, 0);
    // Either the write finished between the signals (exit 130, the image complete) or the
    // second signal ended the process (no image); never a temporary left behind.
    if (WIFSIGNALED(status)) {
        EXPECT_EQ(WTERMSIG(status), SIGINT);
        EXPECT_FALSE(fs::exists(out));
    } else {
        EXPECT_EQ(WEXITSTATUS(status), 130);
    }
    EXPECT_FALSE(temporaryPresent());
}

// The experiment commands: the first signal lets the render in flight finish its pass, then
// stops the experiment before its report (half a computation gives misleading numbers), so
// nothing is written, no temporary stays, and lamina exits with 128 + the signal.
TEST_F(Interruption, CtrlCDuringConvergenceStopsWithoutAReportAndExits130) {
    const auto s = write("scene.json", scene(32, 32));
    const auto report = dir_ / "report";
    const pid_t pid = start({"convergence", s, "-o", report.string(), "--integrators", "path",
                             "--modes", "rgb", "--time", "30", "--reference-time", "60"});
    std::this_thread::sleep_for(1500ms);
    ::kill(pid, SIGINT);
    EXPECT_EQ(wait(pid), 130) << stderrText();
    EXPECT_THAT(stderrText(), ::testing::HasSubstr("interrupted by SIGINT"));
    EXPECT_FALSE(fs::exists(report) && !fs::is_empty(report)) << "a report was written";
    EXPECT_FALSE(temporaryPresent());
}

// The reference is the longest render of a convergence run: once rendered it is written at
// once, so a run interrupted during the measured renders keeps it (and says so), and a rerun
// measures against it without rendering it again.
TEST_F(Interruption, CtrlCDuringConvergenceKeepsTheRenderedReference) {
    const auto s = write("scene.json", scene(32, 32));
    const auto report = dir_ / "report";
    const pid_t pid = start({"convergence", s, "-o", report.string(), "--integrators", "path",
                             "--modes", "rgb", "--time", "60", "--reference-time", "1"});
    std::this_thread::sleep_for(5000ms);
    ::kill(pid, SIGINT);
    EXPECT_EQ(wait(pid), 130) << stderrText();
    const fs::path reference = report / "reference_rgb.exr";
    EXPECT_THAT(stderrText(),
                ::testing::HasSubstr("interrupted by SIGINT: stopped before the report; kept " +
                                     reference.string()));
    ASSERT_TRUE(fs::exists(reference));
    EXPECT_FALSE(fs::exists(report / "summary.md"));
    EXPECT_EQ(render::readRgbImage(reference).width, 32);
    EXPECT_FALSE(temporaryPresent());
    const CommandRun rerun =
        runLamina("convergence " + s + " -o " + (dir_ / "rerun").string() +
                  " --integrators path --modes rgb --time 0.5 --reference " + reference.string());
    EXPECT_EQ(rerun.exitCode, 0) << rerun.output;
    EXPECT_TRUE(fs::exists(dir_ / "rerun" / "summary.md"));
}

// Each finished run is kept too (runs/INTEGRATOR_MODE.csv, as soon as it is done): Ctrl-C
// during the second run keeps the reference and the first run, and --resume renders only
// what is missing.
TEST_F(Interruption, CtrlCDuringConvergenceKeepsTheFinishedRunsAndResumeContinues) {
    const auto s = write("scene.json", scene(32, 32));
    const auto report = dir_ / "report";
    const std::vector<std::string> args = {
        "convergence",      s,         "-o",  report.string(), "--integrators",
        "path,light",       "--modes", "rgb", "--time",        "3",
        "--reference-time", "1"};
    const pid_t pid = start(args);
    const fs::path firstRun = report / "runs" / "path_rgb.csv";
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while (!fs::exists(firstRun) && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(20ms);
    ASSERT_TRUE(fs::exists(firstRun)) << "the first run was not kept";
    std::this_thread::sleep_for(300ms);  // into the light run
    ::kill(pid, SIGINT);
    EXPECT_EQ(wait(pid), 130) << stderrText();
    EXPECT_THAT(stderrText(),
                ::testing::HasSubstr("kept " + (report / "reference_rgb.exr").string() + ", " +
                                     firstRun.string()));
    EXPECT_THAT(stderrText(), ::testing::HasSubstr("--resume"));
    EXPECT_FALSE(fs::exists(report / "runs" / "light_rgb.csv"));
    EXPECT_FALSE(fs::exists(report / "summary.md"));
    EXPECT_FALSE(temporaryPresent());

    std::string command;
    for (const std::string& arg : args)
        command += arg + " ";
    const CommandRun resumed = runLaminaStderr(command + "--resume");
    EXPECT_EQ(resumed.exitCode, 0) << resumed.output;
    EXPECT_THAT(resumed.output, ::testing::HasSubstr("path, rgb mode: kept from"));
    EXPECT_THAT(resumed.output, ::testing::HasSubstr("light, rgb mode: 3 s..."));
    EXPECT_THAT(resumed.output,
                ::testing::Not(::testing::HasSubstr("rendering the rgb reference")));
    EXPECT_TRUE(fs::exists(report / "summary.md"));
    EXPECT_TRUE(fs::exists(report / "runs" / "light_rgb.csv"));
}

// Every experiment that renders keeps its finished renders (renders/NAME.exr) the same way:
// Ctrl-C during polarisation's second render keeps the first and names it, --resume renders
// only the others and writes the summary an uninterrupted run writes, and a resume with other
// settings is refused on one line.
TEST_F(Interruption, CtrlCDuringPolarisationKeepsItsRendersAndResumeContinues) {
    const std::string scene = testing::sourceFile("scenes/polarisation/two-mirrors.json").string();
    const auto report = dir_ / "report";
    const std::vector<std::string> args = {"polarisation", scene, "--spp",
                                           "128",          "-o",  report.string()};
    const pid_t pid = start(args);
    const fs::path first = report / "renders" / "polarised.exr";
    const auto deadline = std::chrono::steady_clock::now() + 60s;
    while (!fs::exists(first) && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(5ms);
    ASSERT_TRUE(fs::exists(first)) << "the first render was not kept";
    ::kill(pid, SIGINT);
    EXPECT_EQ(wait(pid), 130) << stderrText();
    EXPECT_THAT(stderrText(),
                ::testing::HasSubstr("stopped before the report; kept " + first.string() +
                                     " (the same command with --resume"));
    EXPECT_FALSE(fs::exists(report / "renders" / "spectral.exr"));
    EXPECT_FALSE(fs::exists(report / "summary.md"));
    EXPECT_FALSE(temporaryPresent());

    std::string command;
    for (const std::string& arg : args)
        command += arg + " ";
    const CommandRun refused = runLaminaStderr(command + "--resume --seed 3");
    EXPECT_EQ(refused.exitCode, 1) << refused.output;
    EXPECT_THAT(refused.output,
                ::testing::HasSubstr("lamina: error: " + first.string() + ": rendered with seed="));
    EXPECT_EQ(std::count(refused.output.begin(), refused.output.end(), '\n'), 1) << refused.output;

    const CommandRun resumed = runLaminaStderr(command + "--resume");
    EXPECT_EQ(resumed.exitCode, 0) << resumed.output;
    EXPECT_THAT(resumed.output,
                ::testing::HasSubstr("polarised mode: kept from renders/polarised.exr"));
    EXPECT_THAT(resumed.output,
                ::testing::HasSubstr("rendering " + scene + " in spectral mode..."));
    EXPECT_FALSE(fs::exists(report / "renders")) << "kept renders left after the report";

    const auto whole = dir_ / "whole";
    const CommandRun uninterrupted =
        runLamina("polarisation " + scene + " --spp 128 -o " + whole.string());
    EXPECT_EQ(uninterrupted.exitCode, 0) << uninterrupted.output;
    const auto text = [](const fs::path& file) {
        std::ifstream in(file);
        return std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    };
    EXPECT_EQ(text(report / "summary.md"), text(whole / "summary.md"));
    EXPECT_THAT(text(report / "summary.md"), ::testing::HasSubstr("noise floor"));
}

// A shard interrupted (a preempted or requeued array task) and run again with the same command
// resumes from its partial output: it keeps the samples it has, renders the rest of its range,
// and the shard equals the one an uninterrupted run writes (the same sums, added in another
// order: equal to float rounding).
TEST_F(Interruption, ARestartedShardResumesFromItsPartialOutput) {
    const auto s = write("scene.json", R"({
  "camera": {"position": [0, 0, -4], "look_at": [0, 0, 0], "fov": 40},
  "film": {"resolution": [32, 32]},
  "materials": {"m": {"type": "standard", "roughness": 0.3}},
  "shapes": [{"type": "sphere", "radius": 1, "material": "m"}],
  "lights": [{"type": "environment", "radiance": 1}]
})");
    const auto shard = dir_ / "shard.exr";
    const std::vector<std::string> args = {"render", s,    "--samples",   "8:12000",
                                           "-q",     "-o", shard.string()};
    const pid_t pid = start(args);
    std::this_thread::sleep_for(1500ms);
    ::kill(pid, SIGINT);
    ASSERT_EQ(wait(pid), 130) << stderrText();
    const render::FloatImage partial = render::readFloatImage(shard);
    ASSERT_EQ(partial.metadata.ints.at("partial"), 1) << "the render ended before the signal";
    const int kept = partial.metadata.ints.at("samples_done");
    ASSERT_GT(kept, 0);

    const pid_t again = start(args);
    EXPECT_EQ(wait(again), 0) << stderrText();
    EXPECT_THAT(stderrText(),
                ::testing::HasSubstr("lamina: resuming " + shard.string() + ": " +
                                     std::to_string(kept) + " of its 12000 samples kept"));
    const render::FloatImage resumed = render::readFloatImage(shard);
    EXPECT_EQ(resumed.metadata.ints.at("partial"), 0);
    EXPECT_EQ(resumed.metadata.ints.at("sample_first"), 8);
    EXPECT_EQ(resumed.metadata.ints.at("sample_count"), 12000);
    EXPECT_EQ(resumed.metadata.ints.at("samples_done"), 12000);

    const auto whole = dir_ / "whole.exr";
    const CommandRun r = runLamina("render " + s + " --samples 8:12000 -q -o " + whole.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const render::FloatImage uninterrupted = render::readFloatImage(whole);
    ASSERT_EQ(resumed.channels, uninterrupted.channels);
    for (const char* name : {"R", "G", "B", "Count.N", "Weight.Sum"}) {
        const int c = resumed.channel(name);
        ASSERT_GE(c, 0) << name;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) {
                const float a = resumed.at(x, y, c), b = uninterrupted.at(x, y, c);
                ASSERT_NEAR(a, b, 1e-5f * std::abs(b) + 1e-9f) << name << " " << x << "," << y;
            }
    }
    EXPECT_FALSE(temporaryPresent());
}

TEST_F(Interruption, SigtermDuringAFresnelSceneRenderExits143WithoutAReport) {
    const auto s = write("scene.json", scene(32, 32));
    const auto report = dir_ / "report";
    const pid_t pid =
        start({"fresnel", "Au", "--scene", s, "--spp", "16000000", "-o", report.string()});
    std::this_thread::sleep_for(1500ms);
    ::kill(pid, SIGTERM);
    EXPECT_EQ(wait(pid), 143) << stderrText();
    EXPECT_THAT(stderrText(), ::testing::HasSubstr("interrupted by SIGTERM"));
    EXPECT_FALSE(fs::exists(report) && !fs::is_empty(report)) << "a report was written";
}

TEST_F(Interruption, SigintDuringALayeringSweepExits130WithoutAReport) {
    // A million walk estimates per point: minutes of work, stopped inside the sweep.
    const auto report = dir_ / "report";
    const pid_t pid =
        start({"layering", "varnished-wood", "--estimates", "1000000", "-o", report.string()});
    std::this_thread::sleep_for(1500ms);
    ::kill(pid, SIGINT);
    EXPECT_EQ(wait(pid), 130) << stderrText();
    EXPECT_THAT(stderrText(), ::testing::HasSubstr("interrupted by SIGINT"));
    EXPECT_FALSE(fs::exists(report) && !fs::is_empty(report)) << "a report was written";
}

}  // namespace
}  // namespace lamina
