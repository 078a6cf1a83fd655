#include "app/wire_budget.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "foundation/byte_sink.hpp"
#include "foundation/error.hpp"
#include "foundation/progress.hpp"
#include "foundation/rgb_image_source.hpp"
#include "io/image_metrics.hpp"
#include "io/ssim.hpp"
#include "quantize/rate_distortion_runs.hpp"
#include "quantize/run_pipeline.hpp"

namespace lattice::app {
namespace {

constexpr std::array<int, 12> kPaletteSizes = {256, 128, 64, 48, 32, 24, 16, 12, 8, 6, 4, 2};
constexpr std::array<quantize::Dither, 2> kDithers = {quantize::Dither::None, quantize::Dither::FloydSteinberg};
constexpr int kLadderSteps = 16;  // lambda = 50 * 2^k, k = 0..15: up to 1.6M squared error a byte
constexpr int kRefineSteps = 3;   // then bisection between rungs to 2^(1/8) (9 %) of lambda
constexpr int kShrinkSteps = 8;

double ladderLambda(double k) { return 50.0 * std::exp2(k); }

// The --dither spelling, so the settings printed can be typed back.
std::string_view ditherName(quantize::Dither d) { return nameOfValue(quantize::kDitherNames, d, "?"); }

// Area average to a smaller size: each output pixel the mean of the input
// pixels its footprint covers (whole pixels; enough for a fallback).
RgbImage shrink(const RgbImage& in, int width, int height) {
  RgbImage out(width, height);
  for (int y = 0; y < height; ++y) {
    const int y0 = y * in.height / height, y1 = std::max(y0 + 1, (y + 1) * in.height / height);
    for (int x = 0; x < width; ++x) {
      const int x0 = x * in.width / width, x1 = std::max(x0 + 1, (x + 1) * in.width / width);
      std::array<unsigned, 3> sum{};
      for (int v = y0; v < y1; ++v)
        for (int u = x0; u < x1; ++u)
          for (std::size_t c = 0; c < 3; ++c) sum[c] += in.pixel(u, v)[c];
      const unsigned n = static_cast<unsigned>((y1 - y0) * (x1 - x0));
      for (std::size_t c = 0; c < 3; ++c) out.pixel(x, y)[c] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
    }
  }
  return out;
}

class Searcher {
 public:
  Searcher(const devices::Device& device, const quantize::QuantizeOptions& quantizer, std::uint64_t limit,
           LineFormat line, Progress& progress, bool prune)
      : device_(device), quantizer_(quantizer), limit_(limit), line_(line), progress_(progress), prune_(prune) {
    CountingSink none;
    maxColors_ = device_.makeDriver(none)->sink().maxColors();
  }

  int encodings = 0;

  // Searches one picture size; the best fitting choice so far is kept across calls.
  void search(const RgbImage& reference) {
    for (int colors : kPaletteSizes) {
      if (colors > maxColors_) continue;
      for (quantize::Dither dither : kDithers) {
        IndexedImage lossless = quantize(reference, colors, dither);
        // No picture in this palette, dithered or smoothed by runs, comes nearer
        // the truecolour one than the bound: if that is no better than a fitting
        // choice already found, nothing of this setting can win.
        if (prune_ && fits() && paletteBound(reference, lossless.colormap) <= best_->psnr) continue;
        const double psnr = io::compareRgb(reference, toRgbImage(lossless)).psnr;
        const std::uint64_t bytes = encode(lossless);
        WireChoice c{colors, dither, 0, reference.width, reference.height, bytes, 0, psnr, 0, bytes <= limit_};
        consider(c, lossless, reference);
        if (c.fits || !device_.runCost) continue;
        searchLambda(lossless, reference, c);
      }
    }
  }

  bool fits() const { return best_ && best_->fits; }
  WireSearch result(std::uint64_t limit) {
    WireSearch s;
    s.picture = bestPicture_;
    s.reference = bestReference_;
    s.choice = *best_;
    s.choice.seconds = transmitSeconds(s.choice.bytes, line_);
    s.choice.ssim = s.picture.width > 10 && s.picture.height > 10
                        ? io::meanSsim(s.reference, toRgbImage(s.picture))
                        : std::nan("");  // SSIM's window needs 11x11
    s.limit = limit;
    s.baud = line_.baud;
    s.encodings = encodings;
    return s;
  }

