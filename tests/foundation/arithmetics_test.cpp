// The arithmetics list (foundation/arithmetics.hpp): names, runtime choice,
// and the variant over every arithmetic that leaves build through.
#include <catch2/catch.hpp>

#include <string>
#include <type_traits>

#include "foundation/arithmetics.hpp"
#include "foundation/error.hpp"

using namespace lattice;

TEST_CASE("arithmetics: each has the --arith name, and a name chooses its type") {
  CHECK(arithmeticNames() == "float, double, fixed");
  const auto nameOf = [](auto type) { return std::string(arithmeticName<typename decltype(type)::type>()); };
  CHECK(withArithmetic("float", nameOf) == "float");
  CHECK(withArithmetic("double", nameOf) == "double");
  CHECK(withArithmetic("fixed", nameOf) == "fixed");
  CHECK(withArithmetic("fixed", [](auto type) { return std::is_same_v<typename decltype(type)::type, Fixed32>; }));
  CHECK_FALSE(isArithmeticName("half"));
  try {
    withArithmetic("half", nameOf);
    FAIL("an unknown arithmetic was accepted");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Usage);
    CHECK(std::string(e.what()) == "unknown arithmetic 'half'; use one of: float, double, fixed");
  }
}

template <typename T>
struct Slot {
  T value{};
};

TEST_CASE("arithmetics: ArithmeticVariant has one alternative per arithmetic, in list order") {
  using V = ArithmeticVariant<Slot>;
  STATIC_REQUIRE(std::variant_size_v<V> == 3);
  STATIC_REQUIRE(std::is_same_v<std::variant_alternative_t<0, V>, Slot<float>>);
  STATIC_REQUIRE(std::is_same_v<std::variant_alternative_t<2, V>, Slot<Fixed32>>);
  V v{std::in_place_type<Slot<double>>};
  CHECK(v.index() == 1);
}
