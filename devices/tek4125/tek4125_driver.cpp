#include "devices/tek4125/tek4125_driver.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "foundation/error.hpp"

namespace lattice {

namespace {

constexpr int kSurface = 1;
constexpr int kAluOverwrite = 11;

// Estimated bytes of the fixed parts of a raster span and of a rectangle, for
// choosing between them. The exact count depends on which xy bytes change
// (1..5 each) and on the integers' sizes; these assume a short-form RH xy
// within a row, 2-character counts, and an RR whose first corner changes
// Extra/Lo-Y (its y is absolute, RH's is viewport-relative).
constexpr double kSpanHeaderBytes = 3 + 3 + 3 + 2 + 2;  // ESC RH xy, ESC RP count strlen
constexpr double kRectangleBytes = 3 + 5 + 3 + 1;      // ESC RR xy xy index
constexpr double kExtendBytes = 0;  // growing an open rectangle by a row is free

}  // namespace

Tek4125Placement placePicture(const Tek4125Profile& profile, int width, int height) {
  return Tek4125Placement{(profile.width - width) / 2, (profile.height - height) / 2};
}

Tek4125Driver::Tek4125Driver(ByteSink& sink, const Tek4125Profile& profile, Tek4125DriverOptions options)
    : sink_(sink), profile_(profile), options_(options) {
  profile_.validate();
}

void Tek4125Driver::send() {
  if (buffer_.empty()) return;
  sink_.write(std::span<const std::uint8_t>(buffer_));
  stats_.bytes += buffer_.size();
  buffer_.clear();
}

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
  width_ = frame.width;
  height_ = frame.height;
  paletteSize_ = static_cast<int>(frame.palette.size());
  place_ = placePicture(profile_, width_, height_);
  // A picture whose indices fit in 4 bits is sent at 4 bits a pixel even on
  // an 8-plane terminal: half the raster bytes. (4 and the plane count are
  // the depths the public sources show; other depths are not used.)
  rasterBits_ = paletteSize_ + profile_.reserved <= 16 ? 4 : profile_.planes;
  nextRow_ = 0;
  stats_ = {};
  open_.clear();
  openAt_.assign(static_cast<std::size_t>(width_), -1);
  xy_.reset();
  begun_ = true;

  using namespace tek;
  buffer_ = {kEsc, '%', '!', '0'};  // enter Tek mode
  appendCommand(buffer_, "LV");     // dialog area invisible, so text cannot cover the picture
  appendInt(buffer_, 0);
  appendCommand(buffer_, "TM");  // colour map in RGB, opaque, normal
  for (int i = 0; i < 3; ++i) appendInt(buffer_, 1);
  appendCommand(buffer_, "TG");
  appendInt(buffer_, kSurface);
  std::vector<int> groups;
  groups.reserve(frame.palette.size() * 4);
  for (int i = 0; i < paletteSize_; ++i) {
    const Rgb8 c = frame.palette[static_cast<std::size_t>(i)];
    groups.insert(groups.end(), {i + profile_.reserved, percentFrom8(c.r), percentFrom8(c.g), percentFrom8(c.b)});
  }
  appendIntArray(buffer_, groups);
  buffer_.insert(buffer_.end(), {kEsc, 0x0C});  // clear the page to index 0
  appendCommand(buffer_, "RU");
  appendInt(buffer_, kSurface);
  appendInt(buffer_, kAluOverwrite);
  appendInt(buffer_, rasterBits_);
  appendCommand(buffer_, "RS");
  xy_.append(buffer_, place_.left, place_.bottom);
  xy_.append(buffer_, place_.left + width_ - 1, place_.bottom + height_ - 1);
  if (options_.skipBackground && profile_.reserved > 0) {
    // The clear painted a reserved entry, not the picture's index 0: paint that once.
    appendCommand(buffer_, "RR");
    xy_.append(buffer_, place_.left, place_.bottom);
    xy_.append(buffer_, place_.left + width_ - 1, place_.bottom + height_ - 1);
    appendInt(buffer_, profile_.reserved);
    ++stats_.rectangleFills;
  }
  send();
}

