// The frame's passes on every thread (quantize/frame_bands.hpp): histograms
// of parts merge into the whole's, the inverse colour map answers truly when
// many threads resolve its cells at once, and the pipeline in Frame mode hands
// the sink the same palette, rows and row order for 1, 2, 3 and 8 threads,
// with every dither and both histogram forms, and a sink's error comes out
// of the pipeline with the mapping pool joined.
#include <catch2/catch.hpp>

#include <climits>
#include <limits>
#include <thread>
#include <vector>

#include "foundation/error.hpp"
#include "quantize/frame_bands.hpp"
#include "quantize/histogram.hpp"
#include "quantize/inverse_colormap.hpp"
#include "quantize/median_cut.hpp"
#include "quantize/run_pipeline.hpp"
#include "tests/quantize/test_sources.hpp"

using namespace lattice;
using namespace lattice::quantize;
using lattice::testing::FunctionSource;
using lattice::testing::hash2;
using lattice::testing::photoLike;

namespace {

// Every call the sink gets, in order: the palette, then each row's y, colours and indices.
class Recording final : public IndexedSink {
 public:
  int maxColors() const override { return 64; }
  void begin(const FrameInfo& frame) override { palette = frame.palette; }
  void truecolourRow(int y, std::span<const Color18> colours) override {
    order.push_back(-1 - y);
    colourRows.insert(colourRows.end(), colours.begin(), colours.end());
  }
  void row(int y, std::span<const PaletteIndex> indices) override {
    order.push_back(y);
    rows.insert(rows.end(), indices.begin(), indices.end());
  }
  void end() override { ended = true; }
  Palette palette;
  std::vector<int> order;
  std::vector<Color18> colourRows;
  std::vector<PaletteIndex> rows;
  bool ended = false;
};

// A picture whose height is no multiple of a band, with a few thousand colours.
constexpr int kWidth = 53, kHeight = 131;
Color18 pixel(int x, int y) { return photoLike(x, y, kWidth, kHeight); }

std::vector<Color18> rowsOf(int first, int last) {
  std::vector<Color18> out;
  for (int y = first; y < last; ++y)
    for (int x = 0; x < kWidth; ++x) out.push_back(pixel(x, y));
  return out;
}

}  // namespace

TEST_CASE("frame bands: histograms of parts merge into the whole's, in either form") {
  for (HistogramForm form : {HistogramForm::Full, HistogramForm::Small}) {
    INFO("form " << nameOfValue(kHistogramFormNames, form, "?"));
    Histogram whole(form), merged(form), lower(form);
    whole.addRow(rowsOf(0, kHeight));
    merged.addRow(rowsOf(0, 40));
    lower.addRow(rowsOf(40, kHeight));
    if (form == HistogramForm::Full) {  // in two ranges of the cube, as two threads would
      merged.merge(lower, 0, 1000);
      merged.merge(lower, 1000, Color18(Histogram::kCells));
    } else {
      merged.merge(lower);
    }
    whole.finish();
    merged.finish();
    CHECK(merged.totalPixels() == whole.totalPixels());
    CHECK(merged.distinctColors() == whole.distinctColors());
    long differ = 0;
    whole.forEach([&](Color18 c, std::uint32_t n) { differ += merged.count(c) != n; });
    CHECK(differ == 0);
    CHECK(medianCut(merged, 64, {}) == medianCut(whole, 64, {}));
  }
}

TEST_CASE("frame bands: a merged count saturates at the 32-bit maximum as one count would") {
  constexpr std::uint32_t kMax = std::numeric_limits<std::uint32_t>::max();
  Histogram full(HistogramForm::Full), part(HistogramForm::Full);
  full.add(7);
  part.add(7);
  part.add(7);
  Histogram big(HistogramForm::Full);
  big.add(7);
  for (int i = 0; i < 32; ++i) big.merge(big);  // doubled: 2^31 after 31 merges, 2^32 saturates
  CHECK(big.count(7) == kMax);
  big.merge(part);
  CHECK(big.count(7) == kMax);
  full.merge(part);
  CHECK(full.count(7) == 3);
  CHECK(full.totalPixels() == 3);
  CHECK_THROWS_AS(full.merge(Histogram(HistogramForm::Small)), Error);
}

