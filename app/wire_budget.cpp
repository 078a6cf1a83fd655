#include "app/wire_budget.hpp"

#include "app/wire_lambda.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <chrono>
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
constexpr int kShrinkSteps = 8;
constexpr int kProxyRowStep = 4;        // the proxy: every 4th row, a quarter of the work
constexpr int kWalkStartColours = 64;   // where the walk over palette sizes starts
constexpr std::size_t kFullSettings = 3;  // settings searched at full size, best proxy scores first

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

// Every step-th row of a picture (`channels` bytes a pixel): the proxy a
// setting is ranked on.
std::vector<std::uint8_t> everyNthRow(const std::vector<std::uint8_t>& in, int width, int height, int step,
                                      std::size_t channels) {
  const std::size_t row = std::size_t(width) * channels;
  std::vector<std::uint8_t> out;
  for (int y = 0; y < height; y += step)
    out.insert(out.end(), in.begin() + long(std::size_t(y) * row), in.begin() + long(std::size_t(y + 1) * row));
  return out;
}
int proxyHeight(int height) { return (height + kProxyRowStep - 1) / kProxyRowStep; }

// One palette size and dithering, quantized, with what is known of it.
struct Setting {
  int colors = 0;
  quantize::Dither dither = quantize::Dither::None;
  IndexedImage lossless;
  std::uint64_t losslessBytes = 0;
  double losslessPsnr = 0;
  double score = -1e300;  // the proxy's PSNR at the budget (higher is better); below 0: nothing fitted
  double lambda = 0;      // the proxy's fitting lambda: where the full search starts
};

class Searcher {
 public:
  Searcher(const devices::Device& device, const quantize::QuantizeOptions& quantizer, std::uint64_t limit,
           LineFormat line, Progress& progress, bool coarseToFine)
      : device_(device), quantizer_(quantizer), limit_(limit), line_(line), progress_(progress),
        coarseToFine_(coarseToFine) {
    CountingSink none;
    maxColors_ = device_.makeDriver(none)->sink().maxColors();
    for (int colors : kPaletteSizes)
      if (colors <= maxColors_) sizes_.push_back(colors);
  }

  int encodings = 0, proxyEncodings = 0;

