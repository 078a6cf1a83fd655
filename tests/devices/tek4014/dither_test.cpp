// The 4014 driver's dither: luminance in linear light, and each method's
// share of lit dots following it.
#include <catch2/catch.hpp>

#include <numeric>

#include "devices/tek4014/tek4014_dither.hpp"
#include "tests/devices/tek4014/drive_frame.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"

using namespace lattice;
using namespace lattice::tek4014;

TEST_CASE("4014 dither: linear-light luminance of the primaries and of mid grey") {
  CHECK(linearLuminance({0, 0, 0}) == Approx(0.0f));
  CHECK(linearLuminance({255, 255, 255}) == Approx(1.0f));
  CHECK(linearLuminance({255, 0, 0}) == Approx(0.2126f));
  CHECK(linearLuminance({0, 255, 0}) == Approx(0.7152f));
  // sRGB 188 is about half the light, not sRGB 128.
  CHECK(linearLuminance({188, 188, 188}) == Approx(0.5f).epsilon(0.02));
  CHECK(linearLuminance({128, 128, 128}) == Approx(0.216f).epsilon(0.02));
}

TEST_CASE("4014 dither: the share of lit dots follows the luminance") {
  for (int level : {0, 40, 100, 128, 188, 230, 255}) {
    const auto grey = static_cast<std::uint8_t>(level);
    const IndexedImage img = testing::singleColourImage(128, 64, {grey, grey, grey});
    const double want = linearLuminance({grey, grey, grey});
    for (Tek4014Dither method : {Tek4014Dither::FloydSteinberg, Tek4014Dither::Ordered}) {
      INFO("level " << level << ", " << ditherName(method));
      const auto dots = tek4014::test::ditheredDots(img, method);
      const double share = std::accumulate(dots.begin(), dots.end(), 0.0) / static_cast<double>(dots.size());
      CHECK(share == Approx(want).margin(1.0 / 64 + 0.005));
    }
    const auto plain = tek4014::test::ditheredDots(img, Tek4014Dither::Threshold);
    CHECK(std::accumulate(plain.begin(), plain.end(), 0) == (want >= 0.5 ? 128 * 64 : 0));
  }
}
