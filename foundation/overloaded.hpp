#pragma once
// A visitor made of lambdas, one per alternative of a std::variant:
// std::visit(Overloaded{[](const A&) {...}, [](const B&) {...}}, v).
//
// Method: the lambdas' call operators become one overload set. Why: a visit
// that must handle every alternative lists each by type, with no catch-all,
// so an alternative added later without its lambda fails to compile instead
// of falling through to a default.

namespace lattice {

template <typename... Lambdas>
struct Overloaded : Lambdas... {
  using Lambdas::operator()...;
};
template <typename... Lambdas>
Overloaded(Lambdas...) -> Overloaded<Lambdas...>;

}  // namespace lattice
