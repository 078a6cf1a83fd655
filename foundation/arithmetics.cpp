#include "foundation/arithmetics.hpp"

#include <fmt/format.h>

#include "foundation/error.hpp"

namespace lattice {

namespace {

template <typename... Ts>
std::string namesOf(TypeList<Ts...>) {
  std::string names;
  ((names += (names.empty() ? "" : ", ") + std::string(arithmeticName<Ts>())), ...);
  return names;
}

template <typename... Ts>
bool isNameOf(std::string_view name, TypeList<Ts...>) {
  return ((name == arithmeticName<Ts>()) || ...);
}

}  // namespace

std::string arithmeticNames() { return namesOf(Arithmetics{}); }

bool isArithmeticName(std::string_view name) { return isNameOf(name, Arithmetics{}); }

void throwUnknownArithmetic(std::string_view name) {
  throw Error(ErrorKind::Usage, fmt::format("unknown arithmetic '{}'; use one of: {}", name, arithmeticNames()));
}

}  // namespace lattice
