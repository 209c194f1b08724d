// Mitsuba 3's curve files (mitsuba_curve_file.h), read line by line as mitsuba3's
// bsplinecurve.cpp and linearcurve.cpp read them: leading blanks skipped, a blank line ends a
// curve, any other line four numbers. Mitsuba ignores what follows the fourth number; lamina
// refuses it, so nothing in the file is dropped without a word.
#include "lamina/interchange/mitsuba_curve_file.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <string>

#include "lamina/core/error.h"

namespace lamina::render {

namespace {

bool blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

// The numbers of one line; false when it holds anything else.
bool parseLine(const std::string& line, std::vector<double>& out) {
    out.clear();
    const char* p = line.data();
    const char* end = p + line.size();
    while (true) {
        while (p < end && blank(*p))
            ++p;
        if (p == end) return true;
        if (out.size() == 4) return false;
        double v = 0;
        if (*p == '+') ++p;  // from_chars takes no '+', strtof does
        const auto [next, error] = std::from_chars(p, end, v);
        if (error != std::errc() || (next < end && !blank(*next))) return false;
        out.push_back(v);
        p = next;
    }
}

}  // namespace

CurveFileCurves readMitsubaCurveFile(const std::filesystem::path& file,
                                     std::size_t minPointsPerCurve) {
    const std::string name = file.string();
    std::error_code error;
    const auto size = std::filesystem::file_size(file, error);
    if (error) throw InputError(name + ": cannot open the curve file");
    if (size > kMaxCurveFileBytes)
        throw InputError(name + ": a curve file larger than 256 MiB is not supported (split it)");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(name + ": cannot open the curve file");
    CurveFileCurves curves;
    std::size_t points = 0, number = 0;
    bool open = false;  // the last line was a control point
    const auto finishCurve = [&] {
        if (open && curves.back().size() < minPointsPerCurve)
            throw InputError(name + ":" + std::to_string(number) + ": a curve of " +
                             std::to_string(curves.back().size()) +
                             " control points; each curve takes at least " +
                             std::to_string(minPointsPerCurve));
        open = false;
    };
    std::string line;
    std::vector<double> v;
    while (std::getline(in, line)) {
        ++number;
        if (line.size() >= kMaxCurveFileLine)
            throw InputError(name + ":" + std::to_string(number) + ": a line longer than " +
                             std::to_string(kMaxCurveFileLine) + " characters");
        if (!parseLine(line, v) || (!v.empty() && v.size() != 4))
            throw InputError(name + ":" + std::to_string(number) +
                             ": expected a control point \"x y z radius\" (four numbers) or a "
                             "blank line between curves");
        if (v.empty()) {
            finishCurve();
            continue;
        }
        for (const double x : v)
            if (!std::isfinite(x) || std::abs(x) > 1e15)
                throw InputError(name + ":" + std::to_string(number) +
                                 ": a coordinate or radius that is not finite or beyond 1e15");
        if (v[3] < 0) throw InputError(name + ":" + std::to_string(number) + ": a negative radius");
        if (++points > kMaxCurveFilePoints)
            throw InputError(name + ":" + std::to_string(number) + ": more than " +
                             std::to_string(kMaxCurveFilePoints) +
                             " control points in one curve file (split it into several)");
        if (!open) curves.emplace_back();
        open = true;
        curves.back().push_back({glm::dvec3(v[0], v[1], v[2]), v[3]});
    }
    finishCurve();
    if (curves.empty()) throw InputError(name + ": no control points (an empty curve file)");
    return curves;
}

}  // namespace lamina::render
