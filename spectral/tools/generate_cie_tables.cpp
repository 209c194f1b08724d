// Build-time generator: reads the CIE 1931 2-degree colour matching functions and the CIE
// illuminants that Debian's colord-data installs (CGATS-style text files) and writes them as
// C++ tables, so the tables are taken from the package, never copied into the repository.
//
// usage: generate_cie_tables COLORD_DIR OUTPUT.cpp
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Table {
    double startNm = 0, endNm = 0;
    int bands = 0;
    std::vector<std::vector<double>> sets;  // one row of `bands` values per data set
};

[[noreturn]] void fail(const fs::path& file, const std::string& what) {
    std::cerr << "generate_cie_tables: " << file.string() << ": " << what << "\n";
    std::exit(1);
}

Table readCgats(const fs::path& file, int expectedSets) {
    std::ifstream in(file);
    if (!in) fail(file, "cannot open (is the Debian package colord-data installed?)");
    Table t;
    std::string line;
    bool inData = false;
    while (std::getline(in, line)) {
        std::istringstream ls(line);
        std::string key;
        ls >> key;
        if (key == "SPECTRAL_START_NM")
            ls >> t.startNm;
        else if (key == "SPECTRAL_END_NM")
            ls >> t.endNm;
        else if (key == "SPECTRAL_BANDS")
            ls >> t.bands;
        else if (key == "BEGIN_DATA")
            inData = true;
        else if (key == "END_DATA")
            inData = false;
        else if (inData && !key.empty()) {
            std::istringstream row(line);
            std::vector<double> values;
            double v;
            while (row >> v)
                values.push_back(v);
            if (static_cast<int>(values.size()) != t.bands)
                fail(file, "a data row has " + std::to_string(values.size()) +
                               " values, expected " + std::to_string(t.bands));
            t.sets.push_back(std::move(values));
        }
    }
    if (t.bands < 2 || !(t.endNm > t.startNm)) fail(file, "missing or invalid SPECTRAL_* header");
    if (static_cast<int>(t.sets.size()) != expectedSets)
        fail(file, "expected " + std::to_string(expectedSets) + " data sets, found " +
                       std::to_string(t.sets.size()));
    return t;
}

void writeArray(std::ostream& out, const std::string& name, const std::vector<double>& v) {
    out << "const double " << name << "[" << v.size() << "] = {";
    for (std::size_t i = 0; i < v.size(); ++i)
        out << (i % 8 == 0 ? "\n    " : " ") << v[i] << ",";
    out << "\n};\n";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: generate_cie_tables COLORD_DIR OUTPUT.cpp\n";
        return 2;
    }
    const fs::path colord = argv[1];
    const fs::path output = argv[2];

    const Table cmf = readCgats(colord / "cmf" / "CIE1931-2deg-XYZ.cmf", 3);
    std::map<std::string, Table> illuminants;
    for (const auto& entry : fs::directory_iterator(colord / "illuminant")) {
        const std::string stem = entry.path().stem().string();
        if (entry.path().extension() != ".sp" || stem.rfind("CIE-", 0) != 0) continue;
        illuminants.emplace(stem.substr(4), readCgats(entry.path(), 1));
    }
    for (const char* required : {"D65", "A", "E"})
        if (!illuminants.count(required))
            fail(colord / "illuminant",
                 std::string("illuminant CIE-") + required + ".sp is missing");

    const fs::path tmp = output.string() + ".tmp";
    {
        std::ofstream out(tmp);
        out.precision(10);
        out << "// Generated at build time by generate_cie_tables from " << colord.string()
            << " (Debian package colord-data). Do not edit.\n"
            << "#include \"lamina/spectral/cie_tables.h\"\n\nnamespace lamina::cie_data {\n"
            << "namespace {\n";
        writeArray(out, "kCmfXValues", cmf.sets[0]);
        writeArray(out, "kCmfYValues", cmf.sets[1]);
        writeArray(out, "kCmfZValues", cmf.sets[2]);
        for (const auto& [name, t] : illuminants)
            writeArray(out, "kIlluminant" + name, t.sets[0]);
        out << "}  // namespace\n\n";
        auto curve = [&](const Table& t, const std::string& array) {
            std::ostringstream s;
            s.precision(10);
            s << "TabulatedCurve{" << t.startNm << ", " << (t.endNm - t.startNm) / (t.bands - 1)
              << ", std::span<const double>(" << array << ")}";
            return s.str();
        };
        out << "const TabulatedCurve kCmfX = " << curve(cmf, "kCmfXValues") << ";\n"
            << "const TabulatedCurve kCmfY = " << curve(cmf, "kCmfYValues") << ";\n"
            << "const TabulatedCurve kCmfZ = " << curve(cmf, "kCmfZValues") << ";\n"
            << "const NamedCurve kIlluminants[] = {\n";
        for (const auto& [name, t] : illuminants)
            out << "    {\"" << name << "\", " << curve(t, "kIlluminant" + name) << "},\n";
        out << "};\nconst std::span<const NamedCurve> kIlluminantList(kIlluminants);\n"
            << "}  // namespace lamina::cie_data\n";
        if (!out) fail(tmp, "write failed");
    }
    fs::rename(tmp, output);
    return 0;
}
