#include "io/image_metrics.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include "foundation/error.hpp"

namespace lattice::io {

namespace {

void requireSameSize(const RgbImage& a, const RgbImage& b, const std::string& what) {
  if (a.width != b.width || a.height != b.height)
    throw Error(ErrorKind::Input, fmt::format("{}: the images differ in size ({}x{} vs {}x{}); render both at the same "
                                              "size (--width/--height)",
                                              what, a.width, a.height, b.width, b.height));
  const std::size_t expected = static_cast<std::size_t>(a.width) * static_cast<std::size_t>(a.height) * 3;
  if (a.rgb.size() != expected || b.rgb.size() != expected)
    throw Error(ErrorKind::Internal, fmt::format("{}: pixel buffer does not match the image size", what));
}

ImageMetrics measure(const RgbImage& a, const RgbImage& b, int blockSize) {
  if (blockSize < 1) throw Error(ErrorKind::Usage, fmt::format("--block {}: the block size must be at least 1", blockSize));
  ImageMetrics m;
  m.width = a.width;
  m.height = a.height;
  m.blockSize = blockSize;
  const int blocksX = (a.width + blockSize - 1) / blockSize;
  const int blocksY = (a.height + blockSize - 1) / blockSize;
  // Per block: sum of |a - b| over its channels, and its pixel count.
  std::vector<double> blockSum(static_cast<std::size_t>(blocksX) * static_cast<std::size_t>(blocksY), 0.0);
  std::vector<long> blockPixels(blockSum.size(), 0);
  double squared = 0.0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const std::uint8_t* pa = a.pixel(x, y);
      const std::uint8_t* pb = b.pixel(x, y);
      int pixelSum = 0;
      for (int c = 0; c < 3; ++c) {
        const int d = std::abs(int{pa[c]} - int{pb[c]});
        pixelSum += d;
        squared += double(d) * double(d);
        m.maxChannelError = std::max(m.maxChannelError, d);
      }
      if (pixelSum > 0) ++m.differingPixels;
      const std::size_t block =
          static_cast<std::size_t>(y / blockSize) * static_cast<std::size_t>(blocksX) + static_cast<std::size_t>(x / blockSize);
      blockSum[block] += pixelSum;
      ++blockPixels[block];
    }
  }
  const double samples = 3.0 * double(a.width) * double(a.height);
  if (samples > 0) m.rms = std::sqrt(squared / samples);
  m.psnr = m.rms > 0 ? 20.0 * std::log10(255.0 / m.rms) : std::numeric_limits<double>::infinity();
  double meanSum = 0.0;
  m.worstBlockMean = -1.0;
  for (int by = 0; by < blocksY; ++by) {
    for (int bx = 0; bx < blocksX; ++bx) {
      const std::size_t i = static_cast<std::size_t>(by) * static_cast<std::size_t>(blocksX) + static_cast<std::size_t>(bx);
      const double mean = blockSum[i] / (3.0 * double(blockPixels[i]));
      meanSum += mean;
      if (mean > m.worstBlockMean) {
        m.worstBlockMean = mean;
        m.worstBlockX = bx * blockSize;
        m.worstBlockY = by * blockSize;
      }
    }
  }
  if (blockSum.empty()) m.worstBlockMean = 0.0;
  else m.meanBlockMean = meanSum / double(blockSum.size());
  return m;
}

}  // namespace

ImageMetrics compareRgb(const RgbImage& a, const RgbImage& b, int blockSize) {
  requireSameSize(a, b, "compare");
  return measure(a, b, blockSize);
}

ImagePair readComparablePngs(const std::filesystem::path& a, const std::filesystem::path& b) {
  ImagePair pair{readPng(a), readPng(b)};  // readPng's errors name the file
  if (pair.a.width != pair.b.width || pair.a.height != pair.b.height)
    throw Error(ErrorKind::Input, fmt::format("{} is {}x{} but {} is {}x{}: compare renders of the same size "
                                              "(--width/--height)",
                                              a.string(), pair.a.width, pair.a.height, b.string(), pair.b.width,
                                              pair.b.height));
  return pair;
}

ImageMetrics compareRgbFiles(const std::filesystem::path& a, const std::filesystem::path& b, int blockSize) {
  const ImagePair pair = readComparablePngs(a, b);
  return compareRgb(pair.a, pair.b, blockSize);
}

RgbImage amplifiedDifference(const RgbImage& a, const RgbImage& b, double gain) {
  requireSameSize(a, b, "difference image");
  if (!(gain > 0) || !std::isfinite(gain))
    throw Error(ErrorKind::Usage, fmt::format("--gain {}: the gain must be a positive number", gain));
  RgbImage out(a.width, a.height);
  for (std::size_t i = 0; i < a.rgb.size(); ++i) {
    const double d = std::abs(double(a.rgb[i]) - double(b.rgb[i])) * gain;
    out.rgb[i] = static_cast<std::uint8_t>(std::lround(std::min(d, 255.0)));
  }
  return out;
}

}  // namespace lattice::io
