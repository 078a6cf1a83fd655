#include "devices/tek_hls.hpp"

#include <algorithm>
#include <cmath>

namespace lattice::devices {

namespace {

// Tektronix hue = textbook hue + 120 (blue moves from 240 to 0).
constexpr double kTekHueOffset = 120.0;

int roundToInt(double v) { return static_cast<int>(std::lround(v)); }

// One gun of the textbook HLS -> RGB: hue in degrees (any value).
double hlsGun(double m1, double m2, double hue) {
  hue = std::fmod(hue, 360.0);
  if (hue < 0) hue += 360.0;
  if (hue < 60.0) return m1 + (m2 - m1) * hue / 60.0;
  if (hue < 180.0) return m2;
  if (hue < 240.0) return m1 + (m2 - m1) * (240.0 - hue) / 60.0;
  return m1;
}

}  // namespace

Hls rgbToTekHls(Rgb8 rgb) {
  const double r = rgb.r / 255.0, g = rgb.g / 255.0, b = rgb.b / 255.0;
  const double hi = std::max({r, g, b});
  const double lo = std::min({r, g, b});
  const double l = (hi + lo) / 2.0;
  Hls out;
  out.lightness = roundToInt(l * 100.0);
  if (hi == lo) return out;  // a grey: hue is meaningless, saturation 0
  const double d = hi - lo;
  const double s = l <= 0.5 ? d / (hi + lo) : d / (2.0 - hi - lo);
  double h;
  if (hi == r)
    h = (g - b) / d;
  else if (hi == g)
    h = 2.0 + (b - r) / d;
  else
    h = 4.0 + (r - g) / d;
  h = h * 60.0 + kTekHueOffset;
  int hue = roundToInt(h) % 360;
  if (hue < 0) hue += 360;
  out.hue = hue;
  out.saturation = roundToInt(s * 100.0);
  return out;
}

Rgb8 tekHlsToRgb(Hls hls) {
  const double l = std::clamp(hls.lightness, 0, 100) / 100.0;
  const double s = std::clamp(hls.saturation, 0, 100) / 100.0;
  const double hue = static_cast<double>(hls.hue % 360) - kTekHueOffset;
  auto gun = [](double v) { return static_cast<std::uint8_t>(std::clamp(roundToInt(v * 255.0), 0, 255)); };
  if (s == 0.0) return {gun(l), gun(l), gun(l)};
  const double m2 = l <= 0.5 ? l * (1.0 + s) : l + s - l * s;
  const double m1 = 2.0 * l - m2;
  return {gun(hlsGun(m1, m2, hue + 120.0)), gun(hlsGun(m1, m2, hue)), gun(hlsGun(m1, m2, hue - 120.0))};
}

}  // namespace lattice::devices
