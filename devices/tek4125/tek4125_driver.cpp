#include "devices/tek4125/tek4125_driver.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "devices/gun_percent.hpp"
#include "devices/tek4125/tek4125_progressive.hpp"
#include "devices/tek4125/tek4125_rows.hpp"
#include "devices/tek4125/tek4125_run_cost.hpp"
#include "devices/tek4125/tek4125_writer.hpp"
#include "foundation/error.hpp"

namespace lattice::tek4125 {

namespace {

constexpr int kSurface = 1;
constexpr int kAluOverwrite = 11;

std::string describeOptions(const Tek4125DriverOptions& o) {
  return fmt::format("{}{}{}{}", o.skipBackground ? "skip " : "", o.rectangles ? "RR " : "",
                     o.mergeRows ? "merged " : "", o.runLength ? "RL" : "no-RL");
}

}  // namespace

Tek4125Placement placePicture(const Tek4125Profile& profile, int width, int height) {
  return Tek4125Placement{(profile.width - width) / 2, (profile.height - height) / 2};
}

Tek4125Driver::Tek4125Driver(ByteSink& sink, const Tek4125Profile& profile)
    : Tek4125Driver(sink, profile, tek4125Strategy(profile.strategy).options) {}

Tek4125Driver::Tek4125Driver(ByteSink& sink, const Tek4125Profile& profile, Tek4125DriverOptions options)
    : sink_(sink), profile_(profile), options_(options) {
  profile_.validate();
}

// The stream being written: header sent, rows planned as they arrive. The
// writer keeps a reference to the form set, so both live here together.
struct Tek4125Driver::Stream {
  Stream(const Tek4125Forms& f, ByteSink& sink, const Tek4125RowLayout& l, const Tek4125DriverOptions& o)
      : forms(f), layout(l), options(o), out(forms, sink), planner(out, layout, options),
        row(static_cast<std::size_t>(layout.width)) {}
  Tek4125Forms forms;
  Tek4125RowLayout layout;
  Tek4125DriverOptions options;
  Tek4125Writer out;
  Tek4125RowPlanner planner;
  std::vector<int> row;  // one image row of device indices
  Tek4125StreamStats stats;
};

Tek4125Driver::~Tek4125Driver() = default;

bool Tek4125Driver::streams() const {
  // "shortest" encodes the picture once per candidate and progressive draws
  // it coarse to fine: both need the whole frame. Every other strategy writes
  // rows in order once the background is known, so no frame is kept.
  return !options_.shortest && !profile_.progressive;
}

bool Tek4125Driver::wantsPaletteCounts() const { return streams() && options_.skipBackground; }

void Tek4125Driver::paletteCounts(std::span<const std::uint64_t> counts) { counts_.assign(counts.begin(), counts.end()); }

void Tek4125Driver::begin(const FrameInfo& frame) {
  if (frame.width < 1 || frame.height < 1 || frame.width > profile_.width || frame.height > profile_.height)
    throw Error(ErrorKind::Usage,
                fmt::format("tek4125: a {}x{} picture does not fit the {}x{} screen; render at most {}x{} "
                            "(or set the profile's width=/height= if your terminal differs)",
                            frame.width, frame.height, profile_.width, profile_.height, profile_.width,
                            profile_.height));
  if (frame.palette.empty() || static_cast<int>(frame.palette.size()) > maxColors())
    throw Error(ErrorKind::Usage,
                fmt::format("tek4125: the picture has {} colours but the profile allows 1..{} ({} planes, {} "
                            "reserved); quantize to at most {} colours or change planes=/reserved=",
                            frame.palette.size(), maxColors(), profile_.planes, profile_.reserved, maxColors()));
  frame_ = frame;
  nextRow_ = 0;
  stats_ = {};
  begun_ = true;
  stream_.reset();
  pixels_.clear();
  // Counts for another palette (a caller that skipped paletteCounts for
  // this picture) are not used: the frame is kept instead.
  const bool countsKnown = counts_.size() == frame.palette.size();
  if (streams() && (!options_.skipBackground || countsKnown)) {
    const int background = options_.skipBackground ? mostFrequent(counts_) : -1;
    stream_ = openStream(options_, sink_, background);
  } else {
    pixels_.assign(static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height), 0);
  }
}