// Per row, a two-state dynamic programme over the runs of equal index: after
// each run the beam is either inside a raster span (bits are being sent) or
// outside one. Starting a span costs its header; a run outside a span costs
// nothing (background) or a rectangle. Linear in the runs, optimal for the
// estimated costs.
std::vector<Tek4125Driver::Way> Tek4125Driver::chooseWays(const std::vector<Run>& runs,
                                                          const std::vector<int>& continuing) const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double bitsCost = rasterBits_ / 6.0;
  const int background = profile_.reserved;
  const std::size_t n = runs.size();
  std::vector<double> in(n + 1, inf), out(n + 1, inf);
  std::vector<std::uint8_t> inFromIn(n + 1, 0), outFromIn(n + 1, 0);
  out[0] = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const Run& r = runs[k];
    const double raw = r.length * bitsCost;
    const double viaIn = in[k] + raw, viaOut = out[k] + kSpanHeaderBytes + raw;
    inFromIn[k + 1] = viaIn <= viaOut;
    in[k + 1] = std::min(viaIn, viaOut);
    double leave = inf;
    if (options_.skipBackground && r.index == background) leave = 0;
    else if (options_.rectangles) leave = continuing[k] >= 0 ? kExtendBytes : kRectangleBytes;
    const double outIn = in[k] + leave, outOut = out[k] + leave;
    outFromIn[k + 1] = outIn < outOut;
    out[k + 1] = std::min(outIn, outOut);
  }
  std::vector<Way> ways(n);
  bool inside = in[n] < out[n];
  for (std::size_t k = n; k-- > 0;) {
    if (inside) {
      ways[k] = Way::Raster;
      inside = inFromIn[k + 1];
    } else {
      const Run& r = runs[k];
      ways[k] = (options_.skipBackground && r.index == background) ? Way::Skip : Way::Rectangle;
      inside = outFromIn[k + 1];
    }
  }
  return ways;
}

void Tek4125Driver::row(int y, std::span<const PaletteIndex> indices) {
  if (!begun_ || y != nextRow_ || y >= height_ || indices.size() != static_cast<std::size_t>(width_))
    throw Error(ErrorKind::Internal,
                fmt::format("tek4125: row {} ({} pixels) out of order; expected row {} of {} pixels", y,
                            indices.size(), nextRow_, width_));
  ++nextRow_;
  std::vector<Run> runs;
  for (int x = 0; x < width_;) {
    const int index = indices[static_cast<std::size_t>(x)];
    if (index >= paletteSize_)
      throw Error(ErrorKind::Internal,
                  fmt::format("tek4125: row {} pixel {} has index {} beyond the {}-entry palette", y, x, index,
                              paletteSize_));
    int end = x + 1;
    while (end < width_ && indices[static_cast<std::size_t>(end)] == index) ++end;
    runs.push_back(Run{x, end - x, index + profile_.reserved});
    x = end;
  }
  const int tekRow = height_ - 1 - y;  // relative to the viewport's bottom
  // Which runs repeat a rectangle left open by the row above.
  std::vector<int> continuing(runs.size(), -1);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const int o = openAt_[static_cast<std::size_t>(runs[k].start)];
    if (o >= 0 && open_[static_cast<std::size_t>(o)].run.length == runs[k].length &&
        open_[static_cast<std::size_t>(o)].run.index == runs[k].index)
      continuing[k] = o;
  }
  const std::vector<Way> ways = chooseWays(runs, continuing);
  std::vector<OpenRectangle> next;
  for (std::size_t k = 0; k < runs.size();) {
    if (ways[k] == Way::Skip) {
      stats_.skippedPixels += static_cast<std::uint64_t>(runs[k].length);
      ++k;
    } else if (ways[k] == Way::Rectangle) {
      if (continuing[k] >= 0) {
        OpenRectangle& grown = open_[static_cast<std::size_t>(continuing[k])];
        ++grown.rows;
        next.push_back(grown);
        grown.rows = 0;  // taken over by next: not to be sent when the old rectangles close
      } else {
        next.push_back(OpenRectangle{runs[k], tekRow, 1});
      }
      ++k;
    } else {
      std::size_t end = k;
      while (end < runs.size() && ways[end] == Way::Raster) ++end;
      emitSpan(std::span<const Run>(runs).subspan(k, end - k), tekRow);
      k = end;
    }
  }
  if (!options_.mergeRows) {
    for (const OpenRectangle& r : next) emitRectangle(r);
    next.clear();
  }
  closeRectangles(next);
  send();
}

