#include "app/stream_points.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "devices/work_budget.hpp"
#include "foundation/error.hpp"
#include "foundation/number_text.hpp"
#include "app/output_check.hpp"
#include "io/png.hpp"

namespace lattice::app {

std::vector<StreamPoint> parseStreamPoints(const std::string& text, std::uint64_t total) {
  std::vector<StreamPoint> points;
  std::size_t from = 0;
  while (from <= text.size()) {
    const std::size_t comma = std::min(text.find(',', from), text.size());
    const std::string item = text.substr(from, comma - from);
    if (points.size() == kMaxStreamPoints)
      throw Error(ErrorKind::Usage, fmt::format("--at: more than {} points; each writes a full screen, so choose "
                                                "at most {}, e.g. --at 10%,25%,50%",
                                                kMaxStreamPoints, kMaxStreamPoints));
    const bool percent = !item.empty() && item.back() == '%';
    const std::string number = percent ? item.substr(0, item.size() - 1) : item;
    const std::string what = fmt::format("--at {} (a percentage 0%..100% or a whole byte offset)",
                                         item.empty() ? "''" : item);
    if (percent) {
      const double value = parseNumberText(what, number, {0, 100});
      points.push_back({static_cast<std::uint64_t>(std::llround(value / 100.0 * double(total))),
                        fmt::format("{:g}pct", value)});
    } else {
      const double value = parseNumberText(what, number, {0, double(kMaxStreamBytes), true});
      points.push_back({std::min(total, static_cast<std::uint64_t>(value)), fmt::format("{:.0f}B", value)});
    }
    from = comma + 1;
  }
  std::stable_sort(points.begin(), points.end(),
                   [](const StreamPoint& a, const StreamPoint& b) { return a.offset < b.offset; });
  return points;
}

void checkStreamPointOutputs(const std::string& text, const std::string& output, bool force) {
  for (const StreamPoint& p : parseStreamPoints(text, 0)) checkOutputPath(pointPngPath(output, p.tag), "--at", force);
}

std::string pointPngPath(const std::string& output, const std::string& tag) {
  const std::filesystem::path path(output);
  std::filesystem::path named = path;
  named.replace_filename(path.stem().string() + "-at" + tag + (path.has_extension() ? path.extension().string() : ".png"));
  return named.string();
}

std::vector<std::string> decodeWithSnapshots(StreamDecoder& decoder, std::FILE* in, const std::string& name,
                                             const std::string& points, const std::string& output) {
  std::vector<std::uint8_t> stream;
  std::vector<std::uint8_t> buffer(1 << 16);
  while (true) {
    const std::size_t n = std::fread(buffer.data(), 1, buffer.size(), in);
    stream.insert(stream.end(), buffer.begin(), buffer.begin() + static_cast<long>(n));
    if (stream.size() > kMaxStreamBytes)
      throw Error(ErrorKind::Input, fmt::format("{}: the stream is longer than the emulator's limit of {} bytes "
                                                "(kMaxStreamBytes, docs/limits.md)",
                                                name, kMaxStreamBytes));
    if (n < buffer.size()) break;
  }
  if (std::ferror(in) != 0) throw Error(ErrorKind::Input, fmt::format("{}: read error", name));
  std::vector<std::string> written;
  std::uint64_t fed = 0;
  for (const StreamPoint& p : parseStreamPoints(points, stream.size())) {
    decoder.feed(std::span<const std::uint8_t>(stream).subspan(fed, p.offset - fed));
    fed = p.offset;
    written.push_back(pointPngPath(output, p.tag));
    io::writePng(written.back(), decoder.image());
  }
  decoder.feed(std::span<const std::uint8_t>(stream).subspan(fed));
  decoder.finish();
  checkPixelWork(decoder.report(), name);
  return written;
}

}  // namespace lattice::app
