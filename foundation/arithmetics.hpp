#pragma once
// The arithmetics: the scalar types the per-pixel path is built for, listed
// once (docs/developing.md, "Adding an arithmetic").
//
// Method: the per-pixel code is templates over a scalar T. Their explicit
// instantiations, and every runtime choice among the types, come from this
// list, so adding an arithmetic means adding it here and writing its
// specialisations (a *_fixed.cpp file for each place where the generic code
// cannot serve it, as render/roots_fixed.cpp does for fixed point).
//   * Arithmetics: a type list, for code that expands over the types
//     (ArithmeticVariant<F>: std::variant<F<float>, F<double>, F<Fixed32>>).
//   * LATTICE_FOR_EACH_ARITHMETIC(X): X(float) X(double) X(Fixed32), for the
//     explicit instantiations a .cpp file provides and its header declares
//     extern. X is a macro of one argument, the type.
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

}  // namespace lattice

#define LATTICE_FOR_EACH_ARITHMETIC(X) X(float) X(double) X(::lattice::Fixed32)
