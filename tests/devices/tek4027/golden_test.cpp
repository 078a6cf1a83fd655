// The stream the driver writes for a small synthetic frame, and what the
// emulator shows for it, against files in tests/golden/tek4027/, in both
// profiles: the strict (default) goldens keep the plain names, the compact
// ones carry `-compact`. A change in either is a visible diff to review
// (scripts/regenerate-goldens.sh).
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

#include "devices/tek4027/tek4027_decoder.hpp"
#include "devices/tek4027/tek4027_driver.hpp"
#include "foundation/byte_sink.hpp"
#include "io/png.hpp"
#include "tests/devices/tek4027/drive_frame.hpp"
#include "tests/devices/tek4027/synthetic_images.hpp"
#include "tests/support/golden.hpp"

using namespace lattice;
using namespace lattice::io;
using namespace lattice::tek4027;
using namespace lattice::tek4027::test;

namespace {

std::vector<std::uint8_t> drive(const IndexedImage& img, const Tek4027Profile& profile) {
  const std::string text = test::driveFrame(img, profile);
  return {text.begin(), text.end()};
}

// The emulator's screen for a stream that must decode without complaint.
IndexedImage cleanDecode(const std::vector<std::uint8_t>& stream, const Tek4027Profile& profile) {
  Tek4027Decoder decoder(profile);
  decoder.feed(stream);
  decoder.finish();
  CHECK(decoder.report().malformed == 0);
  CHECK(decoder.report().unknownCommands == 0);
  return decoder.image();
}

std::string suffix(const std::string& profileName) { return profileName == "strict" ? "" : "-" + profileName; }

}  // namespace

TEST_CASE("golden: rings 48x32 stream and emulated screen") {
  for (const std::string& name : tek4027PresetNames()) {
    INFO("profile " << name);
    const Tek4027Profile profile = tek4027Preset(name);
    const auto stream = drive(testing::ringsImage(48, 32), profile);
    testing::checkGoldenBytes("tek4027/rings-48x32" + suffix(name) + ".tek", stream);

    testing::checkGoldenPng("tek4027/rings-48x32-screen" + suffix(name) + ".png",
                            toRgbImage(cleanDecode(stream, profile)));
  }
}

TEST_CASE("golden: all eight pots, gradient 40x24") {
  for (const std::string& name : tek4027PresetNames()) {
    INFO("profile " << name);
    const Tek4027Profile profile = tek4027Preset(name);
    auto img = testing::gradientImage(40, 24);
    const auto stream = drive(img, profile);
    testing::checkGoldenBytes("tek4027/gradient-40x24" + suffix(name) + ".tek", stream);

    // Crop to the frame: the rest of the screen is the erase colour.
    RgbImage screen = toRgbImage(cleanDecode(stream, profile));
    RgbImage frame(img.width, img.height);
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) std::copy_n(screen.pixel(x, y), 3, frame.pixel(x, y));
    testing::checkGoldenPng("tek4027/gradient-40x24-frame" + suffix(name) + ".png", frame);
  }
}
