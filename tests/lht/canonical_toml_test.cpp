// The canonical text a lattice's cache key is computed from: our
// own walk of the TOML values, never a formatter's output.
#include <catch2/catch.hpp>

#include <toml++/toml.h>

#include "loader/canonical_toml.hpp"

using namespace lattice::lht;

namespace {
std::string canonical(std::string_view text) { return canonicalToml(toml::parse(text)); }
}  // namespace

TEST_CASE("canonical TOML: the documented form, exact doubles, sorted keys") {
  CHECK(canonical("b = [[0.00049, 2], 'x']\na = true\n") ==
        "{1:a=b1;1:b=[[f3f400e6afcce1c58,i2,],s1:x,];}");
  // Small numbers in nested arrays (what overflowed toml++'s formatter) keep
  // every bit: two doubles one ulp apart give different text.
  CHECK(canonical("p = [[1e-300]]") != canonical("p = [[1.0000000000000002e-300]]"));
  CHECK(canonical("p = [[0.1]]") != canonical("p = [[0.10000000000000002]]"));
  // Order and spelling do not matter; types do.
  CHECK(canonical("a = 1\nb = \"s\"") == canonical("b = 's'\na = 0x1"));
  CHECK(canonical("a = 1") != canonical("a = 1.0"));
  CHECK(canonical("t = { x = 1, y = 2 }") == canonical("[t]\ny = 2\nx = 1"));
  CHECK(canonicalDouble(-0.0) != canonicalDouble(0.0));
}
