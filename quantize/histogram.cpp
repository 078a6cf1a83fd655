#include "quantize/histogram.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "foundation/error.hpp"

namespace lattice::quantize {

Histogram::Histogram() : counts_(kCells, 0) {}

void Histogram::add(Color18 color) {
  if (color >= kCells)
    throw Error(ErrorKind::Internal,
                fmt::format("histogram: colour {:#x} is not an 18-bit colour (a RowSource18 produced it)", color));
  if (counts_.empty()) throw Error(ErrorKind::Internal, "histogram: used after releaseStorage()");
  std::uint32_t& cell = counts_[color];
  if (cell != std::numeric_limits<std::uint32_t>::max()) ++cell;
  ++total_;
}

void Histogram::addRow(std::span<const Color18> row) {
  for (Color18 c : row) add(c);
}

void Histogram::addRowSampled(std::span<const Color18> row, int step) {
  if (step < 1) throw Error(ErrorKind::Internal, "histogram: sample step must be >= 1");
  for (std::size_t x = 0; x < row.size(); x += static_cast<std::size_t>(step)) add(row[x]);
}

std::size_t Histogram::distinctColors() const {
  return static_cast<std::size_t>(std::count_if(counts_.begin(), counts_.end(), [](std::uint32_t n) { return n != 0; }));
}

std::vector<std::uint32_t> Histogram::releaseStorage() {
  total_ = 0;
  return std::move(counts_);
}

}  // namespace lattice::quantize