void Tek4125Driver::row(int y, std::span<const PaletteIndex> indices) {
  if (!begun_ || y != nextRow_ || y >= frame_.height || indices.size() != static_cast<std::size_t>(frame_.width))
    throw Error(ErrorKind::Internal,
                fmt::format("tek4125: row {} ({} pixels) out of order; expected row {} of {} pixels", y,
                            indices.size(), nextRow_, frame_.width));
  for (std::size_t x = 0; x < indices.size(); ++x)
    if (indices[x] >= frame_.palette.size())
      throw Error(ErrorKind::Internal,
                  fmt::format("tek4125: row {} pixel {} has index {} beyond the {}-entry palette", y, x,
                              indices[x], frame_.palette.size()));
  if (stream_)
    streamRow(*stream_, y, indices);
  else
    std::copy(indices.begin(), indices.end(),
              pixels_.begin() + static_cast<long>(y) * static_cast<long>(frame_.width));
  ++nextRow_;
}

int Tek4125Driver::mostFrequent(std::span<const std::uint64_t> counts) {
  return static_cast<int>(std::max_element(counts.begin(), counts.end()) - counts.begin());
}

int Tek4125Driver::mostFrequentIndex() const {
  std::vector<std::uint64_t> count(frame_.palette.size(), 0);
  for (PaletteIndex p : pixels_) ++count[p];
  return mostFrequent(count);
}

std::unique_ptr<Tek4125Driver::Stream> Tek4125Driver::openStream(const Tek4125DriverOptions& options, ByteSink& sink,
                                                                 int backgroundIndex) const {
  Tek4125Forms forms = profile_.formSet();
  forms.shortHighXy = forms.fullXy && profile_.xyShort;  // the short forms of compact already go further
  const int reserved = profile_.reserved;
  const int paletteSize = static_cast<int>(frame_.palette.size());
  const int width = frame_.width, height = frame_.height;
  const Tek4125Placement place = placePicture(profile_, width, height);

  Tek4125RowLayout layout;
  layout.left = place.left;
  layout.bottom = place.bottom;
  layout.width = width;
  layout.height = height;
  // A picture whose indices fit in 4 bits is sent at 4 bits a pixel even on
  // an 8-plane terminal: half the raster bytes, and the one depth a source packs.
  layout.bits = profile_.pixelBitsFor(paletteSize);
  layout.raster = layout.bits == 4 || !forms.rasterOnlyAtFourBits;
  layout.runLength = forms.runLength && (options.runLength || !layout.raster);
  layout.background = options.skipBackground ? backgroundIndex + reserved : -1;
  if (forms.screenViewport) {
    layout.viewportX = 0;
    layout.viewportY = 0;
  } else {
    layout.viewportX = place.left;
    layout.viewportY = place.bottom;
  }
  const int right = place.left + width - 1, top = place.bottom + height - 1;

  auto stream = std::make_unique<Stream>(forms, sink, layout, options);
  Tek4125Writer& out = stream->out;
  out.bytes({tek4125::kEsc, '%', '!', '0'});  // enter Tek mode
  out.command("LV");                      // dialog area invisible, so text cannot cover the picture
  out.integer(0);
  if (forms.escapeDel) {  // raw DEL is ignored from here; ESC ? stands for it
    out.command("KI");
    out.integer(1);
  }
  if (forms.defineSurfaces) {  // one surface of as many planes as RU writes bits: as every source pairs them
    out.command("RD");
    out.integer(1);
    out.integer(layout.bits);
  }
  out.command("TM");  // colour map in RGB, opaque, normal
  for (int i = 0; i < 3; ++i) out.integer(1);
  auto colour = [&](int i) {
    const Rgb8 c = frame_.palette[static_cast<std::size_t>(i)];
    return std::array<int, 3>{devices::percentOf8(c.r), devices::percentOf8(c.g), devices::percentOf8(c.b)};
  };
  if (forms.explicitBackground && reserved == 0) {  // the colour the clear shows: picture colour 0
    out.command("TB");
    for (int g : colour(0)) out.integer(g);
  }
  const int perCommand = forms.colourEntriesPerTg > 0 ? forms.colourEntriesPerTg : paletteSize;
  for (int first = 0; first < paletteSize; first += perCommand) {
    const int n = std::min(perCommand, paletteSize - first);
    out.command("TG");
    out.integer(kSurface);
    out.integer(4 * n);
    for (int i = first; i < first + n; ++i) {
      out.integer(i + reserved);
      for (int g : colour(i)) out.integer(g);
    }
  }
  out.bytes({tek4125::kEsc, 0x0C});  // clear the page (to entry 0)
  out.command("RU");
  out.integer(kSurface);
  out.integer(kAluOverwrite);
  out.integer(layout.bits);
  out.command("RS");
  if (forms.screenViewport) {
    out.xy(0, 0);
    out.xy(profile_.width - 1, profile_.height - 1);
  } else {
    out.xy(place.left, place.bottom);
    out.xy(right, top);
  }
  // The picture's background: one RR unless the clear already painted it.
  if (layout.background >= 0 && (forms.explicitBackground || layout.background != 0)) {
    out.command("RR");
    out.xy(place.left, place.bottom);
    out.xy(right, top);
    out.integer(layout.background);
    ++stream->stats.rectangleFills;
  }
  return stream;
}

