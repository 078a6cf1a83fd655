// What lattice term reads from the user's terminal's answers: whether it
// draws sixels (DA1 attribute 4), its colour registers (XTSMGRAPHICS) and
// its text area's pixels (XTWINOPS 14), from answers as xterm writes them.
#include <catch2/catch.hpp>

#include "app/term/host_graphics.hpp"

using lattice::app::HostGraphics;
using lattice::app::readHostAnswers;

TEST_CASE("term host: xterm -ti vt340's answers say sixels, 256 registers and the pixel size", "[term]") {
  HostGraphics host;
  // Registers and size first, then DA1, which ends the wait.
  CHECK_FALSE(readHostAnswers("\x1b[?1;0;256S\x1b[4;800;1000t", host));
  CHECK(host.registers == 256);
  CHECK(host.pixelWidth == 1000);
  CHECK(host.pixelHeight == 800);
  CHECK(readHostAnswers("\x1b[?1;0;256S\x1b[4;800;1000t\x1b[?63;1;2;4;6;9;15;22c", host));
  CHECK(host.sixel);
}

TEST_CASE("term host: a terminal without attribute 4 or registers shows no sixels", "[term]") {
  HostGraphics host;
  // A VT220-class answer (no 4), and XTSMGRAPHICS refused (status 1): registers stay 16.
  CHECK(readHostAnswers("\x1b[?1;1;0S\x1b[?62;1;2;6;9;15;22c", host));
  CHECK_FALSE(host.sixel);
  CHECK(host.registers == 16);
  CHECK_THAT(host.why, Catch::Contains("do not list sixel graphics"));
  // "14" in the list is not 4, nor is the class 4 (the first number).
  HostGraphics other;
  CHECK(readHostAnswers("\x1b[?4;14;24c", other));
  CHECK_FALSE(other.sixel);
}
