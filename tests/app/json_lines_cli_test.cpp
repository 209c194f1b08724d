// JSON Lines output is always valid JSON: every line `lamina bsdf
// eval|sample|albedo` and `lamina spectrum` print parses, and no number in it is missing
// (a NaN would print as null), for extreme materials: smooth and rough along one axis,
// grazing and opposite directions, index-matched glass, zero and huge k.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

#include "cli_helpers.h"
#include "lamina/core/json_reader.h"

namespace lamina {
namespace {

// Every line of `output` as JSON; fails the test for a line that does not parse.
std::vector<Json> parseLines(const std::string& output, const std::string& what) {
    std::vector<Json> out;
    std::istringstream in(output);
    for (std::string line; std::getline(in, line);) {
        const Json j = Json::parse(line, nullptr, false);
        EXPECT_FALSE(j.is_discarded()) << what << ": not JSON: " << line;
        out.push_back(j);
    }
    EXPECT_FALSE(out.empty()) << what << ": no output";
    return out;
}

// Counts the nulls among the values of `j`, recursively (a NaN or Inf prints as null).
int nulls(const Json& j) {
    if (j.is_null()) return 1;
    int n = 0;
    if (j.is_structured())
        for (const auto& v : j)
            n += nulls(v);
    return n;
}

const char* const kMaterials[] = {
    R"({"type":"conductor","alpha_x":0,"alpha_y":1,"eta":0.2,"k":3})",
    R"({"type":"conductor","distribution":"beckmann","alpha_x":1,"alpha_y":0,"eta":0.2,"k":3})",
    R"({"type":"conductor","alpha":1,"eta":1,"k":0})",
    R"({"type":"conductor","alpha":0,"eta":0.2,"k":1000})",
    R"({"type":"dielectric","alpha_x":0,"alpha_y":0.7,"ior":1.5})",
    R"({"type":"dielectric","alpha":0.3,"ior":1})",
    R"({"type":"dielectric","alpha":1,"ior":4})",
    R"({"type":"standard","alpha_x":0,"alpha_y":1,"metalness":1})",
    R"({"type":"standard","roughness":1,"transmission":1})",
    R"({"type":"oren_nayar","roughness":1,"reflectance":1})"};

// Directions at the pole, the horizon, below it, grazing, and equal or opposite to wo.
const char* const kDirections =
    R"({"wo":[0,0,1],"wi":[0,0,1]}
{"wo":[0.3,0.1,1],"wi":[-0.3,-0.1,1]}
{"wo":[1,0,0],"wi":[0,1,0]}
{"wo":[1,0,1e-7],"wi":[-1,0,1e-7]}
{"wo":[0.2,0.5,1],"wi":[0.2,0.5,1]}
{"wo":[0.2,0.5,1],"wi":[-0.2,-0.5,-1]}
{"wo":[0,0.6,0.8],"wi":[0,-0.6,-0.8]}
{"wo":[0,0,-1],"wi":[0.5,0,-1]}
{"wo":[0.7,0,0.7],"wi":[0,0.7,0.7]})";

TEST(JsonLines, BsdfCommandsPrintOnlyValidJsonWithoutNaN) {
    for (const char* material : kMaterials) {
        const std::string m = std::string("'") + material + "'";
        const CommandRun evalOut = runLamina("bsdf eval " + m, kDirections, " 2>/dev/null");
        ASSERT_EQ(evalOut.exitCode, 0) << material;
        const auto lines = parseLines(evalOut.output, std::string("eval ") + material);
        EXPECT_EQ(lines.size(), 9u) << material;
        for (const Json& j : lines)
            EXPECT_EQ(nulls(j), 0) << material << ": " << j.dump();
        for (const char* wo : {"0,0,1", "1,0,1e-7", "0.3,-0.2,1", "0,0,-1"}) {
            const CommandRun s =
                runLamina("bsdf sample " + m + " --wo " + wo + " --count 64", "", " 2>/dev/null");
            ASSERT_EQ(s.exitCode, 0) << material;
            for (const Json& j : parseLines(s.output, std::string("sample ") + material)) {
                if (j.at("wi").is_null()) continue;  // {"wi":null}: no sample, as documented
                EXPECT_EQ(nulls(j), 0) << material << " wo " << wo << ": " << j.dump();
            }
        }
        const CommandRun a = runLamina("bsdf albedo " + m + " --samples 2000", "", " 2>/dev/null");
        ASSERT_EQ(a.exitCode, 0) << material;
        for (const Json& j : parseLines(a.output, std::string("albedo ") + material))
            EXPECT_EQ(nulls(j), 0) << material << ": " << j.dump();
    }
}

TEST(JsonLines, SpectrumPrintsOnlyJsonLines) {
    for (const char* name : {"Au", "bk7", "D65", "blackbody:6500", "blackbody:1", "water"}) {
        const CommandRun r =
            runLamina(std::string("spectrum ") + name + " --rgb --wavelengths 1,360,555,830,100000",
                      "", " 2>/dev/null");
        ASSERT_EQ(r.exitCode, 0) << name << ": " << r.output;
        const auto lines = parseLines(r.output, name);
        ASSERT_GE(lines.size(), 7u) << name;
        EXPECT_TRUE(lines.front().at("spectrum").is_string()) << lines.front().dump();
        for (const Json& j : lines)
            EXPECT_EQ(nulls(j), 0) << name << ": " << j.dump();
    }
}

}  // namespace
}  // namespace lamina
