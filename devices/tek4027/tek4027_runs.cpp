#include "devices/tek4027/tek4027_runs.hpp"

#include <algorithm>

namespace lattice::tek4027 {

std::vector<PotRun> rowRuns(const PotFrame& frame, int y) {
  std::vector<PotRun> runs;
  int x = 0;
  while (x < frame.width) {
    const int pot = frame.at(x, y);
    int end = x;
    while (end + 1 < frame.width && frame.at(end + 1, y) == pot) ++end;
    if (pot != frame.backgroundPot) runs.push_back({y, x, end, pot});
    x = end + 1;
  }
  return runs;
}

std::vector<PotRun> coverRuns(const PotFrame& frame, int y, int pot, unsigned coverable) {
  std::vector<PotRun> spans;
  auto paintable = [&](int x) {
    const int q = frame.at(x, y);
    return q == pot || ((coverable >> q) & 1u) != 0;
  };
  int x = 0;
  while (x < frame.width) {
    if (frame.at(x, y) != pot) {
      ++x;
      continue;
    }
    int lastOwn = x;
    int end = x;
    while (end + 1 < frame.width && paintable(end + 1)) {
      ++end;
      if (frame.at(end, y) == pot) lastOwn = end;
    }
    spans.push_back({y, x, lastOwn, pot});
    x = lastOwn + 1;
  }
  return spans;
}

namespace {

std::size_t countSpans(const PotFrame& frame, int pot, unsigned coverable) {
  std::size_t n = 0;
  for (int y = 0; y < frame.height; ++y) n += coverRuns(frame, y, pot, coverable).size();
  return n;
}

}  // namespace

std::vector<int> layerOrder(const PotFrame& frame) {
  unsigned remaining = 0;
  for (std::uint8_t p : frame.pots)
    if (p != frame.backgroundPot) remaining |= 1u << p;
  std::vector<int> order;
  while (remaining != 0) {
    int bestPot = -1;
    std::size_t bestCost = 0;
    for (int p = 0; p < 8; ++p) {
      if (((remaining >> p) & 1u) == 0) continue;
      const unsigned rest = remaining & ~(1u << p);
      std::size_t cost = countSpans(frame, p, rest);
      for (int q = 0; q < 8; ++q)
        if ((rest >> q) & 1u) cost += countSpans(frame, q, rest & ~(1u << q));
      if (bestPot < 0 || cost < bestCost) {
        bestPot = p;
        bestCost = cost;
      }
    }
    order.push_back(bestPot);
    remaining &= ~(1u << bestPot);
  }
  return order;
}

namespace {

struct RowRuns {
  std::vector<PotRun> runs;  // of the chained pot, left to right
  std::vector<bool> used;
};

// Index of the unused run of `row` containing column x, or -1.
int runContaining(const RowRuns& row, int x) {
  auto it = std::lower_bound(row.runs.begin(), row.runs.end(), x,
                             [](const PotRun& r, int col) { return r.x1 < col; });
  if (it == row.runs.end() || it->x0 > x) return -1;
  const auto index = static_cast<int>(it - row.runs.begin());
  return row.used[static_cast<std::size_t>(index)] ? -1 : index;
}

void append(std::vector<FramePoint>& chain, FramePoint p) {
  if (chain.empty() || !(chain.back() == p)) chain.push_back(p);
}

}  // namespace

std::vector<std::vector<FramePoint>> chainRuns(const std::vector<std::vector<PotRun>>& runsByRow,
                                               const ChainOptions& options) {
  const auto height = static_cast<int>(runsByRow.size());
  std::vector<RowRuns> rows(runsByRow.size());
  for (std::size_t y = 0; y < rows.size(); ++y) {
    rows[y].runs = runsByRow[y];
    rows[y].used.assign(rows[y].runs.size(), false);
  }
  auto rowAt = [&](int y) -> RowRuns* { return y < height ? &rows[static_cast<std::size_t>(y)] : nullptr; };
  // Where the chain can continue from column x of row y: a run of row y + 1
  // and the column the step lands on (x, or x +- 1 for a diagonal step).
  struct Link {
    int run = -1;
    int column = 0;
  };
  auto nextRun = [&](int y, int x) -> Link {
    RowRuns* below = rowAt(y + 1);
    if (below == nullptr) return {};
    const int columns[3] = {x, x - 1, x + 1};
    const int tries = options.diagonalSteps ? 3 : 1;
    // Landing on an end of the next run saves a point (no walk to the near
    // end first), so an end is preferred over an interior column.
    Link interior;
    for (int t = 0; t < tries; ++t) {
      const int c = columns[t];
      const int i = runContaining(*below, c);
      if (i < 0) continue;
      const PotRun& r = below->runs[static_cast<std::size_t>(i)];
      if (c == r.x0 || c == r.x1) return {i, c};
      if (options.enterInterior && interior.run < 0) interior = {i, c};
    }
    return interior;
  };
  // Which end of run r (entered at column x) to finish at: one that leads on
  // to the next row if either does, preferring the far end (fewest points).
  auto chooseEnd = [&](const PotRun& r, int x) {
    const int far = (x - r.x0 >= r.x1 - x) ? r.x0 : r.x1;
    const int near = far == r.x0 ? r.x1 : r.x0;
    if (nextRun(r.y, far).run >= 0) return far;
    if (nextRun(r.y, near).run >= 0) return near;
    return far;
  };

  std::vector<std::vector<FramePoint>> chains;
  for (int y = 0; y < height; ++y) {
    RowRuns& row = rows[static_cast<std::size_t>(y)];
    for (std::size_t i = 0; i < row.runs.size(); ++i) {
      if (row.used[i]) continue;
      row.used[i] = true;
      PotRun run = row.runs[i];
      std::vector<FramePoint> chain;
      // Start at the end that is not the exit, so the run is one segment.
      const int exit = chooseEnd(run, run.x0);
      const int entry = exit == run.x1 ? run.x0 : run.x1;
      chain.push_back({entry, run.y});
      chain.push_back({exit, run.y});  // a one-pixel run repeats its point: a dot
      int x = exit;
      // A link costs up to three more points (step, near end, far end).
      while (options.maxPoints == 0 || static_cast<int>(chain.size()) + 3 <= options.maxPoints) {
        const Link link = nextRun(run.y, x);
        if (link.run < 0) break;
        RowRuns& below = rows[static_cast<std::size_t>(run.y + 1)];
        below.used[static_cast<std::size_t>(link.run)] = true;
        run = below.runs[static_cast<std::size_t>(link.run)];
        x = link.column;
        append(chain, {x, run.y});
        const int end = chooseEnd(run, x);
        const int other = end == run.x0 ? run.x1 : run.x0;
        append(chain, {other, run.y});
        append(chain, {end, run.y});
        x = end;
      }
      chains.push_back(std::move(chain));
    }
  }
  return chains;
}

}  // namespace lattice::tek4027
