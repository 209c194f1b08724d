#include "lamina/experiments/result_data.h"

#include <cmath>
#include <stdexcept>

namespace lamina::experiments {

Data Data::number(double v) {
    if (!std::isfinite(v)) return {};
    return Data(v);
}

Data Data::numbers(const std::vector<double>& values) {
    Data out = list();
    for (const double v : values)
        out.append(v);
    return out;
}

Data Data::array(std::vector<double> values, std::vector<std::size_t> shape) {
    DataArray a;
    if (shape.empty()) shape = {values.size()};
    a.doubles = std::move(values);
    a.shape = std::move(shape);
    return Data(std::move(a));
}

Data Data::array(std::vector<int> values, std::vector<std::size_t> shape) {
    DataArray a;
    a.integers = true;
    if (shape.empty()) shape = {values.size()};
    a.ints = std::move(values);
    a.shape = std::move(shape);
    return Data(std::move(a));
}

Data& Data::append(Data item) {
    auto* l = std::get_if<List>(&value_);
    if (!l) throw std::logic_error("Data::append on a value that is not a list");
    l->push_back(std::move(item));
    return *this;
}

Data& Data::set(Data key, Data value) {
    auto* d = std::get_if<Dict>(&value_);
    if (!d) throw std::logic_error("Data::set on a value that is not a dict");
    d->push_back({std::move(key), std::move(value)});
    return *this;
}

}  // namespace lamina::experiments
