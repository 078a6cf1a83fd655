// Stream-size strategies under both form sets: the default ("shortest")
// must never be larger than a named strategy by more than the cost model's
// slack, and the savings must be real. The byte figures in docs/tek4125.md
// come from bench/stream-bytes.sh on the example scenes.
#include <catch2/catch.hpp>

#include <fmt/format.h>

#include "tests/devices/tek4125/tek_test_support.hpp"

using namespace lattice;
using namespace lattice::tek4125;
using namespace lattice::tek4125::test;

namespace {

Tek4125Profile profileWith(const std::string& forms, int planes) {
  Tek4125Profile p;
  p.forms = forms;
  p.planes = planes;
  return p;
}

}  // namespace

TEST_CASE("the shortest strategy is never larger than a named one, in either form set") {
  for (const std::string forms : {"strict", "compact"})
    for (int planes : {4, 8}) {
      const Tek4125Profile profile = profileWith(forms, planes);
      const int colors = profile.maxColors();
      for (const IndexedImage& img : {scene(256, 256, colors), flat(256, 256, colors, 3),
                                      gradient(256, 256, colors), noise(128, 128, colors, 2u)}) {
        const std::size_t shortest = encode(img, profile).size();
        for (const Tek4125NamedStrategy& s : tek4125Strategies()) {
          const std::size_t other = encode(img, profile, s.options).size();
          INFO(forms << " planes " << planes << " " << s.name << " " << other << " shortest " << shortest);
          CHECK(shortest <= other + other / 200);  // the cost model is an estimate: 0.5% slack
        }
      }
    }
}

TEST_CASE("the savings are real: the shortest stream beats one raster write per row by far") {
  // 16 colours: RP at 4 bits is a form both sets allow, so "plain" is RP rows in both.
  for (const std::string forms : {"strict", "compact"}) {
    const Tek4125Profile profile = profileWith(forms, 8);
    const IndexedImage img = scene(256, 256, 16);
    const std::size_t shortest = encode(img, profile).size();
    const std::size_t plain = encode(img, profile, tek4125Strategy("plain").options).size();
    INFO(forms << " shortest " << shortest << " plain " << plain);
    CHECK(shortest * 10 < plain * 8);
  }
  // Strictness costs bytes, never pixels: the two form sets draw the same picture.
  const IndexedImage img = scene(200, 120, 256);
  const Tek4125Profile strict = profileWith("strict", 8), compact = profileWith("compact", 8);
  const auto strictBytes = encode(img, strict), compactBytes = encode(img, compact);
  CHECK(compactBytes.size() < strictBytes.size());
  Tek4125Decoder a(strict), b(compact);
  a.feed(strictBytes);
  b.feed(compactBytes);
  CHECK(cutPicture(a.image(), strict, img.width, img.height).pixels ==
        cutPicture(b.image(), compact, img.width, img.height).pixels);
}

TEST_CASE("a one-colour picture is one rectangle, merging rows is what makes it one") {
  for (const std::string forms : {"strict", "compact"}) {
    INFO(forms);
    const Tek4125Profile profile = profileWith(forms, 8);
    Tek4125StreamStats stats;
    // Its only colour is the most frequent: painted once, every run skipped.
    encode(flat(300, 200, 8, 5), profile, {}, &stats);
    CHECK(stats.rectangleFills == 1);
    CHECK(stats.rasterWrites + stats.runLengthWrites == 0);
    CHECK(stats.skippedPixels == 300u * 200u);
    // Without skipping: RR merged down the rows, or one a row without merging.
    encode(flat(300, 200, 8, 5), profile, tek4125Strategy("rectangles").options, &stats);
    CHECK(stats.rectangleFills == 200);
    Tek4125DriverOptions merged = tek4125Strategy("rectangles").options;
    merged.mergeRows = true;
    encode(flat(300, 200, 8, 5), profile, merged, &stats);
    CHECK(stats.rectangleFills == 1);
  }
  // Compact leaves a picture of colour 0 to the clear; strict paints it.
  Tek4125StreamStats stats;
  encode(flat(300, 200, 8, 0), profileWith("compact", 8), {}, &stats);
  CHECK(stats.rectangleFills == 0);
  encode(flat(300, 200, 8, 0), profileWith("strict", 8), {}, &stats);
  CHECK(stats.rectangleFills == 1);
}

TEST_CASE("a picture of at most 16 colours is sent at 4 bits a pixel on an 8-plane terminal") {
  for (const std::string forms : {"strict", "compact"}) {
    const Tek4125Profile profile = profileWith(forms, 8);
    const IndexedImage small = noise(120, 30, 16, 8u), large = noise(120, 30, 17, 8u);
    Tek4125StreamStats smallStats, largeStats;
    const auto smallBytes = encode(small, profile, {}, &smallStats);
    const auto largeBytes = encode(large, profile, {}, &largeStats);
    INFO(forms << " 16 colours " << smallBytes.size() << " B, 17 colours " << largeBytes.size() << " B");
    CHECK(smallStats.rasterBits == 4);
    CHECK(largeStats.rasterBits == 8);
    CHECK(smallBytes.size() * 10 < largeBytes.size() * 7);
    Tek4125Decoder decoder(profile);
    decoder.feed(smallBytes);
    CHECK(cutPicture(decoder.image(), profile, small.width, small.height).pixels == small.pixels);
  }
}
