#include "declared_options.h"

#include <stdexcept>

#include "option_parsing.h"

namespace lamina::app {

using experiments::OptionDecl;
using experiments::OptionKind;

namespace {

std::string joined(const std::vector<std::string>& items) {
    std::string out;
    for (const auto& item : items)
        out += (out.empty() ? "" : ",") + item;
    return out;
}

}  // namespace

std::string commandLineName(const OptionDecl& option) {
    return option.positional ? option.name : "--" + option.name;
}

DeclaredOptions::DeclaredOptions(CLI::App& cmd, const experiments::CommandDecl& command)
    : command_(command) {
    for (const OptionDecl& o : command.options) {
        if (!o.onCommandLine()) continue;
        Slot& s = slots_.emplace_back();
        s.decl = &o;
        const std::string names = o.commandLineNames();
        const auto& d = o.defaultValue;
        switch (o.kind) {
            case OptionKind::Flag:
                s.option = cmd.add_flag(names, s.flag, o.help);
                break;
            case OptionKind::Integer:
                if (const auto* v = std::get_if<long long>(&d)) s.integer = *v;
                s.option = cmd.add_option(names, s.integer, o.help)
                               ->check(CLI::Range(o.minInteger, o.maxInteger));
                break;
            case OptionKind::Number:
                if (const auto* v = std::get_if<double>(&d)) s.number = *v;
                s.option = cmd.add_option(names, s.number, o.help);
                if (o.positiveUnit)
                    s.option->check(positiveNumber(*o.positiveUnit));
                else if (o.numberRange)
                    s.option->check(CLI::Range(o.numberRange->first, o.numberRange->second));
                break;
            case OptionKind::TextList:
                if (const auto* v = std::get_if<std::vector<std::string>>(&d)) s.texts = *v;
                s.option = cmd.add_option(names, s.texts, o.help);
                break;
            case OptionKind::NameList:
            case OptionKind::NumberList:
                if (const auto* v = std::get_if<std::vector<std::string>>(&d)) s.text = joined(*v);
                s.option = cmd.add_option(names, s.text, o.help);
                break;
            case OptionKind::Name:
                if (const auto* v = std::get_if<std::string>(&d)) s.text = *v;
                s.option = cmd.add_option(names, s.text, o.help)->check(CLI::IsMember(o.names));
                break;
            case OptionKind::Text:
            case OptionKind::File:
            case OptionKind::Resolution:
                if (const auto* v = std::get_if<std::string>(&d)) s.text = *v;
                s.option = cmd.add_option(names, s.text, o.help);
                break;
            case OptionKind::Callback:
                throw std::logic_error(command.name + ": --" + o.name +
                                       ": a callback is Python's alone");
        }
        if (o.mustExist) s.option->check(CLI::ExistingFile);
        if (o.required) s.option->required();
        // A flag's default (off) goes without saying.
        if (o.kind != OptionKind::Flag && !std::holds_alternative<std::monostate>(d))
            s.option->capture_default_str();
    }
    for (const Slot& s : slots_) {
        for (const std::string& other : s.decl->excludes)
            if (CLI::Option* o = option(other)) s.option->excludes(o);
        for (const std::string& other : s.decl->needs)
            if (CLI::Option* o = option(other)) s.option->needs(o);
    }
}

CLI::Option* DeclaredOptions::option(const std::string& name) const {
    for (const Slot& s : slots_)
        if (s.decl->name == name) return s.option;
    return nullptr;
}

experiments::OptionValues DeclaredOptions::values() const {
    experiments::OptionValues values(command_);
    reportingUsageErrors([&] {
        for (const Slot& s : slots_) {
            if (s.option->count() == 0) continue;
            const std::string& name = s.decl->name;
            switch (s.decl->kind) {
                case OptionKind::Flag:
                    values.set(name, s.flag);
                    break;
                case OptionKind::Integer:
                    values.set(name, s.integer);
                    break;
                case OptionKind::Number:
                    values.set(name, s.number);
                    break;
                case OptionKind::TextList:
                    values.set(name, s.texts);
                    break;
                default:
                    values.setText(name, s.text);
            }
        }
        values.finish();
    });
    return values;
}

}  // namespace lamina::app
