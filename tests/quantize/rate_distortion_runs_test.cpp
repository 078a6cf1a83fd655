// Rate-distortion runs (quantize/rate_distortion_runs.hpp): lambda 0 and a
// vanishing lambda change nothing; a larger lambda merges runs whose colours
// are close before ones whose colours are far, never invents a colour a
// segment did not hold, and the sink in front of a driver hands on exactly
// the rewritten frame. Against the truecolour picture: lambda 0 changes
// nothing, the objective never gets worse than the picture's own, a segment
// may take the entry nearest its mean (a dither's noise is smoothed), and the
// sink uses the truecolour rows when offered.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>

#include "foundation/error.hpp"
#include "quantize/rate_distortion_runs.hpp"

using namespace lattice;
using namespace lattice::quantize;

namespace {

int countRuns(std::span<const PaletteIndex> row) {
  int runs = row.empty() ? 0 : 1;
  for (std::size_t x = 1; x < row.size(); ++x) runs += row[x] != row[x - 1];
  return runs;
}

const RunCost kFlatCost = [](int, int) { return 3.0; };  // every run the same bytes

IndexedImage noise(int width, int height, int colours, unsigned seed) {
  IndexedImage image(width, height, 0);
  for (int i = 0; i < colours; ++i)
    image.colormap.push_back(Rgb8{static_cast<std::uint8_t>(i * 255 / colours), static_cast<std::uint8_t>(i * 7),
                                  static_cast<std::uint8_t>(255 - i * 255 / colours)});
  std::mt19937 rng(seed);
  for (auto& p : image.pixels) p = static_cast<PaletteIndex>(rng() % unsigned(colours));
  return image;
}

double distortion(const IndexedImage& a, const IndexedImage& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) d += colourError(a.colormap[a.pixels[i]], b.colormap[b.pixels[i]]);
  return d;
}

}  // namespace

TEST_CASE("rate-distortion runs: lambda 0 and a vanishing lambda leave the picture alone") {
  const IndexedImage original = noise(97, 13, 16, 1);
  for (double lambda : {0.0, 1e-9}) {
    IndexedImage copy = original;
    rateDistortionImage(copy, kFlatCost, lambda);
    CHECK(copy.pixels == original.pixels);
  }
}

TEST_CASE("rate-distortion runs: larger lambda, fewer runs and more error, colours from the segment") {
  const IndexedImage original = noise(120, 20, 12, 2);
  int lastRuns = 1 << 30;
  double lastError = -1;
  for (double lambda : {100.0, 1000.0, 10000.0, 100000.0}) {
    IndexedImage copy = original;
    rateDistortionImage(copy, kFlatCost, lambda);
    int runs = 0;
    for (int y = 0; y < copy.height; ++y) {
      const auto row = std::span<const PaletteIndex>(copy.pixels).subspan(std::size_t(y) * 120, 120);
      runs += countRuns(row);
      // Each pixel's new colour is one that stood in its own row.
      const auto before = std::span<const PaletteIndex>(original.pixels).subspan(std::size_t(y) * 120, 120);
      const std::set<PaletteIndex> present(before.begin(), before.end());
      for (PaletteIndex p : row) CHECK(present.count(p) == 1);
    }
    const double error = distortion(original, copy);
    INFO("lambda " << lambda << ": " << runs << " runs, error " << error);
    CHECK(runs <= lastRuns);
    CHECK(error >= lastError);
    lastRuns = runs;
    lastError = error;
  }
  CHECK(lastRuns < 20 * 40);  // huge lambda: long runs, far fewer than the noise's ~110 a row
}

TEST_CASE("rate-distortion runs: near colours merge first, a far colour stays") {
  // Row: 10 x A, 1 x A' (1 level off), 10 x A, 1 x Z (far), 10 x A.
  IndexedImage image(32, 1, 0);
  image.colormap = {Rgb8{100, 100, 100}, Rgb8{101, 100, 100}, Rgb8{250, 0, 0}};
  for (int x = 0; x < 32; ++x) image.at(x, 0) = 0;
  image.at(10, 0) = 1;
  image.at(21, 0) = 2;
  rateDistortionImage(image, kFlatCost, 10.0);  // merging A' saves 6 bytes = 60 > its error of 1
  CHECK(image.at(10, 0) == 0);
  CHECK(image.at(21, 0) == 2);  // Z's error (~52000) is worth far more than 6 bytes
}

TEST_CASE("rate-distortion runs: a free colour (a device's skipped background) absorbs its neighbours") {
  IndexedImage image(12, 1, 0);
  image.colormap = {Rgb8{0, 0, 0}, Rgb8{8, 8, 8}};
  for (int x = 0; x < 12; ++x) image.at(x, 0) = x % 3 == 1 ? 1 : 0;
  const RunCost freeBackground = [](int, int index) { return index == 0 ? 0.0 : 3.0; };
  rateDistortionImage(image, freeBackground, 100.0);
  for (int x = 0; x < 12; ++x) CHECK(image.at(x, 0) == 0);
}

