#include "devices/tek4125/tek4125_encoding.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "foundation/error.hpp"

namespace lattice::tek4125 {

void appendCommand(Bytes& out, std::string_view name) {
  out.push_back(kEsc);
  out.insert(out.end(), name.begin(), name.end());
}

void appendInt(Bytes& out, int value) {
  const int magnitude = std::abs(value);
  if (magnitude > kMaxIntMagnitude)
    throw Error(ErrorKind::Internal, fmt::format("tek4125: integer parameter {} is outside -65535..65535", value));
  const auto hi1 = static_cast<std::uint8_t>(magnitude >> 10);
  const auto hi2 = static_cast<std::uint8_t>((magnitude >> 4) & 63);
  if (hi1 != 0) out.push_back(static_cast<std::uint8_t>(0x40 | hi1));
  if (hi1 != 0 || hi2 != 0) out.push_back(static_cast<std::uint8_t>(0x40 | hi2));
  out.push_back(static_cast<std::uint8_t>(0x20 | (magnitude & 15) | (value >= 0 ? 0x10 : 0)));
}

int intLength(int value) {
  const int magnitude = std::abs(value);
  return magnitude >= 1024 ? 3 : magnitude >= 16 ? 2 : 1;
}

void appendIntArray(Bytes& out, std::span<const int> values) {
  appendInt(out, static_cast<int>(values.size()));
  for (int v : values) appendInt(out, v);
}

void appendReal(Bytes& out, int mantissa, int exponent) {
  appendInt(out, mantissa);
  appendInt(out, exponent);
}

void appendReal(Bytes& out, double value) {
  if (!std::isfinite(value))
    throw Error(ErrorKind::Internal, "tek4125: a real parameter must be finite");
  if (value == 0.0) return appendReal(out, 0, 0);
  // frexp gives value = f * 2^e with 0.5 <= |f| < 1; scale f to 16 bits.
  int e = 0;
  double f = std::frexp(value, &e);
  long m = std::lround(f * 65536.0);
  int exponent = e - 16;
  if (std::labs(m) > kMaxIntMagnitude) {  // f rounded up to 1.0
    m /= 2;
    ++exponent;
  }
  while (m != 0 && m % 2 == 0 && exponent < 0) {  // shortest form of the same value
    m /= 2;
    ++exponent;
  }
  if (std::abs(exponent) > kMaxIntMagnitude)
    throw Error(ErrorKind::Internal, fmt::format("tek4125: real parameter {} is out of range", value));
  appendReal(out, static_cast<int>(m), exponent);
}

void appendString(Bytes& out, std::string_view text) {
  appendInt(out, static_cast<int>(text.size()));
  out.insert(out.end(), text.begin(), text.end());
}

XyBytes xyBytes(int x, int y) {
  if (x < 0 || x > kMaxCoordinate || y < 0 || y > kMaxCoordinate)
    throw Error(ErrorKind::Internal, fmt::format("tek4125: coordinate ({}, {}) is outside 0..4095", x, y));
  XyBytes b;
  b.hiY = static_cast<std::uint8_t>(0x20 | (y >> 7));
  b.extra = static_cast<std::uint8_t>(0x60 | (y & 3) << 2 | (x & 3));
  b.loY = static_cast<std::uint8_t>(0x60 | ((y >> 2) & 31));
  b.hiX = static_cast<std::uint8_t>(0x20 | (x >> 7));
  b.loX = static_cast<std::uint8_t>(0x40 | ((x >> 2) & 31));
  return b;
}

namespace {
struct XyPlan {
  bool hiY, extra, loY, hiX;
};
XyPlan plan(const XyBytes& now, const XyBytes& last, bool known) {
  XyPlan p;
  p.hiY = !known || now.hiY != last.hiY;
  p.extra = !known || now.extra != last.extra;
  p.hiX = !known || now.hiX != last.hiX;
  p.loY = !known || now.loY != last.loY || p.extra || p.hiX;
  return p;
}
}  // namespace

void XyEncoder::append(Bytes& out, int x, int y) {
  const XyBytes now = xyBytes(x, y);
  const XyPlan p = plan(now, last_, known_);
  if (p.hiY) out.push_back(now.hiY);
  if (p.extra) out.push_back(now.extra);
  if (p.loY) out.push_back(now.loY);
  if (p.hiX) out.push_back(now.hiX);
  out.push_back(now.loX);
  last_ = now;
  known_ = true;
}

void XyEncoder::appendHighShort(Bytes& out, int x, int y) {
  const XyBytes now = xyBytes(x, y);
  if (!known_ || now.hiY != last_.hiY) out.push_back(now.hiY);
  out.push_back(now.extra);
  out.push_back(now.loY);
  if (!known_ || now.hiX != last_.hiX) out.push_back(now.hiX);
  out.push_back(now.loX);
  last_ = now;
  known_ = true;
}

int XyEncoder::highShortLength(int x, int y) const {
  const XyBytes now = xyBytes(x, y);
  return 3 + int(!known_ || now.hiY != last_.hiY) + int(!known_ || now.hiX != last_.hiX);
}

int XyEncoder::length(int x, int y) const {
  const XyPlan p = plan(xyBytes(x, y), last_, known_);
  return 1 + int(p.hiY) + int(p.extra) + int(p.loY) + int(p.hiX);
}

}  // namespace lattice::tek4125
