// A pbrt-v4 parameter list ("float radius" 2 "rgb L" [1 1 1] ...) with typed lookups. Every
// lookup marks its parameter used, so that what a translation did not read can be named: an
// importer refuses the parameters it does not understand instead of dropping them.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace lamina::render::pbrt {

/// Where a construct was written: "FILE:LINE".
struct Location {
    std::string file;
    int line = 0;
    std::string str() const { return file + ":" + std::to_string(line); }
};

struct Param {
    std::string type;  ///< as written: float, integer, rgb, spectrum, texture, point3, ...
    std::string name;
    std::vector<double> numbers;
    std::vector<std::string> strings;
    std::vector<bool> bools;
    Location location;
    mutable bool used = false;
};

class ParamList {
  public:
    ParamList() = default;
    /// `owner` names the directive in messages, e.g. `Shape "sphere"`.
    ParamList(std::vector<Param> params, std::string owner)
        : params_(std::move(params)), owner_(std::move(owner)) {}

    /// The parameter called `name` (marked used), or nullptr.
    const Param* find(const std::string& name) const;
    bool has(const std::string& name) const;

    double number(const std::string& name, double fallback) const;  ///< float
    int integer(const std::string& name, int fallback) const;
    bool boolean(const std::string& name, bool fallback) const;
    std::string string(const std::string& name, const std::string& fallback) const;
    /// The numbers of a parameter of one of `types` (e.g. {"point3", "point"}), checking
    /// that their count is a multiple of `arity`; nullopt when it is absent.
    std::optional<std::vector<double>> numbers(const std::string& name,
                                               const std::vector<std::string>& types,
                                               std::size_t arity) const;
    /// A parameter's type must be one of `types`; else an error naming it.
    void expectType(const Param& p, const std::vector<std::string>& types) const;

    /// Refuses every parameter no lookup asked for (`what` names the construct).
    void refuseUnused() const;
    /// pbrt-v4's `Attribute` defaults: each parameter of `defaults` whose name this list does
    /// not have joins it, the later of two defaults of one name first (pbrt-v4's
    /// ParameterDictionary looks the directive's own parameters up first, then the attributes
    /// from the newest). A default no lookup reads is not refused (pbrt-v4's mayBeUnused).
    void addDefaults(const std::vector<Param>& defaults);
    const std::vector<Param>& all() const { return params_; }
    const std::string& owner() const { return owner_; }
    [[noreturn]] void fail(const Param& p, const std::string& message) const;

  private:
    const Param& single(const std::string& name, const std::vector<std::string>& types) const;
    std::vector<Param> params_;
    std::string owner_;
};

/// Canonical spelling of pbrt's aliases (point -> point3, normal -> normal3, vector ->
/// vector3, color -> rgb).
std::string canonicalParamType(const std::string& type);

class Tokenizer;
/// The parameters after a directive: "type name" value | [values] ..., up to the next
/// directive; `owner` ("Shape \"sphere\"") names them in errors.
ParamList readParamList(Tokenizer& tokens, const std::string& owner);

}  // namespace lamina::render::pbrt
