// The band encoder's ordering edges (sixel_band.hpp, "Work"): which
// segment must be written before which, found once a band and mapped to
// each cut's segments.
//
// Method and tunables: a pass's runs between blank runs form a group, which
// lies whole in one segment in every cut (a cut drops blank runs only).
// findOverwrites walks each pass's non-blank runs column by column over the
// rows they set that belong to later registers, one open stretch per owner;
// each stretch is one edge from the pass's group to the owner's group that
// covers it (the owner's own non-blank runs cover every pixel of its own),
// deduplicated as it is added. A run that sets every row of the band takes
// its edges from the later registers' groups and bits instead (every later
// pixel under it is overwritten). linkSegments maps the edges through the
// cut's group-to-segment table. No tunables.
#include <algorithm>
#include <bit>

#include "devices/sixel/sixel_band.hpp"
#include "foundation/error.hpp"

namespace lattice::sixel {

void SixelBandEncoder::findGroups() {
  groups_.clear();
  for (const Pass& pass : passes_) {
    const auto reg = static_cast<std::size_t>(pass.reg);
    groupFirst_[reg] = groups_.size();
    bool afterBlank = true;
    for (std::size_t r = pass.firstRun; r < pass.lastRun; ++r) {
      const SixelRun& run = runs_[r];
      if (run.value == 0) {
        afterBlank = true;
        continue;
      }
      if (afterBlank) groups_.push_back(Group{run.start, run.start, r, r});
      groups_.back().end = run.start + run.count;
      groups_.back().lastRun = r + 1;
      afterBlank = false;
    }
    groupCount_[reg] = groups_.size() - groupFirst_[reg];
    groupFound_[reg] = groupFirst_[reg];
  }
  groupStamp_.assign(groups_.size(), SIZE_MAX);
}

std::size_t SixelBandEncoder::groupAt(PaletteIndex reg, std::size_t x) {
  // The register's groups are [groupFirst_, groupFirst_ + groupCount_), by
  // start. A pass's stretches go left to right, so from the group found last
  // the one wanted is usually that one or a few after it; else a binary
  // search for the last one starting at or before x.
  const std::size_t first = groupFirst_[reg], last = first + groupCount_[reg];
  std::size_t j = groupFound_[reg];
  if (j < last && groups_[j].start <= x) {
    while (j < last && groups_[j].end <= x) ++j;
  } else {
    j = first;
    for (std::size_t step = groupCount_[reg]; step > 1;) {
      const std::size_t half = step / 2;
      if (groups_[j + half].start <= x) j += half, step -= half;
      else step = half;
    }
  }
  if (j >= last || x < groups_[j].start || x >= groups_[j].end)
    throw Error(ErrorKind::Internal, "sixel band: a later register's pixel outside its own pass's runs");
  groupFound_[reg] = j;
  return j;
}

void SixelBandEncoder::addEdge(std::size_t group, PaletteIndex owner, std::size_t x) {
  const std::size_t to = groupAt(owner, x);
  if (groupStamp_[to] == group) return;  // a group's edges are found together: one of each is enough
  groupStamp_[to] = group;
  edges_.push_back(Edge{group, to});
}

void SixelBandEncoder::edgesOfFullRun(std::size_t rank, std::size_t group, const SixelRun& run) {
  // A run setting every row may set only its own and later registers'
  // pixels, so it overwrites every later pixel in its columns: an edge to
  // each later register's group holding one of its pixels there, found from
  // the groups and the registers' bits instead of pixel by pixel.
  const std::size_t w = static_cast<std::size_t>(width_);
  const std::size_t start = run.start, end = run.start + run.count;
  for (std::size_t later = rank + 1; later < passes_.size(); ++later) {
    const auto reg = static_cast<std::size_t>(passes_[later].reg);
    const std::size_t first = groupFirst_[reg], last = first + groupCount_[reg];
    // The first of the register's groups ending after `start` (groups go left to right).
    std::size_t g = first;
    for (std::size_t step = last - first; step > 0;) {
      const std::size_t half = step / 2;
      if (groups_[g + half].end <= start) g += half + 1, step -= half + 1;
      else step = half;
    }
    const std::uint8_t* own = bits_.data() + reg * w;
    for (; g < last && groups_[g].start < end; ++g) {
      const std::size_t from = std::max(start, groups_[g].start), to = std::min(end, groups_[g].end);
      std::size_t x = from;
      while (x < to && own[x] == 0) ++x;
      if (x < to) addEdge(group, static_cast<PaletteIndex>(reg), x);
    }
  }
}

void SixelBandEncoder::findOverwrites(std::size_t rank, std::span<const PaletteIndex> band, std::uint8_t valid) {
  const Pass& pass = passes_[rank];
  const std::size_t w = static_cast<std::size_t>(width_);
  const std::uint8_t* own = bits_.data() + static_cast<std::size_t>(pass.reg) * w;
  // Column by column, one open stretch per owner: a stretch grows while the
  // owner is met in the next column (in any row the pass sets there), so the
  // rows of a band, which mostly agree, give one stretch and not six. A
  // column whose set bits are all the pass's own pixels is passed over.
  // Each stretch becomes an edge between groups (findGroups): the owner's
  // pass covers a pixel of its own with a non-blank run, so a stretch of its
  // pixels lies in one group of its pass, and the edges are deduplicated.
  std::size_t* const openStart = openStart_.data();  // locals: open_'s byte stores may alias members
  std::size_t* const openEnd = openEnd_.data();
  std::size_t group = groupFirst_[static_cast<std::size_t>(pass.reg)];
  bool afterBlank = true, started = false;
  auto flush = [&] {
    for (const PaletteIndex owner : open_) {
      addEdge(group, owner, openStart_[owner]);
      openEnd_[owner] = 0;
    }
    open_.clear();
  };
  for (std::size_t r = pass.firstRun; r < pass.lastRun; ++r) {
    const SixelRun& run = runs_[r];
    if (run.value == 0) {
      flush();
      afterBlank = true;
      continue;
    }
    if (afterBlank) {
      if (started) ++group;
      started = true;
      afterBlank = false;
    }
    if (run.value == valid && run.count > 1) {
      // Stretches still open stay open: a stretch is only ever asked which
      // group it lies in, and the pieces either side of this run lie in the
      // same one.
      edgesOfFullRun(rank, group, run);
      continue;
    }
    for (std::size_t x = run.start, end = run.start + run.count; x < end; ++x) {
      unsigned others = run.value & ~unsigned(own[x]);
      for (; others != 0; others &= others - 1) {
        const int row = std::countr_zero(others);
        const PaletteIndex owner = band[static_cast<std::size_t>(row) * w + x];
        std::size_t& stretchEnd = openEnd[owner];
        if (stretchEnd == 0) {  // not open since the last blank
          open_.push_back(owner);
          openStart[owner] = x;
        } else if (stretchEnd < x) {  // a gap: the last stretch is done
          addEdge(group, owner, openStart[owner]);
          openStart[owner] = x;
        }
        stretchEnd = x + 1;
      }
    }
  }
  flush();
}

void SixelBandEncoder::linkSegments() {
  const std::size_t n = segments_.size();
  if (after_.size() < n) after_.resize(n);
  for (std::size_t i = 0; i < n; ++i) after_[i].clear();
  stamp_.assign(n, n);
  // Where a segment sets a bit of a later register's pixel, that register's
  // segment covering the pixel is written after it.
  for (const Edge& e : edges_) {
    const std::size_t i = segmentOfGroup_[e.from], j = segmentOfGroup_[e.to];
    if (stamp_[j] == i) continue;
    stamp_[j] = i;
    after_[i].push_back(j);
    ++segments_[j].waitingFor;
  }
}

}  // namespace lattice::sixel
