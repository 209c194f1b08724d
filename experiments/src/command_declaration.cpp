#include "lamina/experiments/command_declaration.h"

#include <algorithm>
#include <stdexcept>

#include "declarations.h"

namespace lamina::experiments {

std::string pythonSpelling(std::string_view name) {
    std::string out(name);
    std::replace(out.begin(), out.end(), '-', '_');
    return out;
}

std::string OptionDecl::commandLineNames() const {
    if (positional) return name;
    return (shortName ? std::string("-") + shortName + "," : std::string()) + "--" + name;
}

OptionDecl& OptionDecl::byDefault(OptionValue value) {
    defaultValue = std::move(value);
    return *this;
}
OptionDecl& OptionDecl::shortFlag(char c) {
    shortName = c;
    return *this;
}
OptionDecl& OptionDecl::asPositional() {
    positional = true;
    return *this;
}
OptionDecl& OptionDecl::asRequired() {
    required = true;
    return *this;
}
OptionDecl& OptionDecl::existing() {
    mustExist = true;
    return *this;
}
OptionDecl& OptionDecl::excluding(std::string other) {
    excludes.push_back(std::move(other));
    return *this;
}
OptionDecl& OptionDecl::needing(std::string other) {
    needs.push_back(std::move(other));
    return *this;
}
OptionDecl& OptionDecl::commandLineOnly(std::string reason) {
    frontEnd = FrontEnd::CommandLine;
    difference = std::move(reason);
    return *this;
}
OptionDecl& OptionDecl::pythonOnly(std::string reason) {
    frontEnd = FrontEnd::Python;
    difference = std::move(reason);
    return *this;
}
OptionDecl& OptionDecl::spelledInPython(std::string spelling, std::string reason) {
    python = std::move(spelling);
    difference = std::move(reason);
    return *this;
}
OptionDecl& OptionDecl::differsInPython(std::string reason) {
    difference = std::move(reason);
    return *this;
}

namespace {

OptionDecl option(std::string name, OptionKind kind, std::string help) {
    OptionDecl o;
    o.python = pythonSpelling(name);
    o.name = std::move(name);
    o.kind = kind;
    o.help = std::move(help);
    return o;
}

}  // namespace

OptionDecl flagOption(std::string name, std::string help) {
    return option(std::move(name), OptionKind::Flag, std::move(help)).byDefault(false);
}
OptionDecl integerOption(std::string name, std::string help, long long min, long long max) {
    OptionDecl o = option(std::move(name), OptionKind::Integer, std::move(help));
    o.minInteger = min;
    o.maxInteger = max;
    return o;
}
OptionDecl numberOption(std::string name, std::string help) {
    return option(std::move(name), OptionKind::Number, std::move(help));
}
OptionDecl numberOption(std::string name, std::string help, double min, double max) {
    OptionDecl o = option(std::move(name), OptionKind::Number, std::move(help));
    o.numberRange = {min, max};
    return o;
}
OptionDecl positiveOption(std::string name, std::string help, std::string unit) {
    OptionDecl o = option(std::move(name), OptionKind::Number, std::move(help));
    o.positiveUnit = std::move(unit);
    return o;
}
OptionDecl textOption(std::string name, std::string help) {
    return option(std::move(name), OptionKind::Text, std::move(help));
}
OptionDecl fileOption(std::string name, std::string help) {
    return option(std::move(name), OptionKind::File, std::move(help));
}
OptionDecl textListOption(std::string name, std::string help) {
    return option(std::move(name), OptionKind::TextList, std::move(help));
}
OptionDecl numberListOption(std::string name, std::string help) {
    return option(std::move(name), OptionKind::NumberList, std::move(help));
}
OptionDecl resolutionOption(std::string name, std::string help) {
    return option(std::move(name), OptionKind::Resolution, std::move(help));
}
OptionDecl callbackOption(std::string name, std::string help) {
    return option(std::move(name), OptionKind::Callback, std::move(help));
}
OptionDecl nameOption(std::string name, std::string help, std::vector<std::string> names) {
    OptionDecl o = option(std::move(name), OptionKind::Name, std::move(help));
    o.names = std::move(names);
    return o;
}
OptionDecl nameListOption(std::string name, std::string help, std::vector<std::string> names,
                          std::string what) {
    OptionDecl o = option(std::move(name), OptionKind::NameList, std::move(help));
    o.names = std::move(names);
    o.what = std::move(what);
    return o;
}

const OptionDecl* CommandDecl::find(std::string_view optionName) const {
    for (const OptionDecl& o : options)
        if (o.name == optionName) return &o;
    return nullptr;
}

const OptionDecl& CommandDecl::option(std::string_view optionName) const {
    if (const OptionDecl* o = find(optionName)) return *o;
    throw std::logic_error("the command " + name + " declares no option " +
                           std::string(optionName));
}

const std::vector<CommandDecl>& commandDeclarations() {
    static const std::vector<CommandDecl> commands = {
        renderDeclaration(),      compareDeclaration(),      reciprocityDeclaration(),
        convergenceDeclaration(), fresnelDeclaration(),      stabilityDeclaration(),
        layeringDeclaration(),    polarisationDeclaration(), mediaDeclaration()};
    return commands;
}

const CommandDecl& commandDeclaration(std::string_view name) {
    for (const CommandDecl& c : commandDeclarations())
        if (c.name == name) return c;
    throw std::logic_error("no command " + std::string(name) + " is declared");
}

}  // namespace lamina::experiments
