#include "devices/tek4125/tek4125_rows.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace lattice::tek4125 {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Byte estimates of the fixed parts of commands. A short-form xy within a
// row usually changes Lo-X and one more byte; a full one is five bytes.
struct HeaderCosts {
  double rasterSpan, rasterAfterRuns, runSpan, runsAfterRaster, rectangle;
};

HeaderCosts headerCosts(const Tek4125Forms& forms) {
  const double xy = forms.fullXy ? 5 : 3;
  const double beam = 3 + xy;              // ESC RH xy
  const double rp = 3 + 2 + 2;             // ESC RP count chars
  const double rl = 3 + 2;                 // ESC RL count
  HeaderCosts c;
  c.rasterSpan = beam + rp;
  c.runSpan = beam + rl;
  c.rasterAfterRuns = forms.beamContinues ? rp : c.rasterSpan;
  c.runsAfterRaster = forms.beamContinues ? rl : c.runSpan;
  c.rectangle = 3 + (forms.fullXy ? 10 : 8);  // ESC RR xy xy, the index added per run
  return c;
}

}  // namespace

Tek4125RowPlanner::Tek4125RowPlanner(Tek4125Writer& out, const Tek4125RowLayout& layout,
                                     const Tek4125DriverOptions& options)
    : out_(out), layout_(layout), options_(options) {
  options_.runLength = layout_.runLength;  // the driver decided: the strategy's wish or the only way left
  // The longest run one code can carry: code = length * 2^bits + index <= maxRunCode.
  maxRunLength_ = std::max(1, (out_.forms().maxRunCode + 1) / (1 << layout_.bits) - 1);
  openAt_.assign(static_cast<std::size_t>(layout_.width), -1);
}

double Tek4125RowPlanner::runCodeBytes(const Run& r) const {
  double bytes = 0;
  for (int left = r.length; left > 0;) {
    const int piece = std::min(left, maxRunLength_);
    bytes += tek4125::intLength(piece << layout_.bits | r.index);
    left -= piece;
  }
  const int cap = out_.forms().runCodeBytesPerRl;
  return cap > 0 ? bytes * (1.0 + 5.0 / cap) : bytes;  // each capped RL repeats ESC RL count
}

std::vector<Tek4125RowPlanner::Way> Tek4125RowPlanner::chooseWays(const std::vector<Run>& runs,
                                                                  const std::vector<int>& continuing,
                                                                  const std::vector<bool>& skippable) const {
  const HeaderCosts h = headerCosts(out_.forms());
  const double bitsCost = layout_.bits / 6.0;
  const std::size_t n = runs.size();
  enum { Out = 0, InRaster = 1, InRuns = 2 };
  std::vector<std::array<double, 3>> cost(n + 1, {kInf, kInf, kInf});
  std::vector<std::array<std::uint8_t, 3>> from(n + 1, {0, 0, 0});
  cost[0][Out] = 0;
  auto relax = [&](std::size_t k, int to, int fromState, double c) {
    if (c < cost[k + 1][static_cast<std::size_t>(to)]) {
      cost[k + 1][static_cast<std::size_t>(to)] = c;
      from[k + 1][static_cast<std::size_t>(to)] = static_cast<std::uint8_t>(fromState);
    }
  };
  for (std::size_t k = 0; k < n; ++k) {
    const Run& r = runs[k];
    const auto& c = cost[k];
    double leave = kInf;
    if (skippable[k]) leave = 0;
    else if (options_.rectangles) leave = continuing[k] >= 0 ? 0 : h.rectangle + tek4125::intLength(r.index);
    for (int s = 0; s < 3; ++s) relax(k, Out, s, c[static_cast<std::size_t>(s)] + leave);
    if (layout_.raster) {
      const double raw = r.length * bitsCost;
      relax(k, InRaster, InRaster, c[InRaster] + raw);
      relax(k, InRaster, Out, c[Out] + h.rasterSpan + raw);
      relax(k, InRaster, InRuns, c[InRuns] + h.rasterAfterRuns + raw);
    }
    if (options_.runLength) {
      const double codes = runCodeBytes(r);
      relax(k, InRuns, InRuns, c[InRuns] + codes);
      relax(k, InRuns, Out, c[Out] + h.runSpan + codes);
      relax(k, InRuns, InRaster, c[InRaster] + h.runsAfterRaster + codes);
    }
  }
  std::vector<Way> ways(n);
  int state = static_cast<int>(std::min_element(cost[n].begin(), cost[n].end()) - cost[n].begin());
  for (std::size_t k = n; k-- > 0;) {
    if (state == InRaster) ways[k] = Way::Raster;
    else if (state == InRuns) ways[k] = Way::Runs;
    else ways[k] = skippable[k] ? Way::Skip : Way::Rectangle;
    state = from[k + 1][static_cast<std::size_t>(state)];
  }
  return ways;
}

