#include <catch2/catch.hpp>

#include <cstdlib>

#include "devices/tek4027/tek4027_hls.hpp"

using namespace lattice;
using namespace lattice::tek4027;

TEST_CASE("Tek HLS puts blue at hue 0, red at 120, green at 240") {
  CHECK(rgbToTekHls({0, 0, 255}) == Hls{0, 50, 100});
  CHECK(rgbToTekHls({255, 0, 0}) == Hls{120, 50, 100});
  CHECK(rgbToTekHls({0, 255, 0}) == Hls{240, 50, 100});
  CHECK(rgbToTekHls({255, 255, 0}) == Hls{180, 50, 100});
  CHECK(rgbToTekHls({0, 0, 0}) == Hls{0, 0, 0});
  CHECK(rgbToTekHls({255, 255, 255}) == Hls{0, 100, 0});
  CHECK(rgbToTekHls({128, 128, 128}) == Hls{0, 50, 0});
}

TEST_CASE("Tek HLS to RGB inverts the primaries exactly") {
  CHECK(tekHlsToRgb({0, 50, 100}) == Rgb8{0, 0, 255});
  CHECK(tekHlsToRgb({120, 50, 100}) == Rgb8{255, 0, 0});
  CHECK(tekHlsToRgb({240, 50, 100}) == Rgb8{0, 255, 0});
  CHECK(tekHlsToRgb({300, 50, 100}) == Rgb8{0, 255, 255});
  CHECK(tekHlsToRgb({0, 100, 0}) == Rgb8{255, 255, 255});
  CHECK(tekHlsToRgb({0, 25, 0}) == Rgb8{64, 64, 64});
}

TEST_CASE("Tek HLS to RGB wraps hue and clamps lightness and saturation") {
  CHECK(tekHlsToRgb({360 + 120, 50, 100}) == tekHlsToRgb({120, 50, 100}));
  CHECK(tekHlsToRgb({-240, 50, 100}) == tekHlsToRgb({120, 50, 100}));
  CHECK(tekHlsToRgb({0, 150, 0}) == Rgb8{255, 255, 255});
  CHECK(tekHlsToRgb({0, 50, -20}) == tekHlsToRgb({0, 50, 0}));
}

TEST_CASE("RGB -> Tek HLS -> RGB stays within the documented bound over the whole cube") {
  int worst = 0;
  long outOfRange = 0;
  Rgb8 worstColour;
  for (int r = 0; r < 256; ++r)
    for (int g = 0; g < 256; ++g)
      for (int b = 0; b < 256; ++b) {
        const Rgb8 in{std::uint8_t(r), std::uint8_t(g), std::uint8_t(b)};
        const Hls hls = rgbToTekHls(in);
        if (hls.hue < 0 || hls.hue >= 360 || hls.lightness < 0 || hls.lightness > 100 || hls.saturation < 0 ||
            hls.saturation > 100)
          ++outOfRange;
        const Rgb8 out = tekHlsToRgb(hls);
        const int d = std::max({std::abs(in.r - out.r), std::abs(in.g - out.g), std::abs(in.b - out.b)});
        if (d > worst) {
          worst = d;
          worstColour = in;
        }
      }
  INFO("worst colour " << int(worstColour.r) << "," << int(worstColour.g) << "," << int(worstColour.b));
  CHECK(outOfRange == 0);
  CHECK(worst <= kHlsRoundTripMaxDelta);
  // The bound is tight: if the conversion got better, lower the constant and the docs.
  CHECK(worst == kHlsRoundTripMaxDelta);
}
