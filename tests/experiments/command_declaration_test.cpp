// The commands' declarations (command_declaration.h) and the option values both front ends
// read through them: every difference between the front ends has its reason, names and
// defaults come from the name tables and the experiments' inputs, and a value out of its
// range, a name not in its table, or options given together that exclude each other are
// refused with the option named.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "lamina/experiments/command_declaration.h"
#include "lamina/experiments/command_options.h"
#include "lamina/experiments/convergence.h"
#include "lamina/experiments/reciprocity.h"

namespace lamina::experiments {
namespace {

TEST(CommandDeclarations, NameEveryCommandBothFrontEndsHave) {
    std::vector<std::string> names;
    for (const CommandDecl& c : commandDeclarations())
        names.push_back(c.name);
    EXPECT_THAT(names,
                ::testing::ElementsAre("render", "compare", "reciprocity", "convergence", "fresnel",
                                       "stability", "layering", "polarisation", "media"));
    // The experiments run from both front ends; render and compare have front ends of their
    // own.
    for (const CommandDecl& c : commandDeclarations())
        EXPECT_EQ(bool(c.report), bool(c.data)) << c.name;
    EXPECT_FALSE(commandDeclaration("render").isExperiment());
    EXPECT_TRUE(commandDeclaration("layering").isExperiment());
}

TEST(CommandDeclarations, EveryDifferenceBetweenTheFrontEndsHasItsReason) {
    for (const CommandDecl& c : commandDeclarations()) {
        EXPECT_FALSE(c.help.empty()) << c.name;
        EXPECT_FALSE(c.returns.empty()) << c.name;
        std::set<std::string> names, spellings;
        bool optionalSeen = false;
        for (const OptionDecl& o : c.options) {
            const std::string where = c.name + " --" + o.name;
            EXPECT_TRUE(names.insert(o.name).second) << where << " twice";
            if (o.onPython()) {
                EXPECT_TRUE(spellings.insert(o.python).second) << where;
            }
            EXPECT_FALSE(o.help.empty()) << where;
            const bool differs = o.frontEnd != FrontEnd::Both || o.python != pythonSpelling(o.name);
            if (differs) {
                EXPECT_FALSE(o.difference.empty()) << where << " differs without a reason";
            }
            // Python's parameters: the required ones first.
            if (o.onPython() && !o.required) optionalSeen = true;
            if (o.onPython() && o.required) {
                EXPECT_FALSE(optionalSeen) << where;
            }
            for (const std::string& other : o.excludes)
                EXPECT_NE(c.find(other), nullptr) << where << " excludes " << other;
            for (const std::string& other : o.needs)
                EXPECT_NE(c.find(other), nullptr) << where << " needs " << other;
            if (o.kind == OptionKind::Callback) {
                EXPECT_FALSE(o.onCommandLine()) << where;
            }
        }
    }
}

TEST(CommandDeclarations, DefaultsAreValuesTheOptionsAccept) {
    for (const CommandDecl& c : commandDeclarations())
        for (const OptionDecl& o : c.options) {
            if (std::holds_alternative<std::monostate>(o.defaultValue)) continue;
            OptionValues values(c);
            EXPECT_NO_THROW(values.set(o.name, o.defaultValue)) << c.name << " --" << o.name;
        }
}

TEST(CommandDeclarations, NamesAndDefaultListsComeFromTheNameTables) {
    const CommandDecl& render = commandDeclaration("render");
    EXPECT_EQ(render.option("integrator").names, render::kIntegratorNames.names());
    EXPECT_EQ(render.option("light-selection").names, render::kLightSelectionNames.names());
    EXPECT_EQ(render.option("sampler").names, render::kSamplerNames.names());
    for (const char* command : {"convergence", "reciprocity"}) {
        const OptionDecl& integrators = commandDeclaration(command).option("integrators");
        EXPECT_EQ(std::get<std::vector<std::string>>(integrators.defaultValue),
                  render::kIntegratorNames.names())
            << command;
    }
    EXPECT_EQ(ConvergenceInputs{}.integrators, render::kIntegratorNames.values());
    EXPECT_EQ(ReciprocityInputs{}.integrators, render::kIntegratorNames.values());
}

TEST(CommandDeclarations, PythonSpellsOptionsWithUnderscores) {
    EXPECT_EQ(pythonSpelling("max-depth"), "max_depth");
    EXPECT_EQ(pythonSpelling("allow-correlated-reference"), "allow_correlated_reference");
    EXPECT_EQ(commandDeclaration("render").option("light-selection").python, "light_selection");
    EXPECT_EQ(commandDeclaration("convergence").option("time").python, "seconds");
    EXPECT_EQ(commandDeclaration("render").option("output").commandLineNames(), "-o,--output");
    EXPECT_EQ(commandDeclaration("render").option("scene").commandLineNames(), "scene");
}

// The message of the OptionError that `f` throws, naming its option as `option`.
template <typename F>
std::string refusal(F f, const std::string& option) {
    try {
        f();
    } catch (const OptionError& e) {
        EXPECT_EQ(e.option().name, option);
        return e.what();
    }
    ADD_FAILURE() << "no OptionError for " << option;
    return {};
}

TEST(OptionValues, RefuseValuesOutsideTheDeclaration) {
    OptionValues v(commandDeclaration("render"));
    EXPECT_EQ(refusal([&] { v.set("spp", 0LL); }, "spp"),
              "expected an integer in [1, 16777216], got 0");
    EXPECT_EQ(refusal([&] { v.set("integrator", std::string("photon")); }, "integrator"),
              "expected one of path, light, bdpt, got \"photon\"");
    EXPECT_EQ(refusal([&] { v.setText("resolution", "0x4"); }, "resolution"),
              "expected WIDTHxHEIGHT, each in [1, 65536], e.g. 512x512");
    EXPECT_EQ(refusal([&] { v.set("time", -1.0); }, "time"),
              "expected a positive number of seconds, got -1");
    EXPECT_EQ(refusal([&] { v.set("time", std::nan("")); }, "time"),
              "expected a positive number of seconds, got nan");
    EXPECT_EQ(refusal([&] { v.set("spp", 2.5); }, "spp"), "expected an integer");
    EXPECT_THROW(v.set("no-such-option", true), std::logic_error);

    OptionValues c(commandDeclaration("convergence"));
    EXPECT_EQ(refusal([&] { c.setText("integrators", "path,photon"); }, "integrators"),
              "unknown integrator \"photon\"; expected path, light, bdpt");
    EXPECT_EQ(refusal([&] { c.setText("levels", "1e-2,small"); }, "levels"),
              "expected numbers, got \"small\"");
}

TEST(OptionValues, ExcludedAndNeededOptionsAreRefusedTogether) {
    OptionValues v(commandDeclaration("render"));
    v.set("spp", 4LL);
    v.set("time", 1.0);
    EXPECT_EQ(refusal([&] { v.finish(); }, "time"), "excludes spp (as --time excludes --spp)");
    OptionValues c(commandDeclaration("convergence"));
    c.set("merged", std::string("a.exr"));
    EXPECT_EQ(refusal([&] { c.finish(); }, "merged"), "needs reference");
    c.set("reference", std::string("r.exr"));
    EXPECT_NO_THROW(c.finish());
}

TEST(OptionValues, GiveTheValueElseTheDefault) {
    OptionValues v(commandDeclaration("convergence"));
    EXPECT_EQ(v.number("time"), 10.0);
    EXPECT_FALSE(v.given("time"));
    EXPECT_EQ(v.texts("levels"), (std::vector<std::string>{"1e-2", "1e-3"}));
    v.set("time", 2LL);  // an integer is a number
    EXPECT_EQ(v.number("time"), 2.0);
    EXPECT_TRUE(v.given("time"));
    EXPECT_FALSE(v.text("reference").has_value());
    EXPECT_EQ(v.choices(render::kIntegratorNames, "integrators"),
              render::kIntegratorNames.values());
}

TEST(OptionValues, RenderOptionsAreEveryOverrideBothFrontEndsGive) {
    OptionValues v(commandDeclaration("render"));
    v.set("light-selection", std::string("uniform"));
    v.set("mode", std::string("spectral"));
    v.setText("resolution", "16x24");
    v.set("max-depth", 4LL);
    v.set("aovs", true);
    const render::RenderOptions o = renderOptionsFrom(v);
    EXPECT_EQ(o.lightSelection, render::LightSelection::Uniform);
    EXPECT_EQ(o.mode, render::RenderModeKind::Spectral);
    EXPECT_EQ(o.resolution, (std::pair{16, 24}));
    EXPECT_EQ(o.maxDepth, 4);
    EXPECT_TRUE(o.aovs);
    EXPECT_FALSE(o.spp.has_value());
    EXPECT_EQ(o.threads, 0);  // all cores
    EXPECT_FALSE(o.integrator.has_value());
}

TEST(ResultData, ANumberThatDoesNotExistIsNothing) {
    EXPECT_TRUE(std::holds_alternative<std::monostate>(Data::number(std::nan("")).value()));
    EXPECT_EQ(std::get<double>(Data::number(0.5).value()), 0.5);
    Data d = Data::dict();
    d.set("spp", Data::array(std::vector<int>{1, 2, 4}));
    const auto& entries = std::get<Data::Dict>(d.value());
    ASSERT_EQ(entries.size(), 1u);
    const auto& a = std::get<DataArray>(entries[0].value.value());
    EXPECT_TRUE(a.integers);
    EXPECT_EQ(a.shape, (std::vector<std::size_t>{3}));
    EXPECT_THROW(d.append(1), std::logic_error);
}

}  // namespace
}  // namespace lamina::experiments
