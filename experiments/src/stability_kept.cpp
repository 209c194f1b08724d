#include "stability_kept.h"

#include <cmath>
#include <fstream>
#include <limits>

#include <nlohmann/json.hpp>

#include "lamina/core/error.h"
#include "lamina/experiments/text_format.h"

namespace lamina::experiments {

namespace {

using nlohmann::json;

/// JSON has no Inf or NaN: those are kept as strings.
json number(double v) {
    if (std::isfinite(v)) return v;
    if (std::isnan(v)) return "nan";
    return v > 0 ? "inf" : "-inf";
}

double numberFrom(const json& j) {
    if (j.is_number()) return j.get<double>();
    const std::string s = j.get<std::string>();
    if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
    throw std::invalid_argument("not a number: " + s);
}

json numbers(const std::vector<double>& values) {
    json a = json::array();
    for (double v : values)
        a.push_back(number(v));
    return a;
}

std::vector<double> numbersFrom(const json& j) {
    std::vector<double> v;
    for (const json& e : j)
        v.push_back(numberFrom(e));
    return v;
}

json cellJson(const StabilityCell& c) {
    return {{"evaluations", c.evaluations},
            {"samples", c.samples},
            {"nan", c.nan},
            {"inf", c.inf},
            {"negative", c.negative},
            {"weight_mismatch", c.weightMismatch},
            {"energy_gain", c.energyGain},
            {"worst_float_error", number(c.worstFloatError)}};
}

StabilityCell cellFrom(const json& j) {
    StabilityCell c;
    c.evaluations = j.at("evaluations").get<int>();
    c.samples = j.at("samples").get<int>();
    c.nan = j.at("nan").get<int>();
    c.inf = j.at("inf").get<int>();
    c.negative = j.at("negative").get<int>();
    c.weightMismatch = j.at("weight_mismatch").get<int>();
    c.energyGain = j.at("energy_gain").get<int>();
    c.worstFloatError = numberFrom(j.at("worst_float_error"));
    return c;
}

json probeJson(const PolarisedProbe& p) {
    return {{"what", p.what},
            {"cos_theta", number(p.cosTheta)},
            {"alpha", number(p.alpha)},
            {"evaluations", p.evaluations},
            {"nan", p.nan},
            {"inf", p.inf},
            {"jump_float", number(p.jumpFloat)},
            {"jump_double", number(p.jumpDouble)}};
}

PolarisedProbe probeFrom(const json& j) {
    PolarisedProbe p;
    p.what = j.at("what").get<std::string>();
    p.cosTheta = numberFrom(j.at("cos_theta"));
    p.alpha = numberFrom(j.at("alpha"));
    p.evaluations = j.at("evaluations").get<int>();
    p.nan = j.at("nan").get<int>();
    p.inf = j.at("inf").get<int>();
    p.jumpFloat = numberFrom(j.at("jump_float"));
    p.jumpDouble = numberFrom(j.at("jump_double"));
    return p;
}

json auditJson(const AuditedModel& m, int samples) {
    json cells = json::array();
    for (const StabilityCell& c : m.audit.cells)
        cells.push_back(cellJson(c));
    json probes = json::array();
    for (const PolarisedProbe& p : m.polarised.probes)
        probes.push_back(probeJson(p));
    const PolarisedStabilityReport& p = m.polarised;
    return {{"material", m.json},
            {"samples", samples},
            {"alphas", numbers(m.audit.alphas)},
            {"cosines", numbers(m.audit.cosines)},
            {"cells", std::move(cells)},
            {"polarised",
             {{"probes", std::move(probes)},
              {"evaluations", p.evaluations},
              {"nan", p.nan},
              {"inf", p.inf},
              {"worst_jump_float", number(p.worstJumpFloat)},
              {"worst_jump_double", number(p.worstJumpDouble)},
              {"discontinuities", p.discontinuities}}}};
}

AuditedModel auditFrom(const json& j) {
    AuditedModel m;
    m.json = j.at("material").get<std::string>();
    m.audit.alphas = numbersFrom(j.at("alphas"));
    m.audit.cosines = numbersFrom(j.at("cosines"));
    for (const json& c : j.at("cells"))
        m.audit.cells.push_back(cellFrom(c));
    if (m.audit.cells.size() != m.audit.alphas.size() * m.audit.cosines.size())
        throw std::invalid_argument("cells do not cover alphas x cosines");
    const json& p = j.at("polarised");
    for (const json& q : p.at("probes"))
        m.polarised.probes.push_back(probeFrom(q));
    m.polarised.evaluations = p.at("evaluations").get<int>();
    m.polarised.nan = p.at("nan").get<int>();
    m.polarised.inf = p.at("inf").get<int>();
    m.polarised.worstJumpFloat = numberFrom(p.at("worst_jump_float"));
    m.polarised.worstJumpDouble = numberFrom(p.at("worst_jump_double"));
    m.polarised.discontinuities = p.at("discontinuities").get<int>();
    return m;
}

}  // namespace

std::filesystem::path keptAuditFile(std::size_t index) {
    return std::filesystem::path("renders") / formatText("model%02zu_audit.json", index);
}

void writeKeptAudit(const std::filesystem::path& path, const AuditedModel& model, int samples) {
    std::filesystem::create_directories(path.parent_path());
    std::filesystem::path temporary = path;
    temporary += ".part";
    {
        std::ofstream out(temporary);
        out << auditJson(model, samples).dump() << '\n';
        if (!out) throw InputError(temporary.string() + ": cannot write the kept audit");
    }
    std::filesystem::rename(temporary, path);
}

AuditedModel readKeptAudit(const std::filesystem::path& path, const std::string& materialJson,
                           int samples) {
    const std::string remedy =
        ": resume with the same options, or remove the directory's renders/ to audit again";
    json j;
    AuditedModel m;
    int keptSamples = 0;
    try {
        std::ifstream in(path);
        j = json::parse(in);
        m = auditFrom(j);
        keptSamples = j.at("samples").get<int>();
    } catch (const std::exception&) {
        throw InputError(path.string() + ": not a whole kept audit of lamina stability" + remedy);
    }
    if (m.json != materialJson)
        throw InputError(path.string() + ": audited " + m.json + ", this run asks for " +
                         materialJson + remedy);
    if (keptSamples != samples)
        throw InputError(path.string() + ": audited with samples=" + std::to_string(keptSamples) +
                         ", this run asks for samples=" + std::to_string(samples) + remedy);
    return m;
}

}  // namespace lamina::experiments
