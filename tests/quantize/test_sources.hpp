#pragma once
// Synthetic RowSource18s for the quantizer, pipeline and Apollo tests: a
// colour per (x, y) from a function, and a counting wrapper to check how often
// a mode re-renders. Deterministic by construction.
#include <cstdint>
#include <functional>
#include <span>

#include "foundation/scanline.hpp"

namespace lattice::testing {

class FunctionSource final : public RowSource18 {
 public:
  using Pixel = std::function<Color18(int x, int y)>;
  FunctionSource(int width, int height, Pixel pixel) : width_(width), height_(height), pixel_(std::move(pixel)) {}
  int width() const override { return width_; }
  int height() const override { return height_; }
  void row(int y, std::span<Color18> out) override {
    ++rowCalls;
    for (int x = 0; x < width_; ++x) out[static_cast<std::size_t>(x)] = pixel_(x, y);
  }
  long rowCalls = 0;

 private:
  int width_, height_;
  Pixel pixel_;
};

// A small hash so "noisy" pictures stay deterministic.
inline std::uint32_t hash2(int x, int y) {
  std::uint32_t h = static_cast<std::uint32_t>(x) * 73856093u ^ static_cast<std::uint32_t>(y) * 19349663u;
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return h;
}

// Smooth gradients plus a little noise and a disc: many distinct colours.
inline Color18 photoLike(int x, int y, int width, int height) {
  unsigned r = static_cast<unsigned>(x * 63 / (width > 1 ? width - 1 : 1));
  unsigned g = static_cast<unsigned>(y * 63 / (height > 1 ? height - 1 : 1));
  unsigned b = (r + g) / 2u + (hash2(x, y) & 3u);
  int dx = x - width / 2, dy = y - height / 2;
  if (dx * dx + dy * dy < (width * width) / 16) return packColor18(60u - r / 2u, 20u + (hash2(y, x) & 7u), b & 63u);
  return packColor18(r, g, b > 63u ? 63u : b);
}

}  // namespace lattice::testing
