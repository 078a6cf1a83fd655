#include <catch2/catch.hpp>

#include <algorithm>
#include <climits>
#include <set>

#include "foundation/indexed_image.hpp"
#include "quantize/run_pipeline.hpp"
#include "quantize/median_cut.hpp"
#include "tests/quantize/test_sources.hpp"
#include "foundation/error.hpp"

using namespace lattice;
using namespace lattice::quantize;
using lattice::testing::FunctionSource;
using lattice::testing::photoLike;

namespace {

PipelineOptions quietOptions(PipelineMode mode = PipelineMode::TwoPass) {
  PipelineOptions options;
  options.mode = mode;
  options.progress = false;
  return options;
}

FunctionSource photoSource(int width, int height) {
  return FunctionSource(width, height, [width, height](int x, int y) { return photoLike(x, y, width, height); });
}

// Every pixel's index must be at the minimum distance over the whole palette.
long pixelsNotAtNearest(RowSource18& source, const IndexedImage& image) {
  std::vector<Color18> row(static_cast<std::size_t>(source.width()));
  long wrong = 0;
  for (int y = 0; y < source.height(); ++y) {
    source.row(y, row);
    for (int x = 0; x < source.width(); ++x) {
      Color18 c = row[static_cast<std::size_t>(x)];
      int r = expand6to8(red6(c)), g = expand6to8(green6(c)), b = expand6to8(blue6(c));
      int best = INT_MAX;
      for (Rgb8 p : image.colormap) best = std::min(best, distanceSquared(r, g, b, p));
      if (distanceSquared(r, g, b, image.colorAt(x, y)) != best) ++wrong;
    }
  }
  return wrong;
}

}  // namespace

TEST_CASE("palette within K, every pixel at its true nearest entry without dithering") {
  for (int k : {2, 16, 256}) {
    auto source = photoSource(120, 90);
    IndexedImageSink sink(k);
    PipelineReport report = runPipeline(source, sink, quietOptions());
    const IndexedImage& image = sink.image();
    INFO("K = " << k);
    CHECK(image.colormap.size() <= static_cast<std::size_t>(k));
    CHECK(report.paletteSize == image.colormap.size());
    CHECK(*std::max_element(image.pixels.begin(), image.pixels.end()) < image.colormap.size());
    CHECK(pixelsNotAtNearest(source, image) == 0);
  }
}

TEST_CASE("the sink's colour count caps an explicit --colors") {
  auto source = photoSource(40, 30);
  IndexedImageSink sink(16);
  PipelineOptions options = quietOptions();
  options.maxColors = 200;
  runPipeline(source, sink, options);
  CHECK(sink.image().colormap.size() == 16);
}

TEST_CASE("passes and frame modes give identical pictures, passes renders twice") {
  for (Dither dither : {Dither::None, Dither::FloydSteinberg, Dither::Bayer}) {
    auto a = photoSource(77, 51);
    auto b = photoSource(77, 51);
    IndexedImageSink sa(32), sb(32);
    PipelineOptions passes = quietOptions(PipelineMode::TwoPass), frame = quietOptions(PipelineMode::Frame);
    passes.quantize.dither = frame.quantize.dither = dither;
    PipelineReport ra = runPipeline(a, sa, passes);
    PipelineReport rb = runPipeline(b, sb, frame);
    CHECK(sa.image().pixels == sb.image().pixels);
    CHECK(sa.image().colormap == sb.image().colormap);
    CHECK(a.rowCalls == 2 * 51);
    CHECK(b.rowCalls == 51);
    CHECK(ra.frameBytes == 0);
    CHECK(rb.frameBytes == 77u * 51u * sizeof(Color18));
    CHECK(ra.histogramBytes == 1024u * 1024u);
    CHECK(ra.errorRowBytes == (dither == Dither::FloydSteinberg ? 79u * 12u : 0u));
  }
}

