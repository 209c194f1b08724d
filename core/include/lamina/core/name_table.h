// The one table of names of an enumeration. Every place that reads a name (the scene and
// material JSON readers, the command line's validators) and every place that prints one
// (metadata, `lamina info`, reports) goes through the enumeration's table, so a new value is
// added in one line and no list of names can fall out of step with another.
//
//   inline constexpr NameTable kIntegratorNames{std::array{
//       NameEntry{IntegratorKind::Path, "path"}, NameEntry{IntegratorKind::Light, "light"}}};
//   kIntegratorNames.name(IntegratorKind::Path)  -> "path"
//   kIntegratorNames.find("light")               -> IntegratorKind::Light
//   kIntegratorNames.list()                      -> "path, light"
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lamina {

template <typename E>
struct NameEntry {
    E value;
    std::string_view name;
};
// Spelt out: clang before 17 does not deduce the arguments of an aggregate template.
template <typename E>
NameEntry(E, const char*) -> NameEntry<E>;

template <typename E, std::size_t N>
class NameTable {
  public:
    constexpr explicit NameTable(std::array<NameEntry<E>, N> entries) : entries_(entries) {}

    /// The name of `value` ("?" for a value missing from the table, which a test forbids).
    constexpr std::string_view name(E value) const {
        for (const auto& e : entries_)
            if (e.value == value) return e.name;
        return "?";
    }
    /// The value called `name`, if any.
    constexpr std::optional<E> find(std::string_view name) const {
        for (const auto& e : entries_)
            if (e.name == name) return e.value;
        return std::nullopt;
    }
    /// Every name in table order, e.g. for a command-line validator.
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const auto& e : entries_)
            out.emplace_back(e.name);
        return out;
    }
    /// Every value in table order (e.g. every integrator, as an experiment's default).
    std::vector<E> values() const {
        std::vector<E> out;
        for (const auto& e : entries_)
            out.push_back(e.value);
        return out;
    }
    /// The names joined for a message: "path, light, bdpt".
    std::string list(std::string_view separator = ", ") const {
        std::string out;
        for (const auto& e : entries_) {
            if (!out.empty()) out += separator;
            out += e.name;
        }
        return out;
    }
    constexpr const std::array<NameEntry<E>, N>& entries() const { return entries_; }
    /// The part of the table that names `values` (e.g. the distributions a lobe supports),
    /// under the same names.
    template <std::size_t M>
    constexpr NameTable<E, M> subset(const std::array<E, M>& values) const {
        std::array<NameEntry<E>, M> out{};
        for (std::size_t i = 0; i < M; ++i)
            out[i] = {values[i], name(values[i])};
        return NameTable<E, M>(out);
    }

  private:
    std::array<NameEntry<E>, N> entries_;
};

template <typename E, std::size_t N>
NameTable(std::array<NameEntry<E>, N>) -> NameTable<E, N>;

}  // namespace lamina
