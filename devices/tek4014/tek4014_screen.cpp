#include "devices/tek4014/tek4014_screen.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdlib>
#include <cstring>

namespace lattice::tek4014 {
namespace {

// Products of a coordinate and a step count overflow 64 bits for the far-off
// points a caller may name; the few divisions a vector needs are done wide.
__extension__ typedef __int128 Wide;

constexpr PaletteIndex kLit = 1;

Wide floorDiv(Wide a, Wide b) {  // b > 0
  Wide q = a / b;
  if (a % b != 0 && a < 0) --q;
  return q;
}

Wide ceilDiv(Wide a, Wide b) { return -floorDiv(-a, b); }  // b > 0

// Words a bitmap line takes: its bits, and one more when that would make a
// group of eight lines a multiple of 4 KiB (every group would then fall in
// the same few cache sets, and a vector crossing many groups would evict
// itself).
long strideOf(long bits) {
  const long words = (bits + 63) / 64;
  return words % 8 == 0 ? words + 1 : words;
}

std::uint64_t bitmapBytesOf(long lines, long bits) {
  return 8 * static_cast<std::uint64_t>((lines + 7) / 8 * 8 * strideOf(bits));
}

// The eight bytes (0 or 1) of the eight bits of a byte, lowest bit first.
constexpr std::array<std::array<PaletteIndex, 8>, 256> kByteDots = [] {
  std::array<std::array<PaletteIndex, 8>, 256> t{};
  for (int b = 0; b < 256; ++b)
    for (int j = 0; j < 8; ++j) t[b][j] = static_cast<PaletteIndex>((b >> j) & 1);
  return t;
}();

// Calls run(from, to) for the runs of steps first..last, in order: the
// steps where a count stays k, k + 1, ... (k is the count at `first`),
// either the carries so far (q(i) = floor((2 i minorDelta + n) / 2n): runs of
// straight steps) or the straight steps so far (i - q(i): runs of diagonal
// steps). Run k starts at the first step whose count reaches k:
//   carries:  q(i) >= k      <=>  i >= (2nk - n) / (2 minorDelta)
//   straight: i - q(i) >= k  <=>  i >  (2nk - n) / (2 (n - minorDelta))
// (a tie is a carry), that is at floor((2nk - n - tie) / d) + 1 with tie 1
// or 0 and d the denominator. The numerator grows by 2n = whole * d + part
// a run, so each start is carried from the last instead of divided again.
template <class Visit>
void forEachRun(long n, long d, long tie, long k, long first, long last, Visit run) {
  if (d == 0) {  // the count never changes: one run
    run(first, last);
    return;
  }
  const Wide num = 2 * Wide{n} * (k + 1) - n - tie;
  const Wide quotient = floorDiv(num, d);
  long next = static_cast<long>(quotient) + 1;
  long rest = static_cast<long>(num - quotient * d);  // num mod d, in [0, d)
  const long whole = 2 * n / d, part = 2 * n % d;
  long i = first;
  while (next <= last) {
    run(i, next - 1);
    i = next;
    // Whether the numerator's growth carries into one more step: as
    // arithmetic, not a branch, because near 45 degrees it is taken at random.
    rest += part;
    const long carry = rest >= d;
    rest -= carry * d;
    next += whole + carry;
  }
  run(i, last);
}

}  // namespace

std::uint64_t Tek4014Screen::Vector::work() const {
  if (steps == 0) return 1;
  return last < first ? 0 : static_cast<std::uint64_t>(last - first + 1);
}

Tek4014Screen::Bitmap::Bitmap(long lineCount, long bitCount)
    : lines(lineCount), length(bitCount), stride(strideOf(bitCount)),
      words(static_cast<std::size_t>((lineCount + 7) / 8 * 8 * stride), 0) {}

template <class Lit>
void Tek4014Screen::Bitmap::forEachSet(Lit lit) const {
  // A word of every line, then the next: the pixels lit stay near each other.
  for (long k = 0; k < (length + 63) / 64; ++k)
    for (long line = 0; line < lines; ++line)
      for (std::uint64_t bits = word(line, k); bits != 0; bits &= bits - 1)
        lit(line, 64 * k + std::countr_zero(bits));
}

Tek4014Screen::Tek4014Screen(int width, int height)
    : width_(width), height_(height), rows_(height, width), columns_(width, height),
      diagonals_(long{width} + height - 1, width), antidiagonals_(long{width} + height - 1, width) {}

std::uint64_t Tek4014Screen::bitmapBytes(int width, int height) {
  const long diagonalLines = long{width} + height - 1;
  return bitmapBytesOf(height, width) + bitmapBytesOf(width, height) + 2 * bitmapBytesOf(diagonalLines, width);
}

Tek4014Screen::Vector Tek4014Screen::vector(long x0, long y0, long x1, long y1) const {
  Vector v;
  v.x0 = x0;
  v.y0 = y0;
  const long dx = x1 - x0, dy = y1 - y0;
  v.xMajor = std::labs(dx) >= std::labs(dy);
  const long dMajor = v.xMajor ? dx : dy, dMinor = v.xMajor ? dy : dx;
  const long major = v.xMajor ? x0 : y0, minor = v.xMajor ? y0 : x0;
  v.majorSign = dMajor >= 0 ? 1 : -1;
  v.minorSign = dMinor >= 0 ? 1 : -1;
  v.steps = std::labs(dMajor);
  v.minorDelta = std::labs(dMinor);
  const long majorLast = (v.xMajor ? width_ : height_) - 1;
  const long minorLast = (v.xMajor ? height_ : width_) - 1;
  // Step i is at major + majorSign * i along the major axis ...
  const long lo = v.majorSign > 0 ? -major : major - majorLast;
  const long hi = v.majorSign > 0 ? majorLast - major : major;
  // ... and at minor + minorSign * q(i) along the other, q(i) = floor((2 i
  // minorDelta + n) / 2n): ties away from the start. q never falls and goes
  // through every value 0..minorDelta (minorDelta <= n), so the steps whose q
  // is on the screen are one range, from the first step of the lowest such q
  // to the step before the first of the one past the highest.
  const long qLo = std::max(0L, v.minorSign > 0 ? -minor : minor - minorLast);
  const long qHi = std::min(v.minorDelta, v.minorSign > 0 ? minorLast - minor : minor);
  if (qLo > qHi) return v;
  const Wide n = v.steps, d = 2 * Wide{v.minorDelta};
  auto runStart = [&](long q) -> Wide {  // the first step i with q(i) >= q
    if (q <= 0) return 0;
    if (v.minorDelta == 0) return n + 1;
    return ceilDiv(2 * n * q - n, d);
  };
  v.first = static_cast<long>(std::max({Wide{0}, Wide{lo}, runStart(qLo)}));
  v.last = static_cast<long>(std::min({n, Wide{hi}, runStart(qHi + 1) - 1}));
  return v;
}

void Tek4014Screen::draw(const Vector& vector) {
  const Vector v = vector;
  if (v.last < v.first) return;
  const long n = v.steps, ms = v.majorSign, ns = v.minorSign;
  // The first visible pixel: step `first`, after q0 carries.
  const long q0 = n == 0 ? 0 : static_cast<long>(floorDiv(2 * Wide{v.first} * v.minorDelta + n, 2 * Wide{n}));
  const long major = (v.xMajor ? v.x0 : v.y0) + ms * v.first, minor = (v.xMajor ? v.y0 : v.x0) + ns * q0;
  const long x = v.xMajor ? major : minor, y = v.xMajor ? minor : major;
  Run run;
  if (2 * v.minorDelta <= n) {
    // Mostly straight steps: runs along rows (or columns), joined by
    // diagonal steps; counted by carries.
    run = {v.xMajor ? rows_.view() : columns_.view(), minor, ns, major, ms};
    if (ms > 0) drawRuns<1>(run, n, 2 * v.minorDelta, 1, q0, v.first, v.last);
    else drawRuns<-1>(run, n, 2 * v.minorDelta, 1, q0, v.first, v.last);
    return;
  }
  // Mostly diagonal steps: runs along diagonals, joined by straight steps;
  // counted by straight steps. The diagonal step rises (y - x constant) or
  // falls (x + y constant); its bits are along x, which moves a step along
  // it and, when x is the major axis, a step between two runs too.
  const bool rises = ms == ns;
  run = {rises ? diagonals_.view() : antidiagonals_.view(), rises ? y - x + width_ - 1 : x + y,
         rises && v.xMajor ? -ms : ms, x, v.xMajor ? ms : 0};
  const long along = v.xMajor ? ms : ns;
  if (along > 0) drawRuns<1>(run, n, 2 * (n - v.minorDelta), 0, v.first - q0, v.first, v.last);
  else drawRuns<-1>(run, n, 2 * (n - v.minorDelta), 0, v.first - q0, v.first, v.last);
}

template <int Along>
void Tek4014Screen::drawRuns(Run r, long n, long d, long tie, long count, long first, long last) {
  // Locals, not r's fields: stores to the bitmap cannot change them, so they
  // stay in registers.
  const Lines lines = r.lines;
  const long lineStep = r.lineStep, gap = r.gap;
  long line = r.line, position = r.position;
  forEachRun(n, d, tie, count, first, last, [&](long from, long to) {
    const long end = position + Along * (to - from);
    if constexpr (Along > 0) lines.set(line, position, end);
    else lines.set(line, end, position);
    line += lineStep;
    position = end + gap;
  });
}

void Tek4014Screen::clear() {
  for (Bitmap* b : {&rows_, &columns_, &diagonals_, &antidiagonals_}) std::fill(b->words.begin(), b->words.end(), 0);
}

void Tek4014Screen::paint(IndexedImage& image) const {
  const long w = width_, xLast = width_ - 1;
  auto lit = [&](long x, long y) { image.pixels[static_cast<std::size_t>((height_ - 1 - y) * w + x)] = kLit; };
  // The row bitmap sets every pixel, a byte of bits at a time ...
  for (long y = 0; y < height_; ++y) {
    PaletteIndex* out = image.pixels.data() + (height_ - 1 - y) * w;
    for (long x = 0; x < w; x += 8) {
      const auto byte = static_cast<std::uint8_t>(rows_.word(y, x >> 6) >> (x & 63));
      std::memcpy(out + x, kByteDots[byte].data(), static_cast<std::size_t>(std::min(8L, w - x)));
    }
  }
  // ... and the others add their lit ones.
  columns_.forEachSet([&](long x, long y) { lit(x, y); });
  diagonals_.forEachSet([&](long line, long x) { lit(x, line - xLast + x); });
  antidiagonals_.forEachSet([&](long line, long x) { lit(x, line - x); });
}

}  // namespace lattice::tek4014
