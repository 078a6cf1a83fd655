// The small histogram form (quantize/histogram.hpp, the firmware's): the
// same counts, the same median-cut palette, the same inverse map answers and
// the same pipeline output as the full form, within its stated bound, and a
// clear error past it.
#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "foundation/error.hpp"
#include "foundation/indexed_image.hpp"
#include "quantize/histogram.hpp"
#include "quantize/inverse_colormap.hpp"
#include "quantize/median_cut.hpp"
#include "quantize/run_pipeline.hpp"

using namespace lattice;
using namespace lattice::quantize;

namespace {

// Clustered random colours: a rendered picture's few thousand shades.
std::vector<Color18> picture(int pixels, unsigned seed) {
  std::mt19937 rng(seed);
  const auto next = [&rng](unsigned n) { return static_cast<unsigned>(rng() % n); };
  std::vector<Color18> out;
  for (int i = 0; i < pixels; ++i) {
    const unsigned base = next(4) * 15;
    out.push_back(packColor18(base + next(8), base + next(12), base + next(12)));
  }
  return out;
}

class VectorSource final : public RowSource18 {
 public:
  VectorSource(std::vector<Color18> pixels, int width) : pixels_(std::move(pixels)), width_(width) {}
  int width() const override { return width_; }
  int height() const override { return static_cast<int>(pixels_.size()) / width_; }
  void row(int y, std::span<Color18> out) override {
    std::copy_n(pixels_.begin() + y * width_, width_, out.begin());
  }

 private:
  std::vector<Color18> pixels_;
  int width_;
};

class Collect final : public IndexedSink {
 public:
  int maxColors() const override { return 256; }
  void begin(const FrameInfo& f) override { palette = f.palette; }
  void row(int, std::span<const PaletteIndex> indices) override { rows.insert(rows.end(), indices.begin(), indices.end()); }
  void end() override {}
  Palette palette;
  std::vector<PaletteIndex> rows;
};

}  // namespace

TEST_CASE("small histogram: same counts and the same median-cut palette as the full form") {
  for (unsigned seed : {1u, 2u, 3u}) {
    const auto pixels = picture(20000, seed);
    Histogram full, small(HistogramForm::Small);
    full.addRow(pixels);
    small.addRow(pixels);
    small.finish();
    REQUIRE(small.distinctColors() == full.distinctColors());
    REQUIRE(small.distinctColors() > 1000);  // grew past its first 1024 slots
    CHECK(small.totalPixels() == full.totalPixels());
    for (Color18 c : pixels) REQUIRE(small.count(c) == full.count(c));
    for (int k : {2, 16, 256}) {
      for (SplitRule split : {SplitRule::Median, SplitRule::Variance}) {
        QuantizeOptions options;
        options.split = split;
        options.refineIterations = 2;
        REQUIRE(medianCut(small, k, options) == medianCut(full, k, options));
      }
    }
  }
}

TEST_CASE("uncached inverse map answers as the cached one, ties to the lowest index") {
  Palette palette;
  std::mt19937 rng(5);
  for (int i = 0; i < 40; ++i)
    palette.push_back(Rgb8{static_cast<std::uint8_t>(rng() % 8 * 32), static_cast<std::uint8_t>(rng() % 8 * 32),
                           static_cast<std::uint8_t>(rng() % 8 * 32)});
  palette.push_back(palette[3]);  // an exact duplicate: index 3 must win
  InverseColorMap cached(palette);
  InverseColorMap uncached = InverseColorMap::uncached(palette);
  for (Color18 c = 0; c < (Color18{1} << 18); c += 7) REQUIRE(uncached.nearest(c) == cached.nearest(c));
}

TEST_CASE("small histogram: the whole pipeline writes the same picture as the full form") {
  const auto pixels = picture(64 * 64, 9);
  for (Dither dither : {Dither::None, Dither::FloydSteinberg}) {
    Collect a, b;
    PipelineOptions options;
    options.progress = false;
    options.quantize.dither = dither;
    VectorSource s1(pixels, 64), s2(pixels, 64);
    const PipelineReport full = runPipeline(s1, a, options);
    options.quantize.histogram = HistogramForm::Small;
    const PipelineReport small = runPipeline(s2, b, options);
    CHECK(a.palette == b.palette);
    CHECK(a.rows == b.rows);
    CHECK(full.histogramBytes == Histogram::kBytes);
    CHECK(small.histogramBytes == Histogram::kSmallBytes);
  }
}

TEST_CASE("small histogram: more colours than it holds is a usage error naming the way out") {
  Histogram small(HistogramForm::Small);
  std::vector<Color18> many;
  for (Color18 c = 0; c < Histogram::kSmallMaxColors; ++c) many.push_back(c * 31);
  small.addRow(many);
  CHECK(small.distinctColors() == Histogram::kSmallMaxColors);
  try {
    small.add(Color18{1} << 17 | 1);
    FAIL("no error past the bound");
  } catch (const Error& e) {
    CHECK(e.kind() == ErrorKind::Usage);
    CHECK(std::string(e.what()).find("--histogram full") != std::string::npos);
  }
  Histogram unfinished(HistogramForm::Small);
  unfinished.add(3);
  CHECK_THROWS_AS(medianCut(unfinished, 4, {}), Error);  // read before finish()
}
