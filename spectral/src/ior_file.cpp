// n/k files (ior_spectrum.h, loadIorFile): refractiveindex.info YAML (tabulated n, k, nk and
// dispersion formulas 1 and 2) and CSV tables, every number checked before it is used.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "dispersion_formulas.h"
#include "lamina/core/error.h"
#include "lamina/core/input_file.h"
#include "lamina/spectral/cie.h"
#include "lamina/spectral/ior_spectrum.h"

namespace lamina {

namespace {

[[noreturn]] void fileError(const std::filesystem::path& p, const std::string& what) {
    throw InputError(p.string() + ": " + what);
}

// A column of an n/k table: its name for messages ("n", "k") and its values.
struct Column {
    const char* name;
    const std::vector<double>& values;
};

// Wavelengths positive and increasing; n and k finite and not negative (a negative k would
// make a conductor amplify light, a negative n has no meaning in the Fresnel equations).
void checkTable(const std::filesystem::path& p, const std::vector<double>& nm,
                std::initializer_list<Column> columns) {
    if (nm.size() < 2) fileError(p, "needs at least two wavelengths");
    for (std::size_t i = 0; i < nm.size(); ++i) {
        if (!std::isfinite(nm[i]) || nm[i] <= 0)
            fileError(p, "row " + std::to_string(i + 1) + ": wavelength is not a positive number");
        if (i > 0 && !(nm[i] > nm[i - 1]))
            fileError(p, "row " + std::to_string(i + 1) + ": wavelengths must increase (" +
                             std::to_string(nm[i - 1]) + " then " + std::to_string(nm[i]) + ")");
        for (const Column& col : columns) {
            const double v = col.values[i];
            if (!std::isfinite(v))
                fileError(p, "row " + std::to_string(i + 1) + ": value is not a finite number (" +
                                 col.name + ")");
            if (v < 0)
                fileError(p, "row " + std::to_string(i + 1) + ": " + col.name + " is negative (" +
                                 std::to_string(v) + "); expected n >= 0 and k >= 0");
        }
    }
}

IorSpectrum loadCsv(const std::filesystem::path& path) {
    std::istringstream in(readInputFile(path, kMaxTextFileBytes));
    std::vector<double> nm, n, k;
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        if (line.empty() || line[0] == '#') continue;
        std::replace(line.begin(), line.end(), ',', ' ');
        // strtod, unlike operator>>, reads "nan" and "inf", which checkTable then rejects
        // with a message that says so.
        std::vector<double> v;
        std::istringstream s(line);
        bool numeric = true;
        for (std::string token; s >> token;) {
            char* end = nullptr;
            const double d = std::strtod(token.c_str(), &end);
            if (end == token.c_str() || *end != '\0') numeric = false;
            v.push_back(d);
        }
        if (!numeric || v.empty()) {
            if (nm.empty()) continue;  // a header line such as "lambda_nm,n,k"
            fileError(path, "line " + std::to_string(lineNo) + ": expected numbers nm, n, k");
        }
        if (v.size() != 3)
            fileError(path, "line " + std::to_string(lineNo) +
                                ": expected three columns (wavelength in nm, n, k)");
        const double a = v[0], b = v[1], c = v[2];
        nm.push_back(a);
        n.push_back(b);
        k.push_back(c);
    }
    checkTable(path, nm, {{"n", n}, {"k", k}});
    const std::string name = path.filename().string();
    const bool dispersive =
        *std::max_element(n.begin(), n.end()) != *std::min_element(n.begin(), n.end());
    return IorSpectrum(name, tabulatedCurve(nm, n, name), tabulatedCurve(nm, k, name), dispersive);
}

// A Sellmeier formula whose pole (l^2 = B_i) lies in the rendered range gives an infinite n
// there and a negative n^2 (clamped to n = 0) beside it: refuse it, and any formula whose
// n^2 is not positive somewhere in the range.
void checkFormula(const std::filesystem::path& p, const std::string& where, int formula,
                  const std::vector<double>& c) {
    for (std::size_t i = 0; i < c.size(); ++i)
        if (!std::isfinite(c[i]))
            fileError(p, where + ": coefficient " + std::to_string(i) + " is not finite");
    for (std::size_t i = 1; i + 1 < c.size(); i += 2) {
        const double b = formula == 1 ? c[i + 1] * c[i + 1] : c[i + 1];
        const double poleNm = b > 0 ? std::sqrt(b) * 1e3 : 0.0;
        if (c[i] != 0 && poleNm >= kLambdaMin && poleNm <= kLambdaMax)
            fileError(p, where + ": the formula has a pole at " + std::to_string(poleNm) +
                             " nm, inside the rendered range [360, 830] nm");
    }
    for (double nm = kLambdaMin; nm <= kLambdaMax; nm += 1.0) {
        const double l2 = (nm * 1e-3) * (nm * 1e-3);
        double n2 = 1.0 + c[0];
        for (std::size_t i = 1; i + 1 < c.size(); i += 2)
            n2 += c[i] * l2 / (l2 - (formula == 1 ? c[i + 1] * c[i + 1] : c[i + 1]));
        if (!(n2 > 0) || !std::isfinite(n2))
            fileError(p, where + ": n^2 is not a positive number at " + std::to_string(nm) + " nm");
    }
}

IorSpectrum readYaml(const std::filesystem::path& path, const std::string& text) {
    const YAML::Node root = YAML::Load(text);
    const YAML::Node data = root["DATA"];
    if (!data || !data.IsSequence() || data.size() == 0)
        fileError(path, "no DATA list (expected a refractiveindex.info database file)");
    std::optional<IorSpectrum::Curve> n, k;
    bool dispersive = false;
    const std::string name = path.filename().string();
    for (std::size_t e = 0; e < data.size(); ++e) {
        const std::string type = data[e]["type"] ? data[e]["type"].as<std::string>() : "";
        const std::string where = "DATA[" + std::to_string(e) + "] (" + type + ")";
        if (type.rfind("tabulated", 0) == 0) {
            const int cols = type == "tabulated nk" ? 3 : 2;
            if (type != "tabulated nk" && type != "tabulated n" && type != "tabulated k")
                fileError(path, where + ": unknown data type");
            std::istringstream s(data[e]["data"] ? data[e]["data"].as<std::string>() : "");
            std::vector<double> nm, a, b;
            std::string line;
            int row = 0;
            while (std::getline(s, line)) {
                if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
                ++row;
                std::istringstream ls(line);
                double l, v1, v2 = 0;
                if (!(ls >> l >> v1) || (cols == 3 && !(ls >> v2)))
                    fileError(path, where + ": row " + std::to_string(row) + ": expected " +
                                        std::to_string(cols) + " columns");
                nm.push_back(l * 1000.0);  // um -> nm
                a.push_back(v1);
                b.push_back(v2);
            }
            if (type == "tabulated nk")
                checkTable(path, nm, {{"n", a}, {"k", b}});
            else
                checkTable(path, nm, {{type == "tabulated n" ? "n" : "k", a}});
            if (type == "tabulated nk" || type == "tabulated n") {
                dispersive |=
                    *std::max_element(a.begin(), a.end()) != *std::min_element(a.begin(), a.end());
                n = tabulatedCurve(nm, a, name);
            }
            if (type == "tabulated nk") k = tabulatedCurve(nm, b, name);
            if (type == "tabulated k") k = tabulatedCurve(nm, a, name);
        } else if (type == "formula 1" || type == "formula 2") {
            std::vector<double> c;
            std::istringstream s(data[e]["coefficients"] ? data[e]["coefficients"].as<std::string>()
                                                         : "");
            for (double v; s >> v;)
                c.push_back(v);
            if (c.empty() || c.size() % 2 == 0)
                fileError(path, where + ": expected an odd number of coefficients");
            checkFormula(path, where, type == "formula 1" ? 1 : 2, c);
            n = formulaCurve(type == "formula 1" ? 1 : 2, c);
            dispersive = true;
        } else {
            fileError(path, where +
                                ": unsupported type (lamina reads tabulated nk, tabulated n, "
                                "tabulated k, formula 1, formula 2)");
        }
    }
    if (!n) fileError(path, "no real index (n) in the DATA list");
    if (!k) k = noAbsorption;
    return IorSpectrum(name, *n, *k, dispersive);
}

// Every yaml-cpp exception (a syntax error, a map where a scalar belongs, a subscript on a
// scalar) becomes an InputError naming the file and, where yaml-cpp knows it, the line.
IorSpectrum loadYaml(const std::filesystem::path& path) {
    const std::string text = readInputFile(path, kMaxTextFileBytes);
    try {
        return readYaml(path, text);
    } catch (const YAML::Exception& e) {
        const std::string where =
            e.mark.is_null() ? std::string() : " at line " + std::to_string(e.mark.line + 1);
        fileError(path, "malformed YAML" + where + ": " + (e.msg.empty() ? e.what() : e.msg));
    }
}

}  // namespace

IorSpectrum loadIorFile(const std::filesystem::path& path) {
    checkInputFile(path, kMaxTextFileBytes);
    const std::string ext = path.extension().string();
    if (ext == ".yml" || ext == ".yaml") return loadYaml(path);
    if (ext == ".csv" || ext == ".txt") return loadCsv(path);
    fileError(path, "unknown n/k file type \"" + ext + "\" (expected .yml, .yaml or .csv)");
}

}  // namespace lamina