void Tek4125Driver::streamRow(Stream& stream, int y, std::span<const PaletteIndex> indices) const {
  for (std::size_t x = 0; x < indices.size(); ++x) stream.row[x] = indices[x] + profile_.reserved;
  stream.planner.row(y, stream.row);
}

void Tek4125Driver::closeStream(Stream& stream, Tek4125StreamStats& stats) const {
  stream.planner.finish();
  const Tek4125RowStats r = profile_.progressive ? drawProgressive(stream.out, stream.layout, stream.options, pixels_,
                                                                   frame_.palette, profile_.reserved, progressive_)
                                                 : stream.planner.stats();
  stats = stream.stats;
  stats.rasterWrites = r.rasterWrites;
  stats.runLengthWrites = r.runLengthWrites;
  stats.rectangleFills += r.rectangleFills;
  stats.skippedPixels = r.skippedPixels;
  stats.rasterBits = stream.layout.bits;
  stats.candidate = describeOptions(Tek4125DriverOptions{stream.options.skipBackground, stream.options.rectangles,
                                                         stream.options.mergeRows, stream.layout.runLength, false});
  stream.out.finish();
  stats.bytes = stream.out.size();
  stats.seconds = transmitSeconds(stats.bytes, profile_.line());
}

void Tek4125Driver::encode(const Tek4125DriverOptions& options, ByteSink& sink, Tek4125StreamStats& stats) const {
  const std::unique_ptr<Stream> stream = openStream(options, sink, options.skipBackground ? mostFrequentIndex() : -1);
  if (!profile_.progressive) {
    const auto width = static_cast<std::size_t>(frame_.width);
    for (int y = 0; y < frame_.height; ++y)
      streamRow(*stream, y, std::span<const PaletteIndex>(pixels_).subspan(static_cast<std::size_t>(y) * width, width));
  }
  closeStream(*stream, stats);
}

void Tek4125Driver::end() {
  if (!begun_ || nextRow_ != frame_.height)
    throw Error(ErrorKind::Internal, fmt::format("tek4125: end() after {} of {} rows", nextRow_, frame_.height));
  begun_ = false;
  counts_.clear();
  if (stream_) {
    closeStream(*stream_, stats_);
    stream_.reset();
    sink_.flush();
    return;
  }
  if (profile_.progressive) {
    // Every candidate below keeps options_'s background, so one plan serves them all.
    const int background = options_.skipBackground ? mostFrequentIndex() : -1;
    progressive_ = planProgressive(frame_.width, frame_.height, background >= 0 ? background + profile_.reserved : -1,
                                   profile_.formSet().fullXy, pixels_, frame_.palette, profile_.reserved,
                                   tek4125RunCost(profile_, static_cast<int>(frame_.palette.size()), background));
  }
  std::vector<Tek4125DriverOptions> candidates{options_};
  if (options_.shortest) {
    // The row planner is optimal per row for estimated costs; these variants
    // catch where the estimates or the greedy rectangle merging mislead it.
    Tek4125DriverOptions noRuns = options_, unmerged = options_;
    noRuns.runLength = false;
    unmerged.mergeRows = false;
    candidates.push_back(noRuns);
    candidates.push_back(unmerged);
  }
  // Each candidate is encoded into a counter, and only the smallest (the
  // first of equals) again into the sink: one more encoding (milliseconds)
  // instead of holding whole streams (hundreds of KiB, docs/memory.md).
  std::size_t best = 0;
  if (candidates.size() > 1) {
    std::uint64_t bestBytes = UINT64_MAX;
    for (std::size_t n = 0; n < candidates.size(); ++n) {
      CountingSink counter;
      Tek4125StreamStats s;
      encode(candidates[n], counter, s);
      if (s.bytes < bestBytes) bestBytes = s.bytes, best = n;
    }
  }
  encode(candidates[best], sink_, stats_);
  sink_.flush();
}

std::unique_ptr<Tek4125Driver> makeTek4125Driver(ByteSink& sink, const Tek4125Profile& profile) {
  return std::make_unique<Tek4125Driver>(sink, profile);
}

}  // namespace lattice::tek4125