TEST_CASE("rate-distortion runs: the sink hands on the rewritten frame, or the rows untouched at lambda 0") {
  const IndexedImage original = noise(40, 9, 8, 3);
  for (double lambda : {0.0, 5000.0}) {
    IndexedImageSink collected;
    RateDistortionSink sink(collected, [](const IndexedImage&) { return kFlatCost; }, lambda);
    sink.begin(FrameInfo{original.width, original.height, original.colormap});
    for (int y = 0; y < original.height; ++y)
      sink.row(y, std::span<const PaletteIndex>(original.pixels).subspan(std::size_t(y) * 40, 40));
    sink.end();
    IndexedImage expected = original;
    rateDistortionImage(expected, kFlatCost, lambda);
    CHECK(collected.image().pixels == expected.pixels);
    CHECK((lambda == 0) == (expected.pixels == original.pixels));
  }
  IndexedImage counted(5, 1, 3);
  counted.pixels = {2, 2, 1, 2, 0};
  CHECK(mostFrequentIndex(counted) == 2);
}

namespace {

// The true colours of a picture whose palette colours are `image`'s, each
// pixel moved by `offset` (as a quantizer's error would).
RgbImage trueColours(const IndexedImage& image, int offset) {
  RgbImage truth(image.width, image.height);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const Rgb8 c = image.colorAt(x, y);
      std::uint8_t* p = truth.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(std::clamp(c.r + offset, 0, 255));
      p[1] = static_cast<std::uint8_t>(std::clamp(c.g + offset, 0, 255));
      p[2] = static_cast<std::uint8_t>(std::clamp(c.b + offset, 0, 255));
    }
  return truth;
}

double trueError(const IndexedImage& image, const RgbImage& truth) {
  double d = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = truth.pixel(x, y);
      d += colourError(image.colorAt(x, y), Rgb8{p[0], p[1], p[2]});
    }
  return d;
}

}  // namespace

TEST_CASE("rate-distortion runs against the truecolour picture: lambda 0 is a no-op, error is the true one") {
  const IndexedImage original = noise(97, 13, 16, 4);
  const RgbImage truth = trueColours(original, 3);
  IndexedImage copy = original;
  rateDistortionImage(copy, kFlatCost, 0.0, truth);
  CHECK(copy.pixels == original.pixels);
  // A larger lambda: fewer runs, and the objective (true error + lambda x
  // bytes) is no worse than the picture's own, which the programme could keep.
  for (double lambda : {1000.0, 100000.0}) {
    IndexedImage smoothed = original;
    rateDistortionImage(smoothed, kFlatCost, lambda, truth);
    int before = 0, after = 0;
    for (int y = 0; y < original.height; ++y) {
      before += countRuns(std::span<const PaletteIndex>(original.pixels).subspan(std::size_t(y) * 97, 97));
      after += countRuns(std::span<const PaletteIndex>(smoothed.pixels).subspan(std::size_t(y) * 97, 97));
    }
    INFO("lambda " << lambda << ": " << before << " runs before, " << after << " after");
    CHECK(after < before);
    CHECK(trueError(smoothed, truth) + lambda * 3.0 * after <= trueError(original, truth) + lambda * 3.0 * before);
  }
  IndexedImage wrongSize(5, 5, 0);
  wrongSize.colormap = original.colormap;
  CHECK_THROWS_AS(rateDistortionImage(wrongSize, kFlatCost, 10.0, truth), Error);
}

TEST_CASE("rate-distortion runs against the truecolour picture: a segment takes the entry nearest its mean") {
  // A dithered grey: alternating black and white whose true colour is mid
  // grey throughout. Against the palette colours no merge helps; against the
  // true colours the whole row becomes the grey entry, which no run held.
  IndexedImage image(16, 1, 0);
  image.colormap = {Rgb8{0, 0, 0}, Rgb8{255, 255, 255}, Rgb8{128, 128, 128}};
  for (int x = 0; x < 16; ++x) image.at(x, 0) = static_cast<PaletteIndex>(x % 2);
  RgbImage truth(16, 1);
  std::fill(truth.rgb.begin(), truth.rgb.end(), std::uint8_t(128));
  IndexedImage palette = image;
  rateDistortionImage(palette, kFlatCost, 1.0);
  CHECK(palette.pixels == image.pixels);  // merging black and white costs 65025 x 3 a pixel: never for 3 bytes
  rateDistortionImage(image, kFlatCost, 1.0, truth);
  for (int x = 0; x < 16; ++x) CHECK(image.at(x, 0) == 2);
}

TEST_CASE("rate-distortion runs: the sink uses the truecolour rows the quantizer offers") {
  IndexedImage image(16, 2, 0);
  image.colormap = {Rgb8{0, 0, 0}, Rgb8{255, 255, 255}, Rgb8{128, 128, 128}};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 16; ++x) image.at(x, y) = static_cast<PaletteIndex>((x + y) % 2);
  const Color18 grey = packColor18(reduce8to6(128), reduce8to6(128), reduce8to6(128));
  const std::vector<Color18> greyRow(16, grey);
  for (bool offered : {false, true}) {
    IndexedImageSink collected;
    RateDistortionSink sink(collected, [](const IndexedImage&) { return kFlatCost; }, 1.0);
    sink.begin(FrameInfo{16, 2, image.colormap});
    for (int y = 0; y < 2; ++y) {
      if (offered) sink.truecolourRow(y, greyRow);
      sink.row(y, std::span<const PaletteIndex>(image.pixels).subspan(std::size_t(y) * 16, 16));
    }
    sink.end();
    INFO("truecolour rows offered: " << offered);
    CHECK((collected.image().pixels == std::vector<PaletteIndex>(32, 2)) == offered);
    CHECK((collected.image().pixels == image.pixels) == !offered);
  }
}
