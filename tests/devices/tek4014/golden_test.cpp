// The stream the driver writes for small synthetic frames and what the
// emulator shows for it, against files in tests/golden/tek4014/: the 10-bit
// default (Floyd-Steinberg), the ordered dither, and the 12-bit form. The
// screen PNGs are cropped to the frame's corner (the rest is dark, checked
// by the round-trip tests). scripts/regenerate-goldens.sh rewrites them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "io/png.hpp"
#include "tests/devices/tek4014/drive_frame.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"
#include "tests/support/golden.hpp"

using namespace lattice;
using namespace lattice::tek4014;
using namespace lattice::tek4014::test;

namespace {

// The lower-left w x h corner of the screen, as RGB.
RgbImage corner(const IndexedImage& screen, int w, int h) {
  RgbImage out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgb8 c = screen.colorAt(x, screen.height - h + y);
      std::uint8_t* p = out.pixel(x, y);
      p[0] = c.r;
      p[1] = c.g;
      p[2] = c.b;
    }
  return out;
}

void checkGolden(const std::string& name, const IndexedImage& img, const Tek4014Profile& profile) {
  const auto stream = driveFrame(img, profile);
  testing::checkGoldenBytes("tek4014/" + name + ".tek", stream);
  const Tek4014Decoder d = decode(stream, profile);
  CHECK(d.report().malformed == 0);
  CHECK(d.report().unknownCommands == 0);
  testing::checkGoldenPng("tek4014/" + name + "-screen.png", corner(d.image(), img.width, img.height));
}

}  // namespace

TEST_CASE("golden: 4014 rings 96x64, 10-bit, Floyd-Steinberg") {
  checkGolden("rings-96x64", testing::ringsImage(96, 64), Tek4014Profile{});
}

TEST_CASE("golden: 4014 gradient 64x40, ordered dither") {
  Tek4014Profile profile;
  profile.dither = Tek4014Dither::Ordered;
  checkGolden("gradient-64x40-ordered", testing::gradientImage(64, 40), profile);
}

TEST_CASE("golden: 4014 rings 96x64, 12-bit addresses") {
  Tek4014Profile profile;
  profile.addressBits = 12;
  checkGolden("rings-96x64-12bit", testing::ringsImage(96, 64), profile);
}
