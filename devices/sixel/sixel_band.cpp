#include "devices/sixel/sixel_band.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "devices/sixel/sixel_forms.hpp"

namespace lattice::sixel {

void appendRun(std::size_t count, std::uint8_t value, std::string& out) {
  const char c = static_cast<char>(kSixelFirst + value);
  if (count >= 4) {
    out += kRepeat;
    fmt::format_to(std::back_inserter(out), "{}", count);
    out += c;
  } else {
    out.append(count, c);
  }
}

std::size_t encodeRuns(std::span<const std::uint8_t> must, std::span<const std::uint8_t> may, std::string& out) {
  std::size_t end = must.size();
  while (end > 0 && must[end - 1] == 0) --end;  // nothing after the last must
  std::size_t runs = 0;
  std::size_t x = 0;
  while (x < end) {
    std::uint8_t low = must[x], high = may[x];
    std::size_t y = x + 1;
    for (; y < end; ++y) {
      const std::uint8_t l = static_cast<std::uint8_t>(low | must[y]), h = static_cast<std::uint8_t>(high & may[y]);
      if ((l & ~h) != 0) break;  // no one value fits every column of the run
      low = l;
      high = h;
    }
    appendRun(y - x, low, out);
    ++runs;
    x = y;
  }
  return runs;
}

SixelBandEncoder::SixelBandEncoder(int width, int registers)
    : width_(width),
      count_(static_cast<std::size_t>(registers), 0),
      must_(static_cast<std::size_t>(width)),
      later_(static_cast<std::size_t>(width)),
      may_(static_cast<std::size_t>(width)) {}

void SixelBandEncoder::encode(std::span<const PaletteIndex> band, int rows, std::string& out) {
  const std::size_t w = static_cast<std::size_t>(width_);
  order_.clear();
  for (std::size_t i = 0; i < static_cast<std::size_t>(rows) * w; ++i)
    if (count_[band[i]]++ == 0) order_.push_back(band[i]);
  std::sort(order_.begin(), order_.end(), [&](int a, int b) {
    return count_[static_cast<std::size_t>(a)] != count_[static_cast<std::size_t>(b)]
               ? count_[static_cast<std::size_t>(a)] > count_[static_cast<std::size_t>(b)]
               : a < b;
  });
  // Every pixel is still to be drawn before the first pass.
  const std::uint8_t valid = static_cast<std::uint8_t>((1u << rows) - 1);
  std::fill(later_.begin(), later_.end(), valid);
  for (std::size_t pass = 0; pass < order_.size(); ++pass) {
    const int reg = order_[pass];
    std::fill(must_.begin(), must_.end(), 0);
    for (int r = 0; r < rows; ++r) {
      const PaletteIndex* row = band.data() + static_cast<std::size_t>(r) * w;
      for (std::size_t x = 0; x < w; ++x)
        if (row[x] == reg) must_[x] = static_cast<std::uint8_t>(must_[x] | (1u << r));
    }
    for (std::size_t x = 0; x < w; ++x) {
      later_[x] = static_cast<std::uint8_t>(later_[x] & ~must_[x]);
      may_[x] = static_cast<std::uint8_t>(must_[x] | later_[x]);
    }
    if (pass > 0) out += kCarriageReturn;
    if (reg != lastRegister_) fmt::format_to(std::back_inserter(out), "{}{}", kColour, reg);
    lastRegister_ = reg;
    stats_.runs += encodeRuns(must_, may_, out);
    ++stats_.passes;
  }
  for (int reg : order_) count_[static_cast<std::size_t>(reg)] = 0;
}

}  // namespace lattice::sixel
