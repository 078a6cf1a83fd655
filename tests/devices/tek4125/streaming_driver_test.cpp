// The 4125 driver without a frame (tek4125_driver.hpp): given each palette
// entry's pixel count before the first row (foundation/palette_counts.hpp), a
// strategy other than "shortest" writes the rows as they arrive; its bytes
// must be the ones the kept frame gives, for every such strategy and form
// set, and the quantizer must hand it counts exactly when they are exact.
#include <catch2/catch.hpp>

#include "devices/tek4125/tek4125_decoder.hpp"
#include "foundation/indexed_image.hpp"
#include "quantize/run_pipeline.hpp"
#include "tests/devices/tek4125/tek_test_support.hpp"
#include "tests/quantize/test_sources.hpp"

using namespace lattice;
using namespace lattice::tek4125;
using namespace lattice::tek4125::test;

namespace {

std::vector<std::uint64_t> countsOf(const IndexedImage& image) {
  std::vector<std::uint64_t> counts(image.colormap.size(), 0);
  for (PaletteIndex p : image.pixels) ++counts[p];
  return counts;
}

// The image through a driver that keeps its frame (no counts given).
std::vector<std::uint8_t> framed(const IndexedImage& image, const Tek4125Profile& profile) {
  MemorySink sink;
  Tek4125Driver driver(sink, profile);
  sendImage(driver, image);
  return sink.data();
}

// The same through a driver told the counts first; `held` gets the bytes of
// picture it held while the rows came.
std::vector<std::uint8_t> streamed(const IndexedImage& image, const Tek4125Profile& profile, std::size_t& held) {
  MemorySink sink;
  Tek4125Driver driver(sink, profile);
  const std::vector<std::uint64_t> counts = countsOf(image);
  driver.paletteCounts(counts);
  driver.begin(FrameInfo{image.width, image.height, image.colormap});
  held = driver.frameBytes();
  for (int y = 0; y < image.height; ++y)
    driver.row(y, std::span<const PaletteIndex>(image.pixels).subspan(
                      static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width),
                      static_cast<std::size_t>(image.width)));
  driver.end();
  return sink.data();
}

}  // namespace

TEST_CASE("the 4125 driver streams every strategy but shortest with no frame, the framed bytes") {
  for (const std::string forms : {"strict", "compact"})
    for (int planes : {4, 8})
      for (const std::string strategy : {"plain", "skip", "rectangles", "spans", "runs"}) {
        Tek4125Profile profile;
        profile.forms = forms;
        profile.planes = planes;
        profile.strategy = strategy;
        const int colors = profile.maxColors();
        for (const IndexedImage& image : {scene(90, 57, colors), noise(40, 31, colors, 5u), flat(17, 9, colors, 3)}) {
          INFO(forms << " planes " << planes << " strategy " << strategy << " " << image.width << "x" << image.height);
          std::size_t held = 1;
          const std::vector<std::uint8_t> bytes = streamed(image, profile, held);
          CHECK(held == 0);
          REQUIRE(bytes.size() > 20);
          CHECK(bytes == framed(image, profile));
        }
      }
}

TEST_CASE("the 4125 driver keeps the frame where it must: shortest, progressive, or no counts") {
  const IndexedImage image = scene(64, 40, 16);
  Tek4125Profile shortest;
  shortest.planes = 4;
  {
    MemorySink sink;
    Tek4125Driver driver(sink, shortest);
    CHECK_FALSE(driver.wantsPaletteCounts());  // the host's default asks nothing and changes nothing
    std::size_t held = 0;
    CHECK(streamed(image, shortest, held) == framed(image, shortest));
    CHECK(held == 64u * 40u);
  }
  Tek4125Profile progressive = shortest;
  progressive.strategy = "runs";
  progressive.progressive = true;
  {
    MemorySink sink;
    Tek4125Driver driver(sink, progressive);
    CHECK_FALSE(driver.wantsPaletteCounts());
    std::size_t held = 0;
    CHECK(streamed(image, progressive, held) == framed(image, progressive));
    CHECK(held == 64u * 40u);
  }
  Tek4125Profile runs = shortest;
  runs.strategy = "runs";
  {
    MemorySink sink;
    Tek4125Driver driver(sink, runs);
    CHECK(driver.wantsPaletteCounts());
    // Counts for another palette size are not this picture's: the frame is kept.
    const std::vector<std::uint64_t> wrong(3, 1);
    driver.paletteCounts(wrong);
    driver.begin(FrameInfo{image.width, image.height, image.colormap});
    CHECK(driver.frameBytes() == 64u * 40u);
  }
}

TEST_CASE("the pipeline gives the 4125 driver exact counts without dithering, none with it") {
  const int w = 70, h = 45;
  testing::FunctionSource source(w, h, [&](int x, int y) { return testing::photoLike(x, y, w, h); });
  Tek4125Profile profile;
  profile.strategy = "runs";
  for (const quantize::Dither dither : {quantize::Dither::None, quantize::Dither::FloydSteinberg}) {
    for (const quantize::HistogramForm form : {quantize::HistogramForm::Full, quantize::HistogramForm::Small}) {
      quantize::PipelineOptions options;
      options.progress = false;
      options.quantize.dither = dither;
      options.quantize.histogram = form;
      MemorySink sink;
      Tek4125Driver driver(sink, profile);
      quantize::runPipeline(source, driver, options);
      // Streaming or not shows in what the driver held at the end.
      CHECK((driver.frameBytes() == 0) == (dither == quantize::Dither::None));
      // The reference: the same indices into a driver that keeps its frame.
      IndexedImageSink collect(profile.maxColors());
      quantize::runPipeline(source, collect, options);
      CHECK(sink.data() == framed(collect.image(), profile));
    }
  }
}

TEST_CASE("after a sampled histogram the 4125 driver streams from the sample's counts, the framed picture") {
  // --mode sample (what the firmware runs): the palette comes from
  // every 4th row and column, and so do the counts the driver ranks for its
  // background. It must stream, and draw exactly the picture a driver that
  // kept the frame draws from the same indices (only the background it
  // skips may differ, which changes bytes, never pixels).
  const int w = 70, h = 45;
  testing::FunctionSource source(w, h, [&](int x, int y) { return testing::photoLike(x, y, w, h); });
  Tek4125Profile profile;
  profile.strategy = "runs";
  quantize::PipelineOptions options;
  options.progress = false;
  options.mode = quantize::PipelineMode::Sample;
  MemorySink sink;
  Tek4125Driver driver(sink, profile);
  quantize::runPipeline(source, driver, options);
  CHECK(driver.frameBytes() == 0);
  IndexedImageSink collect(profile.maxColors());
  quantize::runPipeline(source, collect, options);
  const std::vector<std::uint8_t> reference = framed(collect.image(), profile);
  const auto screenOf = [&](const std::vector<std::uint8_t>& bytes) {
    Tek4125Decoder decoder(profile);
    decoder.feed(bytes);
    decoder.finish();
    CHECK(decoder.report().malformed == 0);
    return cutPicture(decoder.image(), profile, w, h);
  };
  const IndexedImage streamedScreen = screenOf(sink.data());
  const IndexedImage framedScreen = screenOf(reference);
  REQUIRE(streamedScreen.pixels.size() == collect.image().pixels.size());
  CHECK(streamedScreen.pixels == framedScreen.pixels);
}
