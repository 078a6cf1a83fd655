#include "devices/tek4027/tek4027_profile.hpp"

#include <fmt/format.h>

#include <cctype>

#include "util/error.hpp"

namespace lattice {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw Error(ErrorKind::Usage, fmt::format("tek4027 profile: {}", what));
}

}  // namespace

void Tek4027Profile::validate() const {
  const auto c = static_cast<unsigned char>(commandChar);
  // The introducer must not be something that can appear inside a command.
  // Letters, digits, signs, separators, terminators and flow control are taken.
  require(c > 0 && c < 127 && !std::isalnum(c) && c != ' ' && c != ',' && c != ';' && c != '\r' &&
              c != '\n' && c != '\t' && c != '-' && c != '+' && c != 0x11 && c != 0x13,
          fmt::format("command character code {} cannot introduce commands; use a punctuation or "
                      "control character such as '!' (33) or US (31)",
                      int(c)));
  require(separator == ' ' || separator == ',', "separator must be a space or a comma");
  require(terminator == '\r' || terminator == ';', "terminator must be CR or ';'");
  require(width >= 1 && width <= 4096 && height >= 1 && height <= 4096,
          fmt::format("resolution {}x{} is outside 1..4096 in each direction", width, height));
  require(colors >= 2 && colors <= 8, fmt::format("colour count {} is outside 2..8 paint pots", colors));
  require(backgroundPot >= 0 && backgroundPot < colors,
          fmt::format("background pot C{} is not one of C0..C{}", backgroundPot, colors - 1));
  require(line.baud > 0, "baud must be positive");
  require(terminalCharsPerSecond > 0, "terminal characters per second must be positive");
  require(maxPointsPerCommand >= 2 && maxPointsPerCommand <= 1024,
          fmt::format("points per command {} is outside 2..1024", maxPointsPerCommand));
  require(workspaceLines >= 1 && graphicsFirstRow >= 1 && graphicsFirstRow <= graphicsLastRow &&
              graphicsLastRow <= workspaceLines,
          "graphics rows must lie within the workspace (1 <= first <= last <= workspace lines)");
}

}  // namespace lattice