 private:
  IndexedImage quantize(const RgbImage& reference, int colors, quantize::Dither dither) {
    RgbImageSource source(reference);
    IndexedImageSink sink(maxColors_);
    quantize::PipelineOptions options;
    options.mode = quantize::PipelineMode::Frame;
    options.maxColors = colors;
    options.quantize = quantizer_;
    options.quantize.dither = dither;
    options.progress = false;
    quantize::runPipeline(source, sink, options);
    return sink.image();
  }

  // The PSNR of the palette's best picture, each pixel at its nearest entry
  // (squared 8-bit RGB error, as the PSNR is measured). Settings that differ
  // only in dithering share a palette, so the last one is kept.
  double paletteBound(const RgbImage& reference, const Palette& palette) {
    if (palette == boundPalette_ && reference.width == boundWidth_ && reference.height == boundHeight_) return bound_;
    std::unordered_map<std::uint32_t, Rgb8> nearest;
    RgbImage best(reference.width, reference.height);
    for (std::size_t i = 0; i < reference.rgb.size(); i += 3) {
      const Rgb8 t{reference.rgb[i], reference.rgb[i + 1], reference.rgb[i + 2]};
      const std::uint32_t key = std::uint32_t(t.r) << 16 | std::uint32_t(t.g) << 8 | t.b;
      auto found = nearest.find(key);
      if (found == nearest.end()) {
        Rgb8 pick = palette.front();
        double least = quantize::colourError(t, pick);
        for (const Rgb8& p : palette)
          if (const double e = quantize::colourError(t, p); e < least) least = e, pick = p;
        found = nearest.emplace(key, pick).first;
      }
      best.rgb[i] = found->second.r, best.rgb[i + 1] = found->second.g, best.rgb[i + 2] = found->second.b;
    }
    boundPalette_ = palette, boundWidth_ = reference.width, boundHeight_ = reference.height;
    bound_ = io::compareRgb(reference, best).psnr;
    return bound_;
  }

  std::uint64_t encode(const IndexedImage& picture) {
    CountingSink counter;
    auto driver = device_.makeDriver(counter);
    sendPicture(picture, driver->sink());
    ++encodings;
    progress_.advance();
    return counter.bytesWritten();
  }

  // The smallest lambda of the ladder whose stream fits, by bisection.
  void searchLambda(const IndexedImage& lossless, const RgbImage& reference, const WireChoice& base) {
    const quantize::RunCost cost = device_.runCost(lossless);
    auto attempt = [&](double k, IndexedImage& out) {
      out = lossless;
      quantize::rateDistortionImage(out, cost, ladderLambda(k), reference);
      return encode(out);
    };
    IndexedImage top;
    const std::uint64_t topBytes = attempt(kLadderSteps - 1, top);
    if (topBytes > limit_) {  // even the coarsest does not fit: keep it only as the smallest stream
      WireChoice c = base;
      c.lambda = ladderLambda(kLadderSteps - 1);
      c.bytes = topBytes;
      c.psnr = io::compareRgb(reference, toRgbImage(top)).psnr;
      c.fits = false;
      consider(c, top, reference);
      return;
    }
    int lo = -1, hi = kLadderSteps - 1;  // lo does not fit (lambda 0), hi fits
    IndexedImage fitting = std::move(top), trial;
    std::uint64_t fittingBytes = topBytes;
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      const std::uint64_t bytes = attempt(mid, trial);
      if (bytes <= limit_) hi = mid, fitting = std::move(trial), fittingBytes = bytes;
      else lo = mid;
    }
    // Between the rungs: a doubling of lambda can leave a tenth of the bytes unused.
    double fitK = hi, overK = lo;
    for (int step = 0; step < kRefineSteps; ++step) {
      const double mid = (fitK + overK) / 2;
      const std::uint64_t bytes = attempt(mid, trial);
      if (bytes <= limit_) fitK = mid, fitting = std::move(trial), fittingBytes = bytes;
      else overK = mid;
    }
    WireChoice c = base;
    c.lambda = ladderLambda(fitK);
    c.bytes = fittingBytes;
    c.psnr = io::compareRgb(reference, toRgbImage(fitting)).psnr;
    c.fits = true;
    consider(c, fitting, reference);
  }

