// The size search of app/wire_size.hpp.
#include "app/wire_size.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "foundation/progress.hpp"

namespace lattice::app {
namespace {

constexpr double kSizeStep = 1.25;       // the first step, growing or shrinking until the floor is bracketed
constexpr double kMinStep = 1.01;        // a step of less than 1 % of a side tells nothing new
constexpr double kSizeTolerance = 1.04;  // the bracket's ends within 4 % of a side
constexpr double kAimAbove = 0.2;        // dB above the floor a probe aims at, so it tends to land inside
constexpr int kMinSide = 16;

struct Probe {
  double scale = 0;
  WireSearch search;
  bool ok = false;  // fits with at least the floor
};

}  // namespace

SizeArea sizeAreaFor(int sceneWidth, int sceneHeight, int deviceWidth, int deviceHeight) {
  SizeArea area;
  const double aspect = double(sceneWidth) / double(sceneHeight);
  area.maxWidth = std::min(deviceWidth, int(std::floor(deviceHeight * aspect)));
  area.maxHeight = std::min(deviceHeight, int(std::floor(deviceWidth / aspect)));
  area.maxWidth = std::max(1, area.maxWidth), area.maxHeight = std::max(1, area.maxHeight);
  const double fit = std::min(1.0, std::min(double(deviceWidth) / sceneWidth, double(deviceHeight) / sceneHeight));
  area.startWidth = std::max(1, int(sceneWidth * fit)), area.startHeight = std::max(1, int(sceneHeight * fit));
  return area;
}

WireSizeSearch searchWireSize(const RenderAt& renderAt, const SizeArea& area, double floorDb,
                              const devices::Device& device, const WireBudget& budget,
                              const quantize::QuantizeOptions& quantizer, bool progress) {
  const auto start = std::chrono::steady_clock::now();
  WireSizeSearch out;
  out.floor = floorDb;
  Progress bar("wire size", 8, "sizes");  // an estimate: a bracket and three bisections
  bar.setEnabled(bar.enabled() && progress);
  const auto sizeAt = [&](double scale) {
    return std::pair{std::clamp(int(std::lround(area.maxWidth * scale)), 1, area.maxWidth),
                     std::clamp(int(std::lround(area.maxHeight * scale)), 1, area.maxHeight)};
  };
  std::vector<Probe> probes;
  const auto probe = [&](double scale) -> const Probe& {
    const auto [w, h] = sizeAt(scale);
    Probe p;
    p.scale = scale;
    p.search = searchWireBudget(renderAt(w, h), device, budget, quantizer, false);
    p.ok = p.search.choice.fits && p.search.choice.psnr >= floorDb;
    out.tried.push_back(SizeTried{w, h, p.search.choice.psnr, p.search.choice.fits});
    bar.advance();
    probes.push_back(std::move(p));
    return probes.back();
  };
  const double smallest = std::min(1.0, double(kMinSide) / std::min(area.maxWidth, area.maxHeight));
  // The scale where the PSNR, taken as linear in log scale through the two
  // probes nearest the floor, is a little above the floor; nullopt without
  // two fitting probes.
  const auto aim = [&]() -> std::optional<double> {
    std::vector<const Probe*> fitting;
    for (const Probe& p : probes)
      if (p.search.choice.fits) fitting.push_back(&p);
    if (fitting.size() < 2) return std::nullopt;
    std::sort(fitting.begin(), fitting.end(), [&](const Probe* a, const Probe* b) {
      return std::abs(a->search.choice.psnr - floorDb) < std::abs(b->search.choice.psnr - floorDb);
    });
    const Probe &a = *fitting[0], &b = *fitting[1];
    const double slope = (b.search.choice.psnr - a.search.choice.psnr) / std::log(b.scale / a.scale);
    if (!(slope < 0)) return std::nullopt;  // quality must fall as the picture grows
    return a.scale * std::exp((floorDb + kAimAbove - a.search.choice.psnr) / slope);
  };
  double scale = std::max(smallest, std::min(1.0, double(area.startWidth) / area.maxWidth));
  std::optional<double> good, bad;  // the largest scale reaching the floor, the smallest not
  const auto record = [&](double s) {
    if (probe(s).ok) good = std::max(good.value_or(0.0), s);
    else bad = std::min(bad.value_or(1e300), s);
  };
  record(scale);
  // Bracket: grow (or shrink) along the aim, at least kMinStep and at most
  // kSizeStep x kSizeStep a probe, until one side of the floor is found.
  while (!(good && bad) && !(good && *good >= 1.0) && !(bad && *bad <= smallest)) {
    const double from = good ? *good : *bad;
    // A first size that reaches the floor: the whole area next, which a
    // loose budget reaches at once and a tight one brackets.
    if (good && probes.size() == 1) {
      record(1.0);
      continue;
    }
    double next = aim().value_or(good ? from * kSizeStep : from / kSizeStep);
    next = good ? std::clamp(next, from * kMinStep, from * kSizeStep * kSizeStep)
                : std::clamp(next, from / kSizeStep / kSizeStep, from / kMinStep);
    record(std::clamp(next, smallest, 1.0));
  }
  // Narrow: the aim when it falls inside the bracket, else its middle.
  while (good && bad && *bad / *good > kSizeTolerance) {
    double next = aim().value_or(std::sqrt(*good * *bad));
    if (!(next > *good * kMinStep && next < *bad / kMinStep)) next = std::sqrt(*good * *bad);
    if (sizeAt(next) == sizeAt(*good) || sizeAt(next) == sizeAt(*bad)) break;
    record(next);
  }
  bar.finish();
  // The largest size reaching the floor; else the most accurate fitting
  // picture; else the smallest stream.
  const Probe* chosen = nullptr;
  for (const Probe& p : probes) {
    if (!chosen) { chosen = &p; continue; }
    const WireChoice &a = p.search.choice, &b = chosen->search.choice;
    if (good) {
      if (p.ok && (!chosen->ok || p.scale > chosen->scale)) chosen = &p;
    } else if (a.fits != b.fits ? a.fits : a.fits ? a.psnr > b.psnr : a.bytes < b.bytes) {
      chosen = &p;
    }
  }
  out.reachedFloor = good.has_value();
  out.search = chosen->search;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

std::string describeWireSize(const WireSizeSearch& s, const SizeArea& area) {
  std::vector<std::string> tried;
  for (const SizeTried& t : s.tried)
    tried.push_back(t.fits ? fmt::format("{}x{} {:.2f} dB", t.width, t.height, t.psnr)
                           : fmt::format("{}x{} does not fit", t.width, t.height));
  const WireChoice& c = s.search.choice;
  const std::string verdict =
      s.reachedFloor
          ? fmt::format("the largest at the scene's aspect, up to {}x{}, reaching {:.1f} dB", area.maxWidth,
                        area.maxHeight, s.floor)
          : fmt::format("no size from {}x{} down reaches {:.1f} dB (lower --wire-quality, or allow more time): the "
                        "most accurate that fits",
                        area.maxWidth, area.maxHeight, s.floor);
  return fmt::format("picture {}x{}, {} ({:.2f} dB); sizes tried: {}; {:.1f} s", c.width, c.height, verdict, c.psnr,
                     fmt::join(tried, ", "), s.seconds);
}

}  // namespace lattice::app
