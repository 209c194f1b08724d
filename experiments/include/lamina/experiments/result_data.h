// An experiment's result as plain data (numbers, texts, arrays, lists and dicts), for a
// front end that returns results instead of writing reports: the Python module turns a Data
// into dicts, lists and NumPy arrays without knowing the experiment
// (python/src/experiments_binding.cpp), so an experiment declared in command_declaration.h
// appears in Python with no binding of its own.
#pragma once

#include <concepts>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace lamina::experiments {

/// A row-major array of doubles or of ints with its shape (one dimension when the shape is
/// empty: the values' count).
struct DataArray {
    bool integers = false;  ///< ints (counts, samples per pixel), else doubles
    std::vector<double> doubles;
    std::vector<int> ints;
    std::vector<std::size_t> shape;
};

struct DataEntry;

class Data {
  public:
    using List = std::vector<Data>;
    using Dict = std::vector<DataEntry>;  ///< in insertion order
    using Value =
        std::variant<std::monostate, bool, long long, double, std::string, DataArray, List, Dict>;

    Data() = default;  ///< nothing (Python's None)
    Data(bool v) : value_(v) {}
    template <std::integral T>
    requires(!std::same_as<T, bool>) Data(T v) : value_(static_cast<long long>(v)) {}
    Data(double v) : value_(v) {}
    Data(std::string v) : value_(std::move(v)) {}
    Data(const char* v) : value_(std::string(v)) {}
    Data(std::string_view v) : value_(std::string(v)) {}

    /// A number that does not exist (NaN: a slope with too few points) as nothing.
    static Data number(double v);
    /// The values as a list of numbers.
    static Data numbers(const std::vector<double>& values);
    static Data array(std::vector<double> values, std::vector<std::size_t> shape = {});
    static Data array(std::vector<int> values, std::vector<std::size_t> shape = {});
    static Data list() { return Data(List{}); }
    static Data dict() { return Data(Dict{}); }

    /// Appends to a list.
    Data& append(Data item);
    /// Adds an entry to a dict (keys in the order they are added).
    Data& set(Data key, Data value);

    const Value& value() const { return value_; }

  private:
    explicit Data(List v) : value_(std::move(v)) {}
    explicit Data(Dict v) : value_(std::move(v)) {}
    explicit Data(DataArray v) : value_(std::move(v)) {}
    Value value_;
};

struct DataEntry {
    Data key;
    Data value;
};

}  // namespace lamina::experiments