  // Fitting beats not fitting; among fitting, higher PSNR, then fewer bytes;
  // among not fitting, fewer bytes.
  void consider(const WireChoice& c, const IndexedImage& picture, const RgbImage& reference) {
    bool better = !best_;
    if (best_) {
      if (c.fits != best_->fits) better = c.fits;
      else if (c.fits) better = c.psnr > best_->psnr || (c.psnr == best_->psnr && c.bytes < best_->bytes);
      else better = c.bytes < best_->bytes;
    }
    if (!better) return;
    best_ = c;
    bestPicture_ = picture;
    if (bestReference_.width != reference.width || bestReference_.height != reference.height) bestReference_ = reference;
  }

  const devices::Device& device_;
  quantize::QuantizeOptions quantizer_;
  std::uint64_t limit_;
  LineFormat line_;
  Progress& progress_;
  bool prune_ = true;
  int maxColors_ = 256;
  std::optional<WireChoice> best_;
  Palette boundPalette_;
  int boundWidth_ = 0, boundHeight_ = 0;
  double bound_ = 0;
  IndexedImage bestPicture_;
  RgbImage bestReference_;
};

}  // namespace

void sendPicture(const IndexedImage& picture, IndexedSink& sink) {
  sink.begin(FrameInfo{picture.width, picture.height, picture.colormap});
  const auto width = static_cast<std::size_t>(picture.width);
  for (int y = 0; y < picture.height; ++y)
    sink.row(y, std::span<const PaletteIndex>(picture.pixels).subspan(std::size_t(y) * width, width));
  sink.end();
}

WireSearch searchWireBudget(const RgbImage& truecolour, const devices::Device& device, const WireBudget& budget,
                            const quantize::QuantizeOptions& quantizer, bool progress) {
  LineFormat line = device.line.value_or(LineFormat{});
  if (budget.baud > 0) line.baud = budget.baud;
  else if (!device.line && budget.seconds)
    throw Error(ErrorKind::Usage, fmt::format("--wire-seconds: {} has no serial line; give --baud B or use "
                                              "--wire-bytes N",
                                              device.name));
  std::uint64_t limit = budget.bytes.value_or(UINT64_MAX);
  if (budget.seconds)
    limit = std::min(limit, static_cast<std::uint64_t>(*budget.seconds * line.baud / line.bitsPerCharacter()));
  Progress bar("wire budget", kPaletteSizes.size() * kDithers.size() * 6, "encodings");  // an estimate
  bar.setEnabled(bar.enabled() && progress);
  Searcher searcher(device, quantizer, limit, line, bar, budget.prune);
  RgbImage reference = truecolour;
  searcher.search(reference);
  for (int step = 0; step < kShrinkSteps && budget.shrink && !searcher.fits(); ++step) {
    const int w = std::max(1, reference.width * 4 / 5), h = std::max(1, reference.height * 4 / 5);
    reference = shrink(truecolour, w, h);
    searcher.search(reference);
  }
  bar.finish();
  return searcher.result(limit);
}

std::vector<std::string> wireSettingsToAdd(const devices::Device& device, const std::vector<std::string>& user) {
  auto key = [](const std::string& kv) { return kv.substr(0, kv.find('=')); };
  std::vector<std::string> added;
  for (const std::string& s : device.wireSettings)
    if (std::none_of(user.begin(), user.end(), [&](const std::string& u) { return key(u) == key(s); }))
      added.push_back(s);
  return added;
}

std::string describeWireChoice(const WireSearch& s) {
  const WireChoice& c = s.choice;
  return fmt::format("{} colours, dither {}, lambda {:.0f}{}, {}x{}: {} bytes of {} allowed, {:.1f} s at {} baud, "
                     "PSNR {:.2f} dB, SSIM {:.4f} ({} encodings)",
                     c.colors, ditherName(c.dither), c.lambda,
                     s.settings.empty() ? "" : fmt::format(", {}", fmt::join(s.settings, ", ")), c.width, c.height,
                     c.bytes, s.limit, c.seconds, s.baud, c.psnr, c.ssim, s.encodings);
}

}  // namespace lattice::app