  // Searches one picture size; the best fitting choice so far is kept across calls.
  void search(const RgbImage& reference) {
    if (!coarseToFine_) {
      for (int colors : sizes_)
        for (quantize::Dither dither : kDithers) {
          Setting s = prepare(reference, colors, dither);
          evaluate(reference, s, lastLambda_);
        }
      return;
    }
    // Coarse: rank settings on the proxy, walking palette sizes from the
    // middle towards the better neighbour while the score rises.
    std::vector<Setting> ranked;
    auto proxied = [&](std::size_t i) {
      double score = -1e300;
      for (quantize::Dither dither : kDithers) {
        Setting s = prepare(reference, sizes_[i], dither);
        rankOnProxy(reference, s);
        score = std::max(score, s.score);
        ranked.push_back(std::move(s));
      }
      return score;
    };
    std::size_t start = 0;
    while (start + 1 < sizes_.size() && sizes_[start] > kWalkStartColours) ++start;
    const double here = proxied(start);
    const double up = start > 0 ? proxied(start - 1) : -1e300;
    const double down = start + 1 < sizes_.size() ? proxied(start + 1) : -1e300;
    if (up > here || down > here) {
      const bool more = up >= down;  // towards more colours
      double best = std::max(up, down);
      for (std::size_t i = more ? start - 1 : start + 1; more ? i > 0 : i + 1 < sizes_.size();) {
        i = more ? i - 1 : i + 1;
        const double score = proxied(i);
        if (score <= best) break;
        best = score;
      }
    }
    // Fine: the best few settings at full size, each starting at its proxy's lambda.
    std::stable_sort(ranked.begin(), ranked.end(), [](const Setting& a, const Setting& b) { return a.score > b.score; });
    for (std::size_t i = 0; i < ranked.size() && i < kFullSettings; ++i) {
      Setting& s = ranked[i];
      // No picture in this palette comes nearer the truecolour one than each
      // pixel at its nearest entry: no better than a fitting choice, skip it.
      if (fits() && paletteBound(reference, s.lossless.colormap) <= best_->psnr) continue;
      evaluate(reference, s, s.lambda > 0 ? s.lambda : lastLambda_);
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
    s.proxyEncodings = proxyEncodings;
    return s;
  }

 private:
  Setting prepare(const RgbImage& reference, int colors, quantize::Dither dither) {
    Setting s;
    s.colors = colors;
    s.dither = dither;
    s.lossless = quantize(reference, colors, dither);
    s.losslessBytes = encode(s.lossless);
    s.losslessPsnr = io::compareRgb(reference, toRgbImage(s.lossless)).psnr;
    return s;
  }

  // The setting's score on every kProxyRowStep-th row, against the limit
  // scaled by the lossless streams' ratio (whole picture to proxy).
  void rankOnProxy(const RgbImage& reference, Setting& s) {
    if (s.losslessBytes <= limit_ || !device_.runCost) {  // exact without a proxy
      s.score = s.losslessBytes <= limit_ ? s.losslessPsnr : -double(s.losslessBytes);
      return;
    }
    IndexedImage lossless(s.lossless.width, proxyHeight(s.lossless.height), 0);
    lossless.colormap = s.lossless.colormap;
    lossless.pixels = everyNthRow(s.lossless.pixels, s.lossless.width, s.lossless.height, kProxyRowStep, 1);
    RgbImage truth(reference.width, proxyHeight(reference.height));
    truth.rgb = everyNthRow(reference.rgb, reference.width, reference.height, kProxyRowStep, 3);
    const double ratio = double(s.losslessBytes) / double(std::max<std::uint64_t>(encode(lossless, true), 1));
    const quantize::RunCost cost = device_.runCost(s.lossless);
    const LambdaFit fit = fitLambda(
        [&](double lambda, IndexedImage& out) {
          out = lossless;
          quantize::rateDistortionImage(out, cost, lambda, truth);
          return encode(out, true);
        },
        std::uint64_t(double(limit_) / ratio), lastLambda_);
    s.lambda = fit.lambda;
    s.score = fit.fits ? io::compareRgb(truth, toRgbImage(fit.picture)).psnr : -double(fit.bytes) * ratio;
    if (fit.fits) lastLambda_ = fit.lambda;
  }

  // The setting at full size: lossless if it fits, else the smallest fitting lambda.
  void evaluate(const RgbImage& reference, const Setting& s, double startLambda) {
    WireChoice c{s.colors, s.dither, 0, reference.width, reference.height, s.losslessBytes, 0, s.losslessPsnr, 0,
                 s.losslessBytes <= limit_};
    consider(c, s.lossless, reference);
    if (c.fits || !device_.runCost) return;
    const quantize::RunCost cost = device_.runCost(s.lossless);
    LambdaFit fit = fitLambda(
        [&](double lambda, IndexedImage& out) {
          out = s.lossless;
          quantize::rateDistortionImage(out, cost, lambda, reference);
          return encode(out);
        },
        limit_, startLambda);
    if (fit.fits) lastLambda_ = fit.lambda;
    c.lambda = fit.lambda;
    c.bytes = fit.bytes;
    c.psnr = io::compareRgb(reference, toRgbImage(fit.picture)).psnr;
    c.fits = fit.fits;
    consider(c, fit.picture, reference);
  }

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
  // (squared 8-bit RGB error, as the PSNR is measured).
  double paletteBound(const RgbImage& reference, const Palette& palette) {
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
    return io::compareRgb(reference, best).psnr;
  }

  std::uint64_t encode(const IndexedImage& picture, bool proxy = false) {
    CountingSink counter;
    auto driver = device_.makeDriver(counter);
    sendPicture(picture, driver->sink());
    ++(proxy ? proxyEncodings : encodings);
    progress_.advance();
    return counter.bytesWritten();
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
  bool coarseToFine_ = true;
  int maxColors_ = 256;
  std::vector<int> sizes_;   // the palette sizes the device can show
  double lastLambda_ = 800;  // the last fitting lambda: where the next setting's search starts
  std::optional<WireChoice> best_;
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
  // An estimate of the encodings: about six settings on the proxy and three whole, five each.
  const std::uint64_t expected = budget.exhaustive ? kPaletteSizes.size() * kDithers.size() * 5 : 45;
  Progress bar("wire budget", expected, "encodings");
  bar.setEnabled(bar.enabled() && progress);
  const auto start = std::chrono::steady_clock::now();
  Searcher searcher(device, quantizer, limit, line, bar, !budget.exhaustive);
  RgbImage reference = truecolour;
  searcher.search(reference);
  for (int step = 0; step < kShrinkSteps && budget.shrink && !searcher.fits(); ++step) {
    const int w = std::max(1, reference.width * 4 / 5), h = std::max(1, reference.height * 4 / 5);
    reference = shrink(truecolour, w, h);
    searcher.search(reference);
  }
  bar.finish();
  WireSearch result = searcher.result(limit);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
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
                     "PSNR {:.2f} dB, SSIM {:.4f} ({} encodings and {} of a quarter of the rows, {:.2f} s)",
                     c.colors, ditherName(c.dither), c.lambda,
                     s.settings.empty() ? "" : fmt::format(", {}", fmt::join(s.settings, ", ")), c.width, c.height,
                     c.bytes, s.limit, c.seconds, s.baud, c.psnr, c.ssim, s.encodings, s.proxyEncodings, s.seconds);
}

}  // namespace lattice::app
