#include "quantize/row_mapper.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "quantize/median_cut.hpp"
#include "foundation/error.hpp"

namespace lattice::quantize {
namespace {

// Division by 16 rounding half away from zero, so positive and negative error
// are treated alike (plain integer division would bias toward zero).
int divide16(int v) { return v >= 0 ? (v + 8) / 16 : -((-v + 8) / 16); }

int clamp8(int v) { return std::clamp(v, 0, 255); }

// The 8x8 Bayer index matrix, built by the usual recursive doubling
// (M2n = [[4M, 4M+2], [4M+3, 4M+1]]) at compile time.
constexpr std::array<std::array<int, 8>, 8> makeBayer() {
  std::array<std::array<int, 8>, 8> m{};
  int size = 1;
  while (size < 8) {
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        int v = 4 * m[y][x];
        m[y][x] = v;
        m[y][x + size] = v + 2;
        m[y + size][x] = v + 3;
        m[y + size][x + size] = v + 1;
      }
    size *= 2;
  }
  return m;
}
constexpr auto kBayer = makeBayer();

// Ordered dither must move a colour by up to half a palette spacing either
// way so the threshold can choose between neighbouring entries. A median-cut
// palette is dense where the picture's colours are, so the spacing is
// measured, not assumed: the mean distance from each entry to its nearest
// other entry. (The cube-filling estimate 256 / cbrt(K) gave 3 to 19 times
// the MSE of this one on the benchmark images, 160x120 quick runs.)
int bayerAmplitude(const Palette& palette) {
  if (palette.size() < 2) return 0;
  double sum = 0;
  for (std::size_t i = 0; i < palette.size(); ++i) {
    int nearest = 3 * 255 * 255;
    for (std::size_t j = 0; j < palette.size(); ++j) {
      if (i == j) continue;
      Rgb8 c = palette[j];
      nearest = std::min(nearest, distanceSquared(palette[i].r, palette[i].g, palette[i].b, c));
    }
    sum += std::sqrt(double(nearest));
  }
  return static_cast<int>(std::lround(sum / double(palette.size()) / 2.0));
}

Color18 toColor18(int r, int g, int b) {
  return packColor18(reduce8to6(unsigned(r)), reduce8to6(unsigned(g)), reduce8to6(unsigned(b)));
}

}  // namespace

RowMapper::RowMapper(InverseColorMap& map, int width, Dither dither) : map_(map), width_(width), dither_(dither) {
  if (width < 1) throw Error(ErrorKind::Internal, fmt::format("row mapper: width {} must be positive", width));
  if (dither_ == Dither::FloydSteinberg) errors_.assign((static_cast<std::size_t>(width) + 2) * 3, 0);
  if (dither_ == Dither::Bayer) bayerSpread_ = bayerAmplitude(map_.palette());
}

void RowMapper::mapRow(int y, std::span<const Color18> in, std::span<PaletteIndex> out) {
  if (in.size() != static_cast<std::size_t>(width_) || out.size() != in.size())
    throw Error(ErrorKind::Internal, fmt::format("row mapper: row of {} pixels, expected {}", in.size(), width_));
  switch (dither_) {
    case Dither::None: mapPlain(in, out); break;
    case Dither::FloydSteinberg: mapFloydSteinberg(y, in, out); break;
    case Dither::Bayer: mapBayer(y, in, out); break;
  }
}

void RowMapper::mapPlain(std::span<const Color18> in, std::span<PaletteIndex> out) {
  for (std::size_t x = 0; x < in.size(); ++x) out[x] = map_.nearest(in[x]);
}

void RowMapper::mapBayer(int y, std::span<const Color18> in, std::span<PaletteIndex> out) {
  const auto& thresholds = kBayer[static_cast<std::size_t>(y) & 7u];
  for (std::size_t x = 0; x < in.size(); ++x) {
    // Threshold centred on zero: (2m + 1 - 64) / 128 lies in (-1/2, 1/2).
    int offset = (2 * thresholds[x & 7u] + 1 - 64) * bayerSpread_ / 64;
    Color18 c = in[x];
    out[x] = map_.nearest(toColor18(clamp8(expand6to8(red6(c)) + offset), clamp8(expand6to8(green6(c)) + offset),
                                    clamp8(expand6to8(blue6(c)) + offset)));
  }
}

// Serpentine Floyd-Steinberg with one error row. errors_ slot x+1 holds, for
// pixel x, the error (in sixteenths) diffused from the row above. While
// pixel x is processed, slot x-dir has already been read, so it is free to
// take its final next-row value; the two next-row sums still open (for x-dir
// and x) live in `behind`/`here`, and the 7/16 share for x+dir in `carry`.
void RowMapper::mapFloydSteinberg(int y, std::span<const Color18> in, std::span<PaletteIndex> out) {
  const int dir = (y % 2 == 0) ? 1 : -1;
  const int first = dir > 0 ? 0 : width_ - 1;
  std::array<int, 3> carry{0, 0, 0}, behind{0, 0, 0}, here{0, 0, 0};
  const Palette& palette = map_.palette();
  auto slot = [&](int x) { return static_cast<std::size_t>(x + 1) * 3; };
  int x = first;
  for (int i = 0; i < width_; ++i, x += dir) {
    Color18 c = in[static_cast<std::size_t>(x)];
    std::array<int, 3> source{expand6to8(red6(c)), expand6to8(green6(c)), expand6to8(blue6(c))};
    std::array<int, 3> wanted{};
    for (int ch = 0; ch < 3; ++ch)
      wanted[ch] = clamp8(source[ch] + divide16(errors_[slot(x) + ch] + carry[ch]));
    PaletteIndex index = map_.nearest(toColor18(wanted[0], wanted[1], wanted[2]));
    out[static_cast<std::size_t>(x)] = index;
    Rgb8 shown = palette[index];
    std::array<int, 3> got{shown.r, shown.g, shown.b};
    for (int ch = 0; ch < 3; ++ch) {
      int e = wanted[ch] - got[ch];
      errors_[slot(x - dir) + ch] = behind[ch] + 3 * e;  // pad slot when x is the first pixel
      behind[ch] = here[ch] + 5 * e;
      here[ch] = e;
      carry[ch] = 7 * e;
    }
  }
  int last = x - dir;
  for (int ch = 0; ch < 3; ++ch) errors_[slot(last) + ch] = behind[ch];
}

}  // namespace lattice::quantize
