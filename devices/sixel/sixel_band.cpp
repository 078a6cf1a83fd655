#include "devices/sixel/sixel_band.hpp"

#include <algorithm>
#include <charconv>

#include "devices/sixel/sixel_forms.hpp"
#include "foundation/error.hpp"

namespace lattice::sixel {

namespace {

void appendNumber(std::size_t n, std::string& out) {
  char digits[24];
  const auto end = std::to_chars(digits, digits + sizeof digits, n).ptr;
  out.append(digits, end);
}

std::size_t digitsOf(std::size_t n) {
  std::size_t d = 1;
  for (; n >= 10; n /= 10) ++d;
  return d;
}

// What appendRun writes, without writing it.
std::size_t runBytes(std::size_t count) { return count >= 4 ? digitsOf(count) + 2 : count; }

}  // namespace

void appendRun(std::size_t count, std::uint8_t value, std::string& out) {
  const char c = static_cast<char>(kSixelFirst + value);
  if (count >= 4) {
    out += kRepeat;
    appendNumber(count, out);
    out += c;
  } else {
    out.append(count, c);
  }
}

namespace {

// runsOf over must[0, end) with the allowed bits given by may(x).
template <typename May>
void appendRuns(const std::uint8_t* must, May may, std::size_t end, std::vector<SixelRun>& runs) {
  while (end > 0 && must[end - 1] == 0) --end;  // nothing after the last must
  std::size_t x = 0;
  while (x < end) {
    std::uint8_t low = must[x], high = may(x);
    std::size_t y = x + 1;
    for (; y < end; ++y) {
      const std::uint8_t l = static_cast<std::uint8_t>(low | must[y]), h = static_cast<std::uint8_t>(high & may(y));
      if ((l & ~h) != 0) break;  // no one value fits every column of the run
      low = l;
      high = h;
    }
    runs.push_back(SixelRun{x, y - x, low});
    x = y;
  }
}

}  // namespace

void runsOf(std::span<const std::uint8_t> must, std::span<const std::uint8_t> may, std::vector<SixelRun>& runs) {
  appendRuns(must.data(), [&](std::size_t x) { return may[x]; }, must.size(), runs);
}

std::size_t encodeRuns(std::span<const std::uint8_t> must, std::span<const std::uint8_t> may, std::string& out) {
  std::vector<SixelRun> runs;
  runsOf(must, may, runs);
  for (const SixelRun& r : runs) appendRun(r.count, r.value, out);
  return runs.size();
}

SixelBandEncoder::SixelBandEncoder(int width, int registers)
    : width_(width),
      regs_(static_cast<std::size_t>(registers)),
      count_(static_cast<std::size_t>(registers), 0),
      bits_(static_cast<std::size_t>(registers) * static_cast<std::size_t>(width), 0),
      tally_(4 * static_cast<std::size_t>(registers), 0),
      lastColumn_(static_cast<std::size_t>(kBandRows) * static_cast<std::size_t>(registers), 0),
      later_(static_cast<std::size_t>(width)),
      groupFirst_(static_cast<std::size_t>(registers), 0),
      groupCount_(static_cast<std::size_t>(registers), 0),
      groupFound_(static_cast<std::size_t>(registers), 0),
      end_(static_cast<std::size_t>(registers), 0),
      openStart_(static_cast<std::size_t>(registers), 0),
      openEnd_(static_cast<std::size_t>(registers), 0) {}

void SixelBandEncoder::passRuns(int reg, std::size_t end) {
  // From column 0: left of its first must a pass may still set free bits, so
  // its first run may start there (one run where a blank and a run would be
  // two); a first run that stays blank is dropped by cutPasses. A pass may
  // set its own bits and those of pixels drawn later.
  Pass pass{reg, runs_.size(), 0};
  const std::uint8_t* must = bits_.data() + static_cast<std::size_t>(reg) * static_cast<std::size_t>(width_);
  const std::uint8_t* later = later_.data();
  appendRuns(must, [=](std::size_t x) { return static_cast<std::uint8_t>(must[x] | later[x]); }, end, runs_);
  pass.lastRun = runs_.size();
  passes_.push_back(pass);
}

void SixelBandEncoder::cutPasses(std::size_t gap) {
  // From the groups: between two groups of a pass lies exactly one blank
  // run (a blank run ends only at a column its pass must set), of their
  // distance in columns, and a leading blank run is dropped by every cut.
  // A segment is a stretch of groups whose blanks are all shorter than gap.
  segments_.clear();
  segmentOfGroup_.resize(groups_.size());
  for (const Pass& pass : passes_) {
    const auto reg = static_cast<std::size_t>(pass.reg);
    const std::size_t first = groupFirst_[reg], last = first + groupCount_[reg];
    for (std::size_t g = first; g < last;) {
      Segment s;
      s.reg = pass.reg;
      s.firstRun = groups_[g].firstRun;
      s.start = groups_[g].start;
      std::size_t h = g;
      segmentOfGroup_[h] = segments_.size();
      while (h + 1 < last && groups_[h + 1].start - groups_[h].end < gap) segmentOfGroup_[++h] = segments_.size();
      s.lastRun = groups_[h].lastRun;
      s.end = groups_[h].end;
      segments_.push_back(s);
      g = h + 1;
    }
  }
}

bool SixelBandEncoder::blankRunBetween(std::size_t shorter, std::size_t longer) const {
  // The blank runs a cut may drop are those between a pass's groups.
  for (const Pass& pass : passes_) {
    const auto reg = static_cast<std::size_t>(pass.reg);
    for (std::size_t g = groupFirst_[reg] + 1; g < groupFirst_[reg] + groupCount_[reg]; ++g) {
      const std::size_t blank = groups_[g].start - groups_[g - 1].end;
      if (blank >= shorter && blank < longer) return true;
    }
  }
  return false;
}

std::size_t SixelBandEncoder::planLines(int selected) {
  const std::size_t n = segments_.size();
  // Leftmost first, ties in segments_' order: a counting sort by start column.
  startCount_.assign(static_cast<std::size_t>(width_) + 1, 0);
  for (const Segment& s : segments_) ++startCount_[s.start + 1];
  for (std::size_t c = 1; c < startCount_.size(); ++c) startCount_[c] += startCount_[c - 1];
  byStart_.resize(n);
  for (std::size_t i = 0; i < n; ++i) byStart_[startCount_[segments_[i].start]++] = i;
  plan_.clear();
  std::size_t bytes = 0;
  int reg = selected;
  // Edges go from a register to later ones only, so some segment is always
  // ready and every line writes at least one: the loop ends.
  std::size_t left = n;
  for (bool firstLine = true; left > 0; firstLine = false) {
    if (!firstLine) plan_.push_back(kLineBreak), ++bytes;
    std::size_t x = 0;
    for (std::size_t k = 0; k < byStart_.size(); ++k) {
      Segment& s = segments_[byStart_[k]];
      if (s.start < x) {  // none before the first starting at x or after can go next: skip to it
        k = static_cast<std::size_t>(
                std::partition_point(byStart_.begin() + static_cast<std::ptrdiff_t>(k), byStart_.end(),
                                     [&](std::size_t j) { return segments_[j].start < x; }) -
                byStart_.begin()) -
            1;
        continue;
      }
      if (s.written || s.waitingFor > 0) continue;
      const std::size_t i = byStart_[k];
      plan_.push_back(i);
      if (s.start > x) bytes += runBytes(s.start - x);
      if (s.reg != reg) bytes += 1 + digitsOf(static_cast<std::size_t>(s.reg));
      reg = s.reg;
      bytes += runBytesBefore_[s.lastRun] - runBytesBefore_[s.firstRun];
      x = s.end;
      s.written = true;
      --left;
      for (std::size_t j : after_[i]) --segments_[j].waitingFor;
    }
    std::erase_if(byStart_, [&](std::size_t i) { return segments_[i].written; });
  }
  return bytes;
}

void SixelBandEncoder::writePlan(std::string& out) {
  std::size_t x = 0;
  for (std::size_t i : bestPlan_) {
    if (i == kLineBreak) {
      out += kCarriageReturn;
      ++stats_.lines;
      x = 0;
      continue;
    }
    const Segment& s = bestSegments_[i];
    if (s.start > x) appendRun(s.start - x, 0, out);
    if (s.reg != lastRegister_) {
      out += kColour;
      appendNumber(static_cast<std::size_t>(s.reg), out);
    }
    lastRegister_ = s.reg;
    for (std::size_t r = s.firstRun; r < s.lastRun; ++r) appendRun(runs_[r].count, runs_[r].value, out);
    stats_.runs += s.lastRun - s.firstRun;
    x = s.end;
  }
  ++stats_.lines;
  stats_.segments += bestSegments_.size();
}

void SixelBandEncoder::encode(std::span<const PaletteIndex> band, int rows, std::string& out) {
  const std::size_t w = static_cast<std::size_t>(width_);
  // One pass over the pixels: each register's bits per column (its row of
  // bits_), its pixel count and its last column. Every step is a store or an
  // increment with no branch on the data; the counts go to four tallies by
  // column, so a run of one register does not make each increment wait for
  // the one before it.
  // (Pointers in locals: a byte store may alias anything, so member
  // vectors' data pointers would be reloaded at every pixel.)
  std::uint8_t* const bits = bits_.data();
  std::uint32_t* const tally = tally_.data();
  const std::size_t regs = regs_;
  for (int r = 0; r < rows; ++r) {
    const PaletteIndex* row = band.data() + static_cast<std::size_t>(r) * w;
    const std::uint8_t bit = static_cast<std::uint8_t>(1u << r);
    std::uint32_t* lastColumn = lastColumn_.data() + static_cast<std::size_t>(r) * regs;
    for (std::size_t x = 0; x < w; ++x) {
      const PaletteIndex reg = row[x];
      bits[reg * w + x] |= bit;
      ++tally[(x & 3) * regs + reg];
      lastColumn[reg] = static_cast<std::uint32_t>(x + 1);  // columns rise along a row: the last store is the last
    }
  }
  order_.clear();
  for (std::size_t reg = 0; reg < regs_; ++reg) {
    const std::uint32_t n = tally_[reg] + tally_[regs_ + reg] + tally_[2 * regs_ + reg] + tally_[3 * regs_ + reg];
    if (n == 0) continue;
    count_[reg] = n;
    std::size_t end = 0;
    for (int r = 0; r < rows; ++r) {
      std::uint32_t& last = lastColumn_[static_cast<std::size_t>(r) * regs_ + reg];
      end = std::max<std::size_t>(end, last);
      last = 0;
    }
    end_[reg] = end;
    order_.push_back(static_cast<int>(reg));
    for (std::size_t t = 0; t < 4; ++t) tally_[t * regs_ + reg] = 0;
  }
  std::sort(order_.begin(), order_.end(), [&](int a, int b) {
    return count_[static_cast<std::size_t>(a)] != count_[static_cast<std::size_t>(b)]
               ? count_[static_cast<std::size_t>(a)] > count_[static_cast<std::size_t>(b)]
               : a < b;
  });
  // Every pixel is still to be drawn before the first pass.
  const std::uint8_t valid = static_cast<std::uint8_t>((1u << rows) - 1);
  std::fill(later_.begin(), later_.end(), valid);
  runs_.clear();
  passes_.clear();
  edges_.clear();
  for (const int reg : order_) {
    const std::uint8_t* own = bits_.data() + static_cast<std::size_t>(reg) * w;
    const std::size_t end = end_[static_cast<std::size_t>(reg)];
    std::uint8_t* const later = later_.data();
    for (std::size_t x = 0; x < end; ++x) later[x] = static_cast<std::uint8_t>(later[x] & ~own[x]);
    passRuns(reg, end);
  }
  // Edges need every pass's groups, so they come after all the runs (bits_
  // still holds each register's own bits until the band is done).
  findGroups();
  for (std::size_t rank = 0; rank < passes_.size(); ++rank) findOverwrites(rank, band, valid);
  // What the runs cost, summed once for every cut's planLines.
  runBytesBefore_.resize(runs_.size() + 1);
  runBytesBefore_[0] = 0;
  for (std::size_t r = 0; r < runs_.size(); ++r) runBytesBefore_[r + 1] = runBytesBefore_[r] + runBytes(runs_[r].count);
  // The band as lines for each cut; the shortest is written (the first of
  // equals). A cut that would drop the same blank runs as the one before it
  // gives the same segments, so the same plan and bytes, and cannot win:
  // it is not laid out.
  std::size_t best = SIZE_MAX;
  std::size_t previousGap = 0;
  for (std::size_t gap : kSplitGaps) {
    if (previousGap != 0 && !blankRunBetween(previousGap, gap)) continue;
    previousGap = gap;
    cutPasses(gap);
    linkSegments();
    const std::size_t bytes = planLines(lastRegister_);
    if (bytes < best) {
      best = bytes;
      bestPlan_.swap(plan_);
      bestSegments_.swap(segments_);
    }
  }
  const std::size_t before = out.size();
  writePlan(out);
  if (out.size() - before != best)  // planLines' count and writePlan's bytes are two codings of one form
    throw Error(ErrorKind::Internal, "sixel band: the bytes written are not the plan's count");
  stats_.passes += order_.size();
  for (int reg : order_) {
    count_[static_cast<std::size_t>(reg)] = 0;
    std::fill_n(bits_.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(reg) * w), w, std::uint8_t{0});
  }
}

}  // namespace lattice::sixel
