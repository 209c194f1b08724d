#include "pbrt_params.h"

#include <algorithm>
#include <cmath>

#include "lamina/core/error.h"
#include "pbrt_tokenizer.h"

namespace lamina::render::pbrt {

std::string canonicalParamType(const std::string& type) {
    if (type == "point") return "point3";
    if (type == "normal") return "normal3";
    if (type == "vector") return "vector3";
    if (type == "color") return "rgb";
    return type;
}

void ParamList::fail(const Param& p, const std::string& message) const {
    throw InputError(p.location.str() + ": " + owner_ + ": parameter \"" + p.type + " " + p.name +
                     "\" " + message);
}

const Param* ParamList::find(const std::string& name) const {
    for (const Param& p : params_)
        if (p.name == name) {
            p.used = true;
            return &p;
        }
    return nullptr;
}

bool ParamList::has(const std::string& name) const {
    return std::any_of(params_.begin(), params_.end(),
                       [&](const Param& p) { return p.name == name; });
}

void ParamList::expectType(const Param& p, const std::vector<std::string>& types) const {
    const std::string type = canonicalParamType(p.type);
    if (std::find(types.begin(), types.end(), type) != types.end()) return;
    std::string list;
    for (std::size_t i = 0; i < types.size(); ++i)
        list += (i ? (i + 1 == types.size() ? " or " : ", ") : "") + types[i];
    fail(p, "has the wrong type: expected " + list);
}

const Param& ParamList::single(const std::string& name,
                               const std::vector<std::string>& types) const {
    const Param* p = find(name);
    expectType(*p, types);
    const std::size_t count = p->numbers.size() + p->strings.size() + p->bools.size();
    if (count != 1) fail(*p, "expected one value, got " + std::to_string(count));
    return *p;
}

double ParamList::number(const std::string& name, double fallback) const {
    if (!has(name)) return fallback;
    return single(name, {"float"}).numbers[0];
}

int ParamList::integer(const std::string& name, int fallback) const {
    if (!has(name)) return fallback;
    const Param& p = single(name, {"integer"});
    const double v = p.numbers[0];
    // The range first: converting a double outside int's range (or NaN) is undefined.
    if (!(v >= -2147483647.0 && v <= 2147483647.0) || v != std::trunc(v))
        fail(p, "expected an integer");
    return int(v);
}

bool ParamList::boolean(const std::string& name, bool fallback) const {
    if (!has(name)) return fallback;
    return single(name, {"bool"}).bools[0];
}

std::string ParamList::string(const std::string& name, const std::string& fallback) const {
    if (!has(name)) return fallback;
    return single(name, {"string"}).strings[0];
}

std::optional<std::vector<double>> ParamList::numbers(const std::string& name,
                                                      const std::vector<std::string>& types,
                                                      std::size_t arity) const {
    const Param* p = find(name);
    if (!p) return std::nullopt;
    expectType(*p, types);
    if (!p->strings.empty() || !p->bools.empty()) fail(*p, "expected numbers");
    if (p->numbers.empty() || p->numbers.size() % arity != 0)
        fail(*p, "expected a multiple of " + std::to_string(arity) + " numbers, got " +
                     std::to_string(p->numbers.size()));
    return p->numbers;
}

void ParamList::refuseUnused() const {
    for (const Param& p : params_)
        if (!p.used) fail(p, "is not supported");
}

void ParamList::addDefaults(const std::vector<Param>& defaults) {
    for (auto d = defaults.rbegin(); d != defaults.rend(); ++d) {
        if (has(d->name)) continue;
        params_.push_back(*d);
        params_.back().used = true;
    }
}

namespace {

// The parameter types of pbrt-v4's ParameterDictionary (paramdict.cpp) and the older
// spellings it still reads.
const std::vector<std::string> kNumericTypes = {
    "integer", "float", "point2", "vector2", "point3", "vector3", "normal3", "rgb", "blackbody"};

}  // namespace

// "type name" value | [values] ..., until the next directive.
ParamList readParamList(Tokenizer& tokens, const std::string& owner) {
    std::vector<Param> list;
    while (tokens.peek() && tokens.peek()->kind == Token::Kind::String) {
        const Token decl = *tokens.next();
        Param p;
        p.location = {tokens.fileName(), decl.line};
        // White space around the type and the name is allowed, as pbrt-v4 allows it
        // (" float beta_n" in published scenes).
        const auto first = decl.text.find_first_not_of(" \t");
        const auto last = decl.text.find_last_not_of(" \t");
        const std::string text =
            first == std::string::npos ? std::string() : decl.text.substr(first, last - first + 1);
        const auto space = text.find_first_of(" \t");
        const auto nameStart = text.find_first_not_of(" \t", space);
        if (space == std::string::npos || nameStart == std::string::npos ||
            text.find_first_of(" \t", nameStart) != std::string::npos)
            tokens.fail(decl.line,
                        owner + ": expected a parameter \"type name\", got \"" + decl.text + "\"");
        p.type = text.substr(0, space);
        p.name = text.substr(nameStart);
        const std::string type = canonicalParamType(p.type);
        const bool numeric =
            std::find(kNumericTypes.begin(), kNumericTypes.end(), type) != kNumericTypes.end();
        const bool textual = type == "string" || type == "texture";
        if (!numeric && !textual && type != "bool" && type != "spectrum")
            tokens.fail(decl.line, owner + ": parameter \"" + decl.text +
                                       "\" has an unknown type \"" + p.type + "\"");
        auto value = [&](const Token& t) {
            if (t.kind == Token::Kind::Number) {
                if (textual || type == "bool")
                    tokens.fail(t.line, owner + ": parameter \"" + decl.text + "\" expects " +
                                            (type == "bool" ? "true or false" : "strings") +
                                            ", got " + t.text);
                p.numbers.push_back(t.number);
            } else if (type == "bool" && (t.text == "true" || t.text == "false")) {
                p.bools.push_back(t.text == "true");
            } else if (t.kind == Token::Kind::String && (textual || type == "spectrum")) {
                p.strings.push_back(t.text);
            } else {
                tokens.fail(t.line, owner + ": parameter \"" + decl.text +
                                        "\": unexpected value \"" + t.text + "\"");
            }
        };
        auto t = tokens.next();
        if (!t) tokens.fail(decl.line, owner + ": parameter \"" + decl.text + "\" has no value");
        if (t->kind == Token::Kind::OpenBracket) {
            while (true) {
                auto v = tokens.next();
                if (!v)
                    tokens.fail(t->line,
                                owner + ": parameter \"" + decl.text + "\": '[' is not closed");
                if (v->kind == Token::Kind::CloseBracket) break;
                value(*v);
            }
        } else {
            value(*t);
        }
        if (p.numbers.empty() && p.strings.empty() && p.bools.empty())
            tokens.fail(decl.line, owner + ": parameter \"" + decl.text + "\" has no value");
        if (!p.strings.empty() && !p.numbers.empty())
            tokens.fail(decl.line,
                        owner + ": parameter \"" + decl.text + "\" mixes numbers and strings");
        for (const Param& q : list)
            if (q.name == p.name)
                tokens.fail(decl.line, owner + ": parameter \"" + p.name + "\" is given twice");
        list.push_back(std::move(p));
    }
    return ParamList(std::move(list), owner);
}

}  // namespace lamina::render::pbrt