TEST_CASE("sample mode renders a fraction of the rows for its histogram") {
  auto source = photoSource(64, 40);
  IndexedImageSink sink(16);
  PipelineOptions options = quietOptions(PipelineMode::Sample);
  options.sampleStep = 4;
  PipelineReport report = runPipeline(source, sink, options);
  CHECK(source.rowCalls == 10 + 40);
  CHECK(report.rowsRendered == 50);
  CHECK(sink.image().colormap.size() == 16);
  // The palette may differ from TwoPass, but mapping is still nearest-entry.
  CHECK(pixelsNotAtNearest(source, sink.image()) == 0);
}

TEST_CASE("a sample step larger than the picture samples only the first pixel") {
  auto source = photoSource(30, 20);
  IndexedImageSink sink(16);
  PipelineOptions options = quietOptions(PipelineMode::Sample);
  options.sampleStep = 2147483647;
  PipelineReport report = runPipeline(source, sink, options);
  CHECK(report.distinctColors == 1);
  CHECK(sink.image().colormap.size() == 1);
  CHECK(source.rowCalls == 1 + 20);
}

TEST_CASE("one colour, two colours and K above the colour count") {
  FunctionSource one(9, 7, [](int, int) { return packColor18(5, 50, 25); });
  IndexedImageSink s1(256);
  runPipeline(one, s1, quietOptions());
  REQUIRE(s1.image().colormap.size() == 1);
  CHECK(std::all_of(s1.image().pixels.begin(), s1.image().pixels.end(), [](PaletteIndex i) { return i == 0; }));

  FunctionSource two(10, 10, [](int x, int y) { return (x + y) % 2 ? packColor18(63, 0, 0) : packColor18(0, 0, 63); });
  IndexedImageSink s2(256);
  runPipeline(two, s2, quietOptions());
  REQUIRE(s2.image().colormap.size() == 2);
  CHECK(s2.image().colorAt(0, 0) == Rgb8{0, 0, 255});
  CHECK(s2.image().colorAt(1, 0) == Rgb8{255, 0, 0});
}

TEST_CASE("1x1, 1xN, Nx1 and 4096-wide pictures") {
  struct Size {
    int w, h;
  };
  for (Size size : {Size{1, 1}, Size{1, 37}, Size{53, 1}, Size{4096, 3}})
    for (Dither dither : {Dither::None, Dither::FloydSteinberg, Dither::Bayer}) {
      auto source = photoSource(size.w, size.h);
      IndexedImageSink sink(8);
      PipelineOptions options = quietOptions();
      options.quantize.dither = dither;
      runPipeline(source, sink, options);
      INFO(size.w << "x" << size.h);
      CHECK(sink.image().width == size.w);
      CHECK(sink.image().height == size.h);
      CHECK(sink.image().colormap.size() <= 8);
      if (dither == Dither::None) CHECK(pixelsNotAtNearest(source, sink.image()) == 0);
    }
}

TEST_CASE("deterministic across runs with every option") {
  PipelineOptions options = quietOptions();
  options.quantize.split = SplitRule::Variance;
  options.quantize.refineIterations = 3;
  options.quantize.dither = Dither::FloydSteinberg;
  auto a = photoSource(64, 48);
  auto b = photoSource(64, 48);
  IndexedImageSink sa(16), sb(16);
  runPipeline(a, sa, options);
  runPipeline(b, sb, options);
  CHECK(sa.image().pixels == sb.image().pixels);
  CHECK(sa.image().colormap == sb.image().colormap);
}

TEST_CASE("bad options and empty sources are errors, not crashes") {
  FunctionSource empty(0, 5, [](int, int) { return Color18{0}; });
  IndexedImageSink sink(16);
  CHECK_THROWS_AS(runPipeline(empty, sink, quietOptions()), Error);
  auto source = photoSource(4, 4);
  PipelineOptions options = quietOptions(PipelineMode::Sample);
  options.sampleStep = 0;
  CHECK_THROWS_AS(runPipeline(source, sink, options), Error);
  options = quietOptions();
  options.maxColors = 300;
  CHECK_THROWS_AS(runPipeline(source, sink, options), Error);
  FunctionSource wide(3, 3, [](int, int) { return Color18{1} << 20; });  // not 18-bit
  CHECK_THROWS_AS(runPipeline(wide, sink, quietOptions()), Error);
}
