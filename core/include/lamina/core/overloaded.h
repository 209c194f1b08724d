// One visitor made of several lambdas, one per alternative of a std::variant:
//
//   std::visit(Overloaded{[](const MeshDesc& m) { ... }, [](const SphereDesc& s) { ... }}, shape);
//
// A variant that gains an alternative without a lambda for it no longer compiles, so every
// place that treats each kind of a thing on its own is found by the compiler.
#pragma once

namespace lamina {

template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
// Spelt out: clang before 17 does not deduce the arguments of an aggregate template.
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

}  // namespace lamina