// Rectangles of the previous row that this row did not extend are final:
// send them. Pixels of different rectangles and spans never overlap, so
// sending a rectangle rows later paints the same picture.
void Tek4125Driver::closeRectangles(std::vector<OpenRectangle>& next) {
  for (const OpenRectangle& r : open_) {
    if (r.rows > 0) emitRectangle(r);
    openAt_[static_cast<std::size_t>(r.run.start)] = -1;
  }
  open_.swap(next);
  for (std::size_t i = 0; i < open_.size(); ++i)
    openAt_[static_cast<std::size_t>(open_[i].run.start)] = static_cast<int>(i);
}

void Tek4125Driver::emitRectangle(const OpenRectangle& rect) {
  // RR corners are screen pixels (not viewport-relative, unlike RH).
  const int x = place_.left + rect.run.start;
  const int top = place_.bottom + rect.topTekRow;
  tek::appendCommand(buffer_, "RR");
  xy_.append(buffer_, x, top - rect.rows + 1);
  xy_.append(buffer_, x + rect.run.length - 1, top);
  tek::appendInt(buffer_, rect.run.index);
  ++stats_.rectangleFills;
}

void Tek4125Driver::emitSpan(std::span<const Run> runs, int tekRow) {
  const int start = runs.front().start;
  const int count = runs.back().start + runs.back().length - start;
  const int bits = rasterBits_;
  const int chars = (count * bits + 5) / 6;
  tek::appendCommand(buffer_, "RH");
  xy_.append(buffer_, start, tekRow);
  tek::appendCommand(buffer_, "RP");
  tek::appendInt(buffer_, count);
  tek::appendInt(buffer_, chars);
  // Pixels MSB first into 6-bit groups, each sent as 0x20 + group.
  unsigned accumulator = 0;
  int held = 0;
  for (const Run& r : runs) {
    for (int i = 0; i < r.length; ++i) {
      accumulator = accumulator << bits | static_cast<unsigned>(r.index);
      held += bits;
      while (held >= 6) {
        held -= 6;
        buffer_.push_back(static_cast<std::uint8_t>(0x20 + ((accumulator >> held) & 63u)));
      }
      accumulator &= (1u << held) - 1u;
    }
  }
  if (held > 0) buffer_.push_back(static_cast<std::uint8_t>(0x20 + ((accumulator << (6 - held)) & 63u)));
  ++stats_.rasterWrites;
}

void Tek4125Driver::end() {
  if (!begun_ || nextRow_ != height_)
    throw Error(ErrorKind::Internal,
                fmt::format("tek4125: end() after {} of {} rows", nextRow_, height_));
  begun_ = false;
  std::vector<OpenRectangle> none;
  closeRectangles(none);
  send();
  sink_.flush();
  stats_.seconds = transmitSeconds(stats_.bytes, profile_.line());
}

std::unique_ptr<Tek4125Driver> makeTek4125Driver(ByteSink& sink, const Tek4125Profile& profile,
                                                 Tek4125DriverOptions options) {
  return std::make_unique<Tek4125Driver>(sink, profile, options);
}

}  // namespace lattice
