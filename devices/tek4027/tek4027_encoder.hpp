#pragma once
// Turns a PotFrame into 4027 command text. Several ways of ordering and
// spelling the vectors are kept so they can be measured against each other
// (docs/tek4027.md has the figures); the driver sends the shortest.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "devices/tek4027/tek4027_hls.hpp"
#include "devices/tek4027/tek4027_profile.hpp"
#include "devices/tek4027/tek4027_runs.hpp"

namespace lattice::tek4027 {

enum class Tek4027Strategy {
  RowOrder,         // rows top to bottom, !COL whenever the pot changes, one !VEC per run
  ColourOrder,      // one !COL per pot, then that pot's runs, one !VEC per run
  Chained,          // per pot, runs chained into absolute polylines (links at run ends only)
  ChainedRelative,  // per pot, chains entered anywhere; each chain spelled absolute or
                    // with !RVE deltas (where the profile permits), whichever is shorter
  Layered,          // painter's order (layerOrder): a pot's spans run across pixels of pots
                    // drawn after it; one !VEC per span
  LayeredChained,   // painter's spans chained as in ChainedRelative
  Shortest,         // all of the above, keep the shortest stream
};

std::string_view strategyName(Tek4027Strategy strategy);

// How the strategies walk the picture: its rows top first (horizontal
// vectors, each step to the next row one down), its rows bottom first (each
// step `0 1`, a byte shorter than `0 -1`), or its columns left first
// (vertical vectors, steps `1 0`). All use the same command forms; Shortest
// tries each.
enum class Tek4027Orientation { Rows, RowsUp, Columns };
std::string_view orientationName(Tek4027Orientation orientation);

struct Tek4027StreamStats {
  Tek4027Strategy strategy = Tek4027Strategy::Shortest;  // the one actually used
  Tek4027Orientation orientation = Tek4027Orientation::Rows;
  std::uint64_t bytes = 0;
  std::uint64_t commands = 0;
  std::uint64_t colourSelects = 0;  // !COL commands
  std::uint64_t vectorCommands = 0;  // !VEC and !RVE commands
  std::uint64_t reportRequests = 0;  // !REP 00 (report pacing, tek4027_pacing.hpp)
  double lineSeconds = 0;      // at the profile's baud
  double terminalSeconds = 0;  // at the terminal's drawing speed
  // The terminal cannot go faster than either limit.
  double seconds() const { return lineSeconds > terminalSeconds ? lineSeconds : terminalSeconds; }
};

// What to draw: pot numbers per pixel and the colour to define in each pot
// that is used (unused pots are left as they are).
struct Tek4027Picture {
  PotFrame frame;
  std::array<std::optional<Rgb8>, 8> potColours;
};

// `!MIX` takes whole percent per gun: the nearest percent, and the 8-bit
// level a terminal (and our emulator) shows for it.
int percentFromLevel(std::uint8_t level);
std::uint8_t levelFromPercent(long percent);

// The whole stream: set-up (!WOR, !GRA), pot definitions (!MIX or !MAP, as
// the profile permits), erase (!ERA G), the vectors, and a final terminator.
// The frame is placed at the top-left of the graphics area. Report pacing is
// applied afterwards (tek4027_pacing.hpp).
std::string encodeTek4027(const Tek4027Picture& picture, const Tek4027Profile& profile, Tek4027Strategy strategy,
                          Tek4027StreamStats* stats = nullptr,
                          Tek4027Orientation orientation = Tek4027Orientation::Rows);

}  // namespace lattice::tek4027
