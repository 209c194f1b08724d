#include "pbrt_params.h"

#include <algorithm>

#include "lamina/core/error.h"

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
    if (v != double(int(v)) || v < -2147483647.0 || v > 2147483647.0)
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

}  // namespace lamina::render::pbrt
