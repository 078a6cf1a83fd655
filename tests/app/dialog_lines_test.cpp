// The dialog area under lattice term's picture: the 4125's alphanumeric
// text as the emulator keeps it, and its last lines as a text terminal
// would show them.
#include <catch2/catch.hpp>

#include <string>

#include "app/term/dialog_lines.hpp"
#include "devices/device_table.hpp"

using lattice::app::lastDialogLines;

TEST_CASE("term dialog: LF starts a line, CR returns to its start, long lines wrap", "[term]") {
  CHECK(lastDialogLines("one\r\ntwo\r\nthree\r\n", 2, 80) == std::vector<std::string>{"two", "three"});
  CHECK(lastDialogLines("abcdef\rXY", 2, 80) == std::vector<std::string>{"XYcdef"});
  CHECK(lastDialogLines("abcdefgh", 3, 3) == std::vector<std::string>{"abc", "def", "gh"});
  CHECK(lastDialogLines("", 2, 80) == std::vector<std::string>{""});
}

TEST_CASE("term dialog: the 4125 keeps ANSI-mode and alpha-mode text, not graphics", "[term]") {
  const lattice::devices::Device device = lattice::devices::makeDevice("tek4125");
  auto emulator = device.makeEmulator();
  // Alpha text, a GS vector (its address bytes are printable, and are not text),
  // US back to alpha, then ANSI mode's text.
  const std::string stream = "Plot 1\r\n\x1d  `  !  `!\x1f" "done\r\n\x1b%!1ansi text";
  emulator->feed(std::span(reinterpret_cast<const std::uint8_t*>(stream.data()), stream.size()));
  CHECK(emulator->dialogText() == "Plot 1\r\ndone\r\nansi text");
  CHECK(lastDialogLines(emulator->dialogText(), 2, 80) == std::vector<std::string>{"done", "ansi text"});
}
