// Byte-exact stream and decoded picture for one small synthetic image under
// each form set (strict: no suffix; compact: _compact), so any change to what
// goes down the wire is seen in review.
// Regenerate: LATTICE_REGENERATE_GOLDENS=1 (scripts/regenerate-goldens.sh).
#include <catch2/catch.hpp>

#include "tests/devices/tek4125/tek_test_support.hpp"
#include "tests/support/golden.hpp"

#include <fmt/format.h>

using namespace lattice;
using namespace lattice::tek4125;
using namespace lattice::tek4125::test;

TEST_CASE("golden: a 24x16 scene at 4 and 8 planes, strict and compact") {
  for (const std::string forms : {"strict", "compact"})
  for (int planes : {4, 8}) {
    Tek4125Profile profile;
    profile.forms = forms;
    profile.planes = planes;
    const IndexedImage img = scene(24, 16, planes == 4 ? 16 : 40);
    const std::vector<std::uint8_t> bytes = encode(img, profile);
    const std::string stem =
        fmt::format("tek4125/scene24x16_{}planes{}", planes, forms == "strict" ? "" : "_" + forms);
    lattice::testing::checkGoldenBytes(stem + ".tek", bytes);
    Tek4125Decoder decoder(profile);
    decoder.feed(bytes);
    decoder.finish();
    const IndexedImage picture = cutPicture(decoder.image(), profile, img.width, img.height);
    lattice::testing::checkGoldenPng(stem + ".png", toRgbImage(picture));
    // The golden picture is the input's colours within the percent rounding.
    CHECK(lattice::testing::compareImages(toRgbImage(picture), toRgbImage(img)).maxChannelDelta <= 2);
  }
}
