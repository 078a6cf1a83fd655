// The emulator's work is bounded by its input: rectangle fills are
// row fills charged against kPixelWorkBudget, and a stream that asks for more
// drawing than the budget is refused by decodeBytes (what `lattice emulate`
// and a fuzzer call).
#include <catch2/catch.hpp>

#include <algorithm>

#include "devices/tek4125/tek4125_decoder.hpp"
#include "devices/tek4125/tek4125_encoding.hpp"
#include "devices/work_budget.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::tek4125;

namespace {

Bytes fullScreenFills(int count, int index) {
  Bytes b;
  for (int i = 0; i < count; ++i) {
    appendCommand(b, "RR");
    XyEncoder xy;  // the full form every time, as a hostile stream would send
    xy.append(b, 0, 0);
    xy.append(b, 4095, 4095);
    appendInt(b, index);
  }
  return b;
}

}  // namespace

TEST_CASE("rectangle fills copy or XOR whole rows and are charged their area") {
  Bytes b;
  appendCommand(b, "RU");
  appendInt(b, 1);
  appendInt(b, 7);  // ALU 7: XOR
  appendInt(b, 8);
  const Bytes fills = fullScreenFills(2, 0x5A);
  b.insert(b.end(), fills.begin(), fills.end());
  Tek4125Decoder d{Tek4125Profile{}};
  decodeBytes(d, b, "xor.tek");
  // XORed twice: back to the cleared screen.
  CHECK(std::all_of(d.image().pixels.begin(), d.image().pixels.end(), [](PaletteIndex p) { return p == 0; }));
  CHECK(d.report().pixelWork == 2u * 1280u * 1024u);

  Tek4125Decoder copy{Tek4125Profile{}};
  decodeBytes(copy, fullScreenFills(1, 7), "copy.tek");
  CHECK(std::all_of(copy.image().pixels.begin(), copy.image().pixels.end(), [](PaletteIndex p) { return p == 7; }));
}

TEST_CASE("a stream of full-screen fills is refused once it passes the drawing budget") {
  const std::uint64_t screen = 1280u * 1024u;
  const int fit = static_cast<int>(kPixelWorkBudget / screen);  // 819
  {
    Tek4125Decoder d{Tek4125Profile{}};
    REQUIRE_NOTHROW(decodeBytes(d, fullScreenFills(fit, 3), "fits.tek"));
    CHECK(d.report().pixelWork == fit * screen);
  }
  Tek4125Decoder d{Tek4125Profile{}};
  Bytes over = fullScreenFills(fit, 3);
  const Bytes last = fullScreenFills(1, 9);
  over.insert(over.end(), last.begin(), last.end());
  try {
    decodeBytes(d, over, "fills.tek");
    FAIL("a stream over the budget was accepted");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Input);
    CHECK(std::string(e.what()).find("fills.tek") != std::string::npos);
    CHECK(std::string(e.what()).find("kPixelWorkBudget") != std::string::npos);
  }
  CHECK(d.report().overBudget);
  // The fill past the budget was not drawn.
  CHECK(std::all_of(d.image().pixels.begin(), d.image().pixels.end(), [](PaletteIndex p) { return p == 3; }));
}
