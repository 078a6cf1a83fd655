#include "quantize/histogram.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "foundation/error.hpp"

namespace lattice::quantize {
namespace {

constexpr std::size_t kSmallFirstSlots = 1024;

// Fibonacci hashing into a power-of-two table.
std::size_t slotOf(Color18 c, std::size_t slots) { return (c * 0x9E3779B1u) >> 8 & (slots - 1); }

}  // namespace

Histogram::Histogram(HistogramForm form) : form_(form) {
  if (form_ == HistogramForm::Full)
    counts_.assign(kCells, 0);
  else
    pairs_.assign(kSmallFirstSlots, Pair{kEmptySlot, 0});
}

void Histogram::growSmall() {
  if (pairs_.size() >= kSmallMaxSlots)
    throw Error(ErrorKind::Usage,
                fmt::format("the small histogram holds at most {} distinct colours and this picture has more: use "
                            "--mode sample (fewer pixels counted) or --histogram full (1 MiB)",
                            kSmallMaxColors));
  std::vector<Pair> grown(pairs_.size() * 2, Pair{kEmptySlot, 0});
  for (const Pair& p : pairs_) {
    if (p.color == kEmptySlot) continue;
    std::size_t i = slotOf(p.color, grown.size());
    while (grown[i].color != kEmptySlot) i = (i + 1) & (grown.size() - 1);
    grown[i] = p;
  }
  pairs_ = std::move(grown);
}

void Histogram::checkAddable() const {
  if (finished_) throw Error(ErrorKind::Internal, "histogram: colour added after finish()");
  if (form_ == HistogramForm::Full && counts_.empty())
    throw Error(ErrorKind::Internal, "histogram: used after releaseStorage()");
}

void Histogram::add(Color18 color) {
  if (color >= kCells)
    throw Error(ErrorKind::Internal,
                fmt::format("histogram: colour {:#x} is not an 18-bit colour (a RowSource18 produced it)", color));
  checkAddable();
  addCount(color, 1);
}

// Saturating: a count stays at the 32-bit maximum once it gets there.
void Histogram::addCount(Color18 color, std::uint32_t n) {
  std::uint32_t* cell = nullptr;
  if (form_ == HistogramForm::Full) {
    cell = &counts_[color];
  } else {
    std::size_t i = slotOf(color, pairs_.size());
    while (pairs_[i].color != kEmptySlot && pairs_[i].color != color) i = (i + 1) & (pairs_.size() - 1);
    if (pairs_[i].color == kEmptySlot) {
      if ((used_ + 1) * 4 > pairs_.size() * 3) {
        growSmall();
        addCount(color, n);  // into the grown table (total_ counted there)
        return;
      }
      pairs_[i].color = color;
      ++used_;
    }
    cell = &pairs_[i].count;
  }
  *cell = n > std::numeric_limits<std::uint32_t>::max() - *cell ? std::numeric_limits<std::uint32_t>::max() : *cell + n;
  total_ += n;
}

void Histogram::addRow(std::span<const Color18> row) {
  if (form_ != HistogramForm::Full) {
    for (Color18 c : row) add(c);
    return;
  }
  checkAddable();  // once a row: the full form's per-pixel work is one bounds check and one count
  for (Color18 c : row) {
    if (c >= kCells) add(c);  // throws, naming the colour
    std::uint32_t& cell = counts_[c];
    cell += cell != std::numeric_limits<std::uint32_t>::max();
  }
  total_ += row.size();
}

void Histogram::merge(const Histogram& part, Color18 first, Color18 last) {
  if (part.form_ != form_ || part.finished_)
    throw Error(ErrorKind::Internal, "histogram: merged a part of another form, or a finished one");
  checkAddable();
  if (form_ == HistogramForm::Full) {
    constexpr std::uint32_t kMax = std::numeric_limits<std::uint32_t>::max();
    for (Color18 c = first; c < last; ++c) {
      const std::uint32_t n = part.counts_[c];
      counts_[c] = n > kMax - counts_[c] ? kMax : counts_[c] + n;
    }
    if (first == 0) total_ += part.total_;
    return;
  }
  const std::uint64_t total = total_ + part.total_;  // addCount counts a saturated count's pixels once
  for (const Pair& p : part.pairs_)
    if (p.color != kEmptySlot) addCount(p.color, p.count);
  total_ = total;
}

void Histogram::addRowSampled(std::span<const Color18> row, int step) {
  if (step < 1) throw Error(ErrorKind::Internal, "histogram: sample step must be >= 1");
  for (std::size_t x = 0; x < row.size(); x += static_cast<std::size_t>(step)) add(row[x]);
}

void Histogram::finish() {
  if (finished_ || form_ == HistogramForm::Full) {
    finished_ = true;
    return;
  }
  // Empty slots hold the largest key, so one sort puts the pairs first, in order.
  std::sort(pairs_.begin(), pairs_.end(), [](const Pair& a, const Pair& b) { return a.color < b.color; });
  pairs_.resize(used_);
  finished_ = true;
}

std::span<const Histogram::Pair> Histogram::sortedPairs() const {
  if (!finished_) throw Error(ErrorKind::Internal, "histogram: the small form is read before finish()");
  return pairs_;
}

std::uint32_t Histogram::count(Color18 color) const {
  if (form_ == HistogramForm::Full) return counts_[color];
  const auto pairs = sortedPairs();
  const auto it = std::lower_bound(pairs.begin(), pairs.end(), color,
                                   [](const Pair& p, Color18 c) { return p.color < c; });
  return it != pairs.end() && it->color == color ? it->count : 0;
}

std::size_t Histogram::distinctColors() const {
  if (form_ == HistogramForm::Small) return used_;
  return static_cast<std::size_t>(std::count_if(counts_.begin(), counts_.end(), [](std::uint32_t n) { return n != 0; }));
}

std::vector<std::uint32_t> Histogram::releaseStorage() {
  total_ = 0;
  if (form_ == HistogramForm::Small) {
    std::vector<Pair>().swap(pairs_);
    used_ = 0;
    return {};
  }
  return std::move(counts_);
}

}  // namespace lattice::quantize