void Tek4125RowPlanner::row(int y, std::span<const int> indices, std::span<const int> shown) {
  std::vector<Run> runs;
  for (int x = 0; x < layout_.width;) {
    const int index = indices[static_cast<std::size_t>(x)];
    int end = x + 1;
    while (end < layout_.width && indices[static_cast<std::size_t>(end)] == index) ++end;
    runs.push_back(Run{x, end - x, index});
    x = end;
  }
  const int screenRow = layout_.bottom + layout_.height - 1 - y;
  std::vector<int> continuing(runs.size(), -1);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const int o = openAt_[static_cast<std::size_t>(runs[k].start)];
    if (o >= 0 && open_[static_cast<std::size_t>(o)].run.length == runs[k].length &&
        open_[static_cast<std::size_t>(o)].run.index == runs[k].index)
      continuing[k] = o;
  }
  std::vector<bool> skippable(runs.size(), false);
  if (options_.skipBackground)
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const Run& r = runs[k];
      skippable[k] = shown.empty() ? r.index == layout_.background
                                   : std::all_of(shown.begin() + r.start, shown.begin() + r.start + r.length,
                                                 [&](int s) { return s == r.index; });
    }
  const std::vector<Way> ways = chooseWays(runs, continuing, skippable);
  std::vector<OpenRectangle> next;
  bool afterSpan = false;  // the previous run was drawn by RP or RL, so the beam is right after it
  for (std::size_t k = 0; k < runs.size();) {
    if (ways[k] == Way::Skip || ways[k] == Way::Rectangle) {
      if (ways[k] == Way::Skip) {
        stats_.skippedPixels += static_cast<std::uint64_t>(runs[k].length);
      } else if (continuing[k] >= 0) {
        OpenRectangle& grown = open_[static_cast<std::size_t>(continuing[k])];
        ++grown.rows;
        next.push_back(grown);
        grown.rows = 0;  // taken over by next: not to be sent when the old rectangles close
      } else {
        next.push_back(OpenRectangle{runs[k], screenRow, 1});
      }
      afterSpan = false;
      ++k;
      continue;
    }
    std::size_t end = k;
    while (end < runs.size() && ways[end] == ways[k]) ++end;
    const auto span = std::span<const Run>(runs).subspan(k, end - k);
    const bool positioned = afterSpan && out_.forms().beamContinues;
    if (ways[k] == Way::Raster) emitRaster(span, screenRow, positioned);
    else emitRuns(span, screenRow, positioned);
    afterSpan = true;
    k = end;
  }
  if (!options_.mergeRows) {
    for (const OpenRectangle& r : next) emitRectangle(r);
    next.clear();
  }
  closeRectangles(next);
}

void Tek4125RowPlanner::beamTo(int x, int screenRow) {
  out_.command("RH");  // relative to the pixel viewport
  out_.xy(layout_.left + x - layout_.viewportX, screenRow - layout_.viewportY);
}

void Tek4125RowPlanner::emitRaster(std::span<const Run> runs, int screenRow, bool positioned) {
  const int start = runs.front().start;
  const int count = runs.back().start + runs.back().length - start;
  const int bits = layout_.bits;
  if (!positioned) beamTo(start, screenRow);
  out_.command("RP");
  out_.integer(count);
  out_.integer((count * bits + 5) / 6);
  // Pixels MSB first into 6-bit groups, each sent as 0x20 + group.
  unsigned accumulator = 0;
  int held = 0;
  for (const Run& r : runs)
    for (int i = 0; i < r.length; ++i) {
      accumulator = accumulator << bits | static_cast<unsigned>(r.index);
      held += bits;
      while (held >= 6) {
        held -= 6;
        out_.byte(static_cast<std::uint8_t>(0x20 + ((accumulator >> held) & 63u)));
      }
      accumulator &= (1u << held) - 1u;
    }
  if (held > 0) out_.byte(static_cast<std::uint8_t>(0x20 + ((accumulator << (6 - held)) & 63u)));
  ++stats_.rasterWrites;
}

void Tek4125RowPlanner::emitRuns(std::span<const Run> runs, int screenRow, bool positioned) {
  std::vector<int> codes;
  for (const Run& r : runs)
    for (int left = r.length; left > 0;) {
      const int piece = std::min(left, maxRunLength_);
      codes.push_back(piece << layout_.bits | r.index);
      left -= piece;
    }
  if (!positioned) beamTo(runs.front().start, screenRow);
  // One RL, or (capped form sets) consecutive RLs of at most cap code bytes;
  // each continues where the last left the beam, as the GKS driver's do.
  const int cap = out_.forms().runCodeBytesPerRl;
  for (std::size_t i = 0; i < codes.size();) {
    std::size_t end = i;
    int bytes = 0;
    while (end < codes.size() && (cap == 0 || end == i || bytes + tek4125::intLength(codes[end]) <= cap))
      bytes += tek4125::intLength(codes[end++]);
    out_.command("RL");
    out_.integer(static_cast<int>(end - i));
    for (std::size_t j = i; j < end; ++j) out_.integer(codes[j]);
    ++stats_.runLengthWrites;
    i = end;
  }
}

// Rectangles of the previous row that this row did not extend are final:
// send them. Pixels of different rectangles and spans never overlap, so
// sending a rectangle rows later paints the same picture.
void Tek4125RowPlanner::closeRectangles(std::vector<OpenRectangle>& next) {
  for (const OpenRectangle& r : open_) {
    if (r.rows > 0) emitRectangle(r);
    openAt_[static_cast<std::size_t>(r.run.start)] = -1;
  }
  open_.swap(next);
  for (std::size_t i = 0; i < open_.size(); ++i)
    openAt_[static_cast<std::size_t>(open_[i].run.start)] = static_cast<int>(i);
}

void Tek4125RowPlanner::finish() {
  std::vector<OpenRectangle> none;
  closeRectangles(none);
}

void Tek4125RowPlanner::emitRectangle(const OpenRectangle& rect) {
  const int x = layout_.left + rect.run.start;  // RR corners are screen pixels
  out_.command("RR");
  out_.xy(x, rect.topScreenRow - rect.rows + 1);
  out_.xy(x + rect.run.length - 1, rect.topScreenRow);
  out_.integer(rect.run.index);
  ++stats_.rectangleFills;
}

}  // namespace lattice::tek4125
