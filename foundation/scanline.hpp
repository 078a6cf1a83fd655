#pragma once
// The one scanline interface between renderer, quantizer and device driver.
//
//   RowSource18 (renderer)  --rows of Color18-->  quantizer
//   quantizer               --palette, rows of indices-->  IndexedSink (driver)
//
// Only O(width) pixels cross a stage boundary at a time. A RowSource18 must be
// deterministic: asking for row y twice gives the same colours, so a
// two-pass quantizer (histogram pass, then mapping pass) can re-render.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace lattice {

// 18-bit colour, 6 bits a channel, packed r<<12 | g<<6 | b (0..2^18-1), the
// form the thesis's *model* produced and the index of the quantizer's histogram.
using Color18 = std::uint32_t;

constexpr Color18 packColor18(unsigned r6, unsigned g6, unsigned b6) {
  return static_cast<Color18>((r6 & 63u) << 12 | (g6 & 63u) << 6 | (b6 & 63u));
}
constexpr unsigned red6(Color18 c) { return (c >> 12) & 63u; }
constexpr unsigned green6(Color18 c) { return (c >> 6) & 63u; }
constexpr unsigned blue6(Color18 c) { return c & 63u; }
// 6-bit channel to 8 bits with rounding (0 -> 0, 63 -> 255).
constexpr std::uint8_t expand6to8(unsigned v6) {
  return static_cast<std::uint8_t>((v6 * 255u + 31u) / 63u);
}
// 8-bit channel to 6 bits, rounding to nearest.
constexpr unsigned reduce8to6(unsigned v8) { return (v8 * 63u + 127u) / 255u; }

// A palette entry: 8 bits a gun, the precision devices are given colours in
// (each driver converts further: Tek 0..100 percent, 4027 HLS, Apollo 0xRRGGBB).
struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb8&, const Rgb8&) = default;
};

using Palette = std::vector<Rgb8>;
// Palette index of one pixel. At most 256 colours on any supported device.
using PaletteIndex = std::uint8_t;

// Producer of rows of 18-bit colour, top row first (y = 0 is the top).
class RowSource18 {
 public:
  virtual ~RowSource18() = default;
  virtual int width() const = 0;
  virtual int height() const = 0;
  // Fill out (size width()) with row y. Deterministic; may be called more than
  // once per row and in any order.
  virtual void row(int y, std::span<Color18> out) = 0;
};

// What a consumer of indexed rows is told before the first row.
struct FrameInfo {
  int width = 0;
  int height = 0;
  Palette palette;  // size <= the sink's maxColors()
};

// Consumer of quantized rows: device drivers, the indexed-image collector.
class IndexedSink {
 public:
  virtual ~IndexedSink() = default;
  // How many palette entries the device can show (2^planes, minus reserved).
  virtual int maxColors() const = 0;
  virtual void begin(const FrameInfo& frame) = 0;
  // Offered just before row(y) by a quantizer that has them: the colours the
  // row's indices stand for, before quantizing. Most sinks ignore it; one that
  // measures error against the picture itself keeps it
  // (quantize/rate_distortion_runs.hpp).
  virtual void truecolourRow(int /*y*/, std::span<const Color18> /*colours*/) {}
  // Rows arrive in order y = 0 .. height-1, each of size width.
  virtual void row(int y, std::span<const PaletteIndex> indices) = 0;
  virtual void end() = 0;
};

}  // namespace lattice
