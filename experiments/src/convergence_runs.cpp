#include "lamina/experiments/convergence_runs.h"

#include <fstream>
#include <sstream>

#include "lamina/core/error.h"
#include "lamina/core/output_files.h"
#include "lamina/experiments/text_format.h"

namespace lamina::experiments {

namespace {

constexpr const char* kRowHeader = "seconds,spp,mse,rmse,relmse,mae,max,compared,non_finite";

/// Every double with 17 significant digits: read back, it is the same double.
std::string exact(double v) {
    return formatText("%.17g", v);
}

}  // namespace

RunSettings runSettings(const ConvergenceInputs& in, const render::SceneDesc& scene,
                        const render::RgbImage& reference) {
    const render::RenderOptions& o = in.overrides;
    double pixelSum = 0;
    for (const float v : reference.pixels)
        pixelSum += double(v);
    const int width = o.resolution ? o.resolution->first : scene.film.width;
    const int height = o.resolution ? o.resolution->second : scene.film.height;
    return {
        {"time", exact(in.seconds)},
        {"scene_hash", render::sceneHash(scene)},
        {"max_depth", std::to_string(o.maxDepth.value_or(scene.settings.maxDepth))},
        {"resolution", std::to_string(width) + "x" + std::to_string(height)},
        {"sampler",
         std::string(render::kSamplerNames.name(o.sampler.value_or(scene.settings.sampler)))},
        {"seed", std::to_string(o.seed.value_or(scene.settings.seed))},
        {"reference", std::to_string(reference.width) + "x" + std::to_string(reference.height) +
                          " sum " + exact(pixelSum)},
    };
}

std::filesystem::path runFile(render::IntegratorKind integrator, render::RenderModeKind mode) {
    return std::filesystem::path("runs") /
           (std::string(render::kIntegratorNames.name(integrator)) + "_" +
            std::string(render::kRenderModeNames.name(mode)) + ".csv");
}

void writeRunFile(const std::filesystem::path& directory, const ConvergenceCurve& run,
                  const RunSettings& settings) {
    std::string text = "# a finished run of lamina convergence (--resume takes it back)\n";
    text += "# paths_per_second=" + exact(run.pathsPerSecond) + "\n";
    text += "# spp=" + std::to_string(run.spp) + "\n";
    for (const auto& [key, value] : settings)
        text += "# " + key + "=" + value + "\n";
    text += std::string(kRowHeader) + "\n";
    for (const ErrorLog::Row& r : run.log.rows())
        text += exact(r.seconds) + "," + std::to_string(r.spp) + "," + exact(r.metrics.mse) + "," +
                exact(r.metrics.rmse) + "," + exact(r.metrics.relmse) + "," + exact(r.metrics.mae) +
                "," + exact(r.metrics.max) + "," + std::to_string(r.metrics.compared) + "," +
                std::to_string(r.metrics.nonFinite) + "\n";
    const std::filesystem::path path = directory / runFile(run.integrator, run.mode);
    std::filesystem::create_directories(path.parent_path());
    writeTextFile(path, text);
}

std::optional<ConvergenceCurve> readRunFile(const std::filesystem::path& directory,
                                            render::IntegratorKind integrator,
                                            render::RenderModeKind mode,
                                            const RunSettings& settings,
                                            const render::RgbImage& reference) {
    const std::filesystem::path path = directory / runFile(integrator, mode);
    if (!std::filesystem::exists(path)) return std::nullopt;
    std::ifstream in(path);
    if (!in) throw InputError(path.string() + ": cannot be read");
    ConvergenceCurve run{integrator, mode, ErrorLog(reference), 0, 0};
    RunSettings found;
    std::vector<ErrorLog::Row> rows;
    int lineNumber = 0;
    const auto bad = [&](const std::string& what) {
        return InputError(path.string() + ":" + std::to_string(lineNumber) + ": " + what);
    };
    bool header = false;
    for (std::string line; std::getline(in, line);) {
        ++lineNumber;
        if (line.rfind("# ", 0) == 0) {
            const std::size_t eq = line.find('=');
            if (eq == std::string::npos) continue;  // the comment line
            found.emplace_back(line.substr(2, eq - 2), line.substr(eq + 1));
            continue;
        }
        if (!header) {
            if (line != kRowHeader) throw bad(std::string("expected the header ") + kRowHeader);
            header = true;
            continue;
        }
        std::istringstream fields(line);
        std::vector<std::string> f;
        for (std::string field; std::getline(fields, field, ',');)
            f.push_back(field);
        try {
            if (f.size() != 9) throw std::invalid_argument("fields");
            ErrorLog::Row r{std::stod(f[0]), std::stoi(f[1]), {}};
            r.metrics.mse = std::stod(f[2]);
            r.metrics.rmse = std::stod(f[3]);
            r.metrics.relmse = std::stod(f[4]);
            r.metrics.mae = std::stod(f[5]);
            r.metrics.max = std::stod(f[6]);
            r.metrics.compared = std::stoull(f[7]);
            r.metrics.nonFinite = std::stoull(f[8]);
            rows.push_back(r);
        } catch (const std::exception&) {
            throw bad("expected 9 numbers: " + std::string(kRowHeader));
        }
    }
    if (!header || rows.empty()) throw bad("expected the rows of a finished run");
    const auto value = [&](const std::string& key) -> std::optional<std::string> {
        for (const auto& [k, v] : found)
            if (k == key) return v;
        return std::nullopt;
    };
    for (const auto& [key, expected] : settings) {
        const std::optional<std::string> v = value(key);
        if (v != expected)
            throw InputError(path.string() + ": the run was rendered with " + key + " " +
                             v.value_or("(none)") + ", this one has " + expected +
                             ": resume with the same options, or remove the file to render "
                             "the run again");
    }
    try {
        run.pathsPerSecond = std::stod(value("paths_per_second").value_or(""));
        run.spp = std::stoi(value("spp").value_or(""));
    } catch (const std::exception&) {
        throw InputError(path.string() + ": expected the lines # paths_per_second= and # spp=");
    }
    run.log = ErrorLog(reference, std::move(rows));
    return run;
}

}  // namespace lamina::experiments
