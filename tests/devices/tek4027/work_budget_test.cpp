// The 4027 emulator's work is bounded by its input: erasing the
// graphics and drawing vectors are charged against kPixelWorkBudget.
#include <catch2/catch.hpp>

#include <string>

#include "devices/tek4027/tek4027_decoder.hpp"
#include "devices/work_budget.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::tek4027;

namespace {
std::vector<std::uint8_t> repeat(const std::string& unit, std::uint64_t times) {
  std::vector<std::uint8_t> out;
  for (std::uint64_t i = 0; i < times; ++i) out.insert(out.end(), unit.begin(), unit.end());
  return out;
}
}  // namespace

TEST_CASE("4027: a stream of graphics erases is refused once it passes the drawing budget") {
  const std::uint64_t screen = Tek4027Decoder().image().pixels.size();  // the profile's screen
  const std::uint64_t fit = kPixelWorkBudget / screen;
  {
    Tek4027Decoder d;
    REQUIRE_NOTHROW(decodeBytes(d, repeat("!ERA G\r", fit), "fits.t27"));
    CHECK(d.report().pixelWork == fit * screen);
  }
  Tek4027Decoder d;
  CHECK_THROWS_WITH(decodeBytes(d, repeat("!ERA G\r", fit + 1), "erase.t27"),
                    Catch::Contains("erase.t27") && Catch::Contains("kPixelWorkBudget"));
}

TEST_CASE("4027: vectors are charged the steps they draw on the screen") {
  Tek4027Decoder d;
  const std::string stream = "!VEC 0 0 639 0\r!VEC -1000 5 5000 5\r";
  decodeBytes(d, std::vector<std::uint8_t>(stream.begin(), stream.end()), "v.t27");
  // 640 steps for the first; the second is clipped to the screen (plus a step each side).
  CHECK(d.report().pixelWork >= 1280);
  CHECK(d.report().pixelWork <= 1284);
}
