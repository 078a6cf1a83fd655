#pragma once
// One six-row band of register numbers as sixel bytes: the driver's whole
// encoding step, separated so that tests, the benchmark and a later per-row
// pre-pass can call it on its own.
//
// Method (the bytes are the measure; docs/sixel.md gives the figures):
//  * Every register present in the band has a pass: `#Pc` selects it and
//    sixels follow. A later sixel overwrites a pixel an earlier one set
//    (xterm's set_sixel, libsixel's decoder, the VT340). Registers absent
//    from the band cost nothing.
//  * Passes are ranked from the register with the most pixels in the band
//    to the one with the fewest. A pixel whose register ranks LATER is free
//    in the earlier passes: whatever they set there is painted over. So the
//    most frequent register can cover whole stretches with one repeated
//    sixel (usually `!W~`), and every pass picks its sixels from what it
//    must set (its own pixels) up to what it may set (its own and the free
//    ones).
//  * runsOf() turns a pass into runs: from each column it extends the run
//    while one sixel value lies between the union of the columns' musts and
//    the intersection of their mays (the longest run from there, so the
//    fewest runs, greedily); the value written is the union of the musts.
//    A pass runs from column 0 (left of its first must it may still set free
//    bits, so its first run can start there) to its last must.
//  * A pass is cut into segments at its blank runs (value 0) of at least
//    `gap` columns, and at a leading blank run; those blanks are dropped.
//    Segments are then packed into lines, as libsixel's encoder packs its
//    per-colour nodes (tosixel.c, sixel_encode_body): a line runs left to
//    right, each segment after the previous one's end, the gap written as
//    blank sixels and `#Pc` where the register changes; `$` starts the next
//    line at column 0. A segment that sets a bit of a later register's pixel
//    is written before that register's segment covering the column (the
//    overwrite keeps its order); of the segments whose predecessors are all
//    written, the one starting leftmost at or after the line's position goes
//    next. This saves the `$` and the leading blank run a pass per register
//    would cost, which at 256 registers is most of a band's blank bytes.
//  * The band is laid out once for each gap of kSplitGaps and the shortest
//    kept: short gaps fill lines, at the price of more `#Pc` switches, which
//    pays at 256 registers and not at 16.
//  * A run of n >= 4 equal sixels is written `!n` and the sixel (n = 3
//    costs three bytes either way, and is written plainly).
//  * `#Pc` is left out when it is the register already selected (the
//    register stays selected across `$` and `-`).
//
// Work (the bytes above fix what is written; this is how it is found
// cheaply; docs/sixel.md "Encoder only" has the figures):
//  * One branch-free pass over the band fills each register's bits per
//    column (a registers x width array, zero again after the band), its
//    pixel count (four tallies by column) and its last column.
//  * Which segment must precede which is found once a band, not once a cut
//    (sixel_band_edges.cpp):
//    a pass's runs between blank runs form a group, which lies whole in one
//    segment in every cut (a cut drops blank runs only). For each run, the
//    columns where it sets bits of later registers' pixels are gathered
//    column by column into one stretch per owner, and each stretch becomes
//    an edge from the pass's group to the owner's group covering it (the
//    owner's own non-blank runs cover its pixels); a cut only maps groups
//    to its segments. A run that sets every row of the band overwrites
//    every later pixel in its columns, so its edges are read from the later
//    registers' groups and bits instead.
//  * A cut is made from the groups: between two groups of a pass lies one
//    blank run, of their distance. A cut that drops the same blank runs as
//    the one before it is not laid out (same segments, same bytes; the
//    first of equals is kept anyway).
//  * planLines sorts by counting, skips to the first segment at or after
//    the line's position, and reads a segment's run bytes from prefix sums.
//
// Tunable: kSplitGaps. Measured on Plate 6 (512x512, 16 and 256 colours,
// bytes): no cut 51,717 and 167,605; 8 alone 53,730 and 163,272; 8 and no
// cut 51,717 and 162,987; 8, 32, no cut (kept) 51,705 and 162,824; 4, 8, 16,
// 32, 64, no cut 51,676 and 162,336 for twice the layout time.
#include <cstdint>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "foundation/scanline.hpp"

namespace lattice::sixel {

// SIZE_MAX: passes are never cut, only packed.
inline constexpr std::size_t kSplitGaps[] = {8, 32, SIZE_MAX};

// One run of a pass: `count` copies of sixel `value` from column `start`.
struct SixelRun {
  std::size_t start = 0;  // column
  std::size_t count = 0;
  std::uint8_t value = 0;  // 0..63
};

// The runs of one pass from column 0 to its last must: must[x] are the bits
// that pass has to set at column x, may[x] (a superset) the bits it is
// allowed to set. Appends to `runs`.
void runsOf(std::span<const std::uint8_t> must, std::span<const std::uint8_t> may, std::vector<SixelRun>& runs);

// Appends runsOf(must, may) as sixel bytes to `out`; returns the number of runs.
std::size_t encodeRuns(std::span<const std::uint8_t> must, std::span<const std::uint8_t> may, std::string& out);

// Appends a run of `count` copies of sixel `value` (0..63) to `out`.
void appendRun(std::size_t count, std::uint8_t value, std::string& out);

struct SixelBandStats {
  std::uint64_t passes = 0;    // colour passes (registers drawn, summed over bands)
  std::uint64_t lines = 0;     // `$`-separated lines
  std::uint64_t segments = 0;  // pieces of passes placed on lines
  std::uint64_t runs = 0;
};

class SixelBandEncoder {
 public:
  SixelBandEncoder(int width, int registers);
  // `band` holds `rows` (1..6) rows of `width` register numbers, top first.
  // Appends the band's bytes (without the `-` that follows it) to `out`.
  void encode(std::span<const PaletteIndex> band, int rows, std::string& out);
  const SixelBandStats& stats() const { return stats_; }

