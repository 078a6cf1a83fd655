#include "devices/tek4014/tek4014_dither.hpp"

#include <algorithm>
#include <cmath>

namespace lattice::tek4014 {
namespace {

float decodeSrgb(std::uint8_t v) {
  const float c = static_cast<float>(v) / 255.0f;
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// The 8x8 Bayer matrix: each entry's rank in the order dots are lit.
constexpr std::uint8_t kBayer8[8][8] = {
    {0, 32, 8, 40, 2, 34, 10, 42},  {48, 16, 56, 24, 50, 18, 58, 26}, {12, 44, 4, 36, 14, 46, 6, 38},
    {60, 28, 52, 20, 62, 30, 54, 22}, {3, 35, 11, 43, 1, 33, 9, 41},   {51, 19, 59, 27, 49, 17, 57, 25},
    {15, 47, 7, 39, 13, 45, 5, 37},  {63, 31, 55, 23, 61, 29, 53, 21}};

}  // namespace

float linearLuminance(Rgb8 c) {
  return 0.2126f * decodeSrgb(c.r) + 0.7152f * decodeSrgb(c.g) + 0.0722f * decodeSrgb(c.b);
}

RowDither::RowDither(Tek4014Dither method, int width, const Palette& palette)
    : method_(method), width_(width), luminance_(256, 0.0f) {
  for (std::size_t i = 0; i < palette.size() && i < luminance_.size(); ++i) luminance_[i] = linearLuminance(palette[i]);
  if (method_ == Tek4014Dither::FloydSteinberg) {
    error_.assign(static_cast<std::size_t>(width) + 2, 0.0f);
    next_.assign(static_cast<std::size_t>(width) + 2, 0.0f);
  }
}

void RowDither::row(int y, std::span<const PaletteIndex> indices, std::span<std::uint8_t> lit) {
  const auto w = static_cast<std::size_t>(width_);
  switch (method_) {
    case Tek4014Dither::Threshold:
      for (std::size_t x = 0; x < w; ++x) lit[x] = luminance_[indices[x]] >= 0.5f ? 1 : 0;
      return;
    case Tek4014Dither::Ordered:
      for (std::size_t x = 0; x < w; ++x) {
        const float threshold = (static_cast<float>(kBayer8[y & 7][x & 7]) + 0.5f) / 64.0f;
        lit[x] = luminance_[indices[x]] > threshold ? 1 : 0;
      }
      return;
    case Tek4014Dither::FloydSteinberg: break;
  }
  // error_[x + 1] is pixel x's incoming error; the guards absorb what falls off the edges.
  std::fill(next_.begin(), next_.end(), 0.0f);
  const bool leftToRight = (y % 2) == 0;
  for (std::size_t i = 0; i < w; ++i) {
    const std::size_t x = leftToRight ? i : w - 1 - i;
    const std::size_t at = x + 1;
    const std::size_t ahead = leftToRight ? at + 1 : at - 1, behind = leftToRight ? at - 1 : at + 1;
    const float value = luminance_[indices[x]] + error_[at];
    const bool on = value >= 0.5f;
    lit[x] = on ? 1 : 0;
    const float e = value - (on ? 1.0f : 0.0f);
    error_[ahead] += e * (7.0f / 16.0f);
    next_[behind] += e * (3.0f / 16.0f);
    next_[at] += e * (5.0f / 16.0f);
    next_[ahead] += e * (1.0f / 16.0f);
  }
  std::swap(error_, next_);
}

}  // namespace lattice::tek4014