TEST_CASE("frame bands: the inverse colour map answers truly with 8 threads resolving its cells at once") {
  Palette palette;
  for (int i = 0; i < 200; ++i) {
    const std::uint32_t h = hash2(i, 5);
    palette.push_back(Rgb8{static_cast<std::uint8_t>(h), static_cast<std::uint8_t>(h >> 8),
                           static_cast<std::uint8_t>(h >> 16)});
  }
  InverseColorMap reference = InverseColorMap::uncached(palette);  // no cache: read-only, shared safely
  for (int round = 0; round < 4; ++round) {
    InverseColorMap shared(palette);
    constexpr unsigned kThreads = 8;
    std::vector<long> wrong(kThreads, 0);
    {
      std::vector<std::jthread> threads;
      for (unsigned t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
          // Each thread walks the cube from its own start, so many meet on cells not yet resolved.
          for (std::size_t i = 0; i < Histogram::kCells; ++i) {
            const auto c = static_cast<Color18>((i * 2654435761u + t * 40503u) & (Histogram::kCells - 1));
            wrong[t] += shared.nearest(c) != reference.nearest(c);
          }
        });
    }
    INFO("round " << round);
    for (unsigned t = 0; t < kThreads; ++t) CHECK(wrong[t] == 0);
    CHECK(shared.resolvedCoarseCells() == static_cast<std::size_t>(InverseColorMap::kCoarseCells));
  }
}

TEST_CASE("frame bands: the sink gets the same calls for 1, 2, 3 and 8 threads") {
  for (HistogramForm form : {HistogramForm::Full, HistogramForm::Small})
    for (Dither dither : {Dither::None, Dither::Bayer, Dither::FloydSteinberg}) {
      INFO("form " << nameOfValue(kHistogramFormNames, form, "?") << ", dither "
                   << nameOfValue(kDitherNames, dither, "?"));
      auto run = [&](unsigned threads) {
        FunctionSource source(kWidth, kHeight, pixel);
        PipelineOptions options;
        options.mode = PipelineMode::Frame;
        options.progress = false;
        options.threads = threads;
        options.quantize.dither = dither;
        options.quantize.histogram = form;
        Recording sink;
        const PipelineReport report = runPipeline(source, sink, options);
        CHECK(report.rowsRendered == kHeight);
        CHECK(sink.ended);
        return sink;
      };
      const Recording one = run(1);
      REQUIRE(one.palette.size() > 16);
      REQUIRE(one.order.size() == 2 * std::size_t{kHeight});
      for (unsigned threads : {2u, 3u, 8u}) {
        INFO(threads << " threads");
        const Recording many = run(threads);
        CHECK(many.palette == one.palette);
        CHECK(many.order == one.order);
        CHECK(many.colourRows == one.colourRows);
        CHECK(many.rows == one.rows);
      }
    }
}

TEST_CASE("frame bands: the pipeline's buffers count a partial histogram a thread and two bands of indices") {
  PipelineOptions options;
  options.mode = PipelineMode::Frame;
  const PipelineReport one = pipelineBuffers(100, 1000, options);
  options.threads = 4;
  const PipelineReport four = pipelineBuffers(100, 1000, options);
  CHECK(four.histogramBytes == one.histogramBytes + 3 * Histogram::kBytes);
  CHECK(four.rowBytes == one.rowBytes + 2 * std::size_t{kBandRows} * 100);
  CHECK(histogramWorkers(40, 8) == 1);  // no band under kBandRows rows
  CHECK(histogramWorkers(1000, 8) == 8);
  CHECK(histogramWorkers(1000, 64) == kMostHistogramParts);  // the memory stays bounded on many cores
  options.mode = PipelineMode::TwoPass;  // one row at a time: no bands
  CHECK(pipelineBuffers(100, 1000, options).totalBytes() == pipelineBuffers(100, 1000, PipelineOptions{}).totalBytes());
  options.mode = PipelineMode::Frame;
  options.quantize.dither = Dither::FloydSteinberg;  // maps on one thread: no bands of indices
  CHECK(pipelineBuffers(100, 1000, options).rowBytes == one.rowBytes);
}

TEST_CASE("frame bands: a sink's error mid-picture comes out of the pipeline while the pool maps the next band") {
  class Failing final : public IndexedSink {
   public:
    int maxColors() const override { return 16; }
    void begin(const FrameInfo&) override {}
    void row(int y, std::span<const PaletteIndex>) override {
      if (y == kBandRows + 3) throw Error(ErrorKind::Output, "the line dropped");
      ++rows;
    }
    void end() override {}
    int rows = 0;
  };
  FunctionSource source(kWidth, kHeight, pixel);
  PipelineOptions options;
  options.mode = PipelineMode::Frame;
  options.progress = false;
  options.threads = 3;
  Failing sink;
  CHECK_THROWS_WITH(runPipeline(source, sink, options), "the line dropped");
  CHECK(sink.rows == kBandRows + 3);  // every row before it, in order
}