 private:
  struct Pass {
    int reg = 0;
    std::size_t firstRun = 0, lastRun = 0;  // runs_[firstRun, lastRun)
  };
  // A group: a pass's maximal stretch of runs with no blank run among them,
  // columns [start, end). A cut drops blank runs only, so a group always
  // lies whole in one segment, whatever the cut.
  struct Group {
    std::size_t start = 0, end = 0;
    std::size_t firstRun = 0, lastRun = 0;  // runs_[firstRun, lastRun)
  };
  // Group `from` sets a bit of a pixel whose register's group `to` paints.
  struct Edge {
    std::size_t from = 0, to = 0;
  };
  struct Segment {
    int reg = 0;
    std::size_t start = 0, end = 0;        // columns [start, end)
    std::size_t firstRun = 0, lastRun = 0;  // runs_[firstRun, lastRun)
    std::size_t waitingFor = 0;            // segments that must precede it, not yet written
    bool written = false;
  };
  void passRuns(int reg, std::size_t end);
  void cutPasses(std::size_t gap);
  void findGroups();  // groups_ of every pass, once a band
  std::size_t groupAt(PaletteIndex reg, std::size_t x);  // the register's group covering column x
  void addEdge(std::size_t group, PaletteIndex owner, std::size_t x);
  // The edges of the pass of rank `rank`, for every cut: once a pass, after
  // findGroups. `valid`: the band's rows as bits.
  void findOverwrites(std::size_t rank, std::span<const PaletteIndex> band, std::uint8_t valid);
  void edgesOfFullRun(std::size_t rank, std::size_t group, const SixelRun& run);
  // Whether some pass has a blank run, not its first, of shorter <= count < longer
  // columns: else cutting at `shorter` and at `longer` gives the same segments.
  bool blankRunBetween(std::size_t shorter, std::size_t longer) const;
  void linkSegments();
  // Lays the segments out in lines (plan_) and returns the bytes they take,
  // `selected` being the register selected before the band.
  std::size_t planLines(int selected);
  void writePlan(std::string& out);  // bestPlan_ of bestSegments_
  static constexpr std::size_t kLineBreak = SIZE_MAX;  // `$` in a plan

  int width_;
  int lastRegister_ = -1;  // selected at the end of the previous band
  std::size_t regs_;                  // registers the palette has
  std::vector<std::uint32_t> count_;  // pixels per register in this band
  std::vector<int> order_;            // registers present, most pixels first
  std::vector<std::uint8_t> bits_;    // per register, its pixels' bits per column (registers x width; zero between bands)
  std::vector<std::uint32_t> tally_;  // 4 x registers pixel counts, by column mod 4 (zero between bands)
  std::vector<std::uint32_t> lastColumn_;  // per row and register, one past its last pixel (zero between bands)
  std::vector<std::uint8_t> later_;   // per column, bits of pixels drawn by passes not yet done
  std::vector<SixelRun> runs_;        // every pass's runs, this band
  std::vector<std::size_t> runBytesBefore_;  // bytes of runs_[0, r), for planLines
  std::vector<Pass> passes_;          // in order_
  std::vector<Segment> segments_;     // by pass, each pass's left to right
  std::vector<std::size_t> plan_, bestPlan_;  // segment indices and kLineBreak, in writing order
  std::vector<Segment> bestSegments_;
  std::vector<std::size_t> byStart_;  // segments_ indices, leftmost first
  std::vector<std::size_t> startCount_;  // planLines' counting sort, per start column
  std::vector<std::vector<std::size_t>> after_;  // per segment, the segments waiting for it
  std::vector<Group> groups_;                     // by pass, each pass's left to right
  std::vector<Edge> edges_;                       // this band's, for every cut
  std::vector<std::size_t> groupStamp_;           // per group, the last group an edge came from
  std::vector<std::size_t> segmentOfGroup_;       // per group, its segment in this cut
  std::vector<std::size_t> stamp_;                // per segment, the last one linked to it
  std::vector<std::size_t> groupFirst_, groupCount_;  // per register, its groups in groups_
  std::vector<std::size_t> groupFound_;           // per register, the group groupAt found last
  std::vector<std::size_t> end_;                 // per register, one past its last column in this band
  std::vector<std::size_t> openStart_, openEnd_;  // per register, findOverwrites' open stretch (end 0: none)
  std::vector<PaletteIndex> open_;               // registers with an open stretch
  SixelBandStats stats_;
};

}  // namespace lattice::sixel
