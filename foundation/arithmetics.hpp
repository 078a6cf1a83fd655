#pragma once
// The arithmetics: the scalar types the per-pixel path is built for, listed
// once (docs/developing.md, "Adding an arithmetic").
//
// Method: the per-pixel code is templates over a scalar T. Their explicit
// instantiations, and every runtime choice among the types, come from this
// list, so adding an arithmetic means adding it here and writing its
// specialisations (a *_fixed.cpp file for each place where the generic code
// cannot serve it, as render/solve/roots_fixed.cpp does for fixed point).
//   * Arithmetics: a type list, for code that expands over the types
//     (ArithmeticVariant<F>: std::variant<F<float>, F<double>, F<Fixed32>>).
//   * arithmeticName<T>(): the name `--arith` gives it; withArithmetic(name, f)
//     calls f(std::type_identity<T>{}) for the arithmetic of that name.
//   * LATTICE_FOR_EACH_ARITHMETIC(X): X(float) X(double) X(Fixed32), for the
//     explicit instantiations a .cpp file provides and its header declares
//     extern. X is a macro of one argument, the type.
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include "foundation/fixed.hpp"

namespace lattice {

template <typename... Ts>
struct TypeList {};

using Arithmetics = TypeList<float, double, Fixed32>;

namespace detail {
template <template <typename> class F, typename List>
struct VariantOver;
template <template <typename> class F, typename... Ts>
struct VariantOver<F, TypeList<Ts...>> {
  using type = std::variant<F<Ts>...>;
};
}  // namespace detail

// std::variant<F<T>...> over every arithmetic T.
template <template <typename> class F>
using ArithmeticVariant = typename detail::VariantOver<F, Arithmetics>::type;

// The name of an arithmetic on the command line (`--arith`) and in messages.
template <typename T>
constexpr std::string_view arithmeticName();
template <>
constexpr std::string_view arithmeticName<float>() { return "float"; }
template <>
constexpr std::string_view arithmeticName<double>() { return "double"; }
template <>
constexpr std::string_view arithmeticName<Fixed32>() { return "fixed"; }

// "float, double, fixed": for help texts and messages.
std::string arithmeticNames();

namespace detail {
template <typename F, typename T, typename... Rest>
decltype(auto) withArithmetic(std::string_view name, F&& f, TypeList<T, Rest...>) {
  if constexpr (sizeof...(Rest) == 0) {
    return f(std::type_identity<T>{});  // the caller checked the name (isArithmeticName)
  } else {
    if (name == arithmeticName<T>()) return f(std::type_identity<T>{});
    return withArithmetic(name, std::forward<F>(f), TypeList<Rest...>{});
  }
}
}  // namespace detail

bool isArithmeticName(std::string_view name);
[[noreturn]] void throwUnknownArithmetic(std::string_view name);

// Calls f(std::type_identity<T>{}) for the arithmetic named `name`; throws
// lattice::Error(Usage) naming the choices for an unknown name.
template <typename F>
decltype(auto) withArithmetic(std::string_view name, F&& f) {
  if (!isArithmeticName(name)) throwUnknownArithmetic(name);
  return detail::withArithmetic(name, std::forward<F>(f), Arithmetics{});
}

}  // namespace lattice

#define LATTICE_FOR_EACH_ARITHMETIC(X) X(float) X(double) X(::lattice::Fixed32)
