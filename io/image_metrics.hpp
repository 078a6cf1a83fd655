#pragma once
// How far one RGB picture is from another: the figures `lattice diff` prints
// and benches quote when comparing a lattice render with the full ray trace
// (thesis ch. 4 says fidelity has "no well-established quantitative
// criterion"; PSNR/RMS plus a worst-block figure is the usual stand-in).
#include <cstdint>
#include <filesystem>

#include "io/png.hpp"

namespace lattice::io {

struct ImageMetrics {
  int width = 0;
  int height = 0;
  double rms = 0.0;            // root mean square channel difference, 0..255
  double psnr = 0.0;           // dB against a peak of 255; +infinity when identical
  int maxChannelError = 0;     // largest |a - b| of any channel of any pixel
  long differingPixels = 0;    // pixels where any channel differs
  int blockSize = 8;           // N of the N x N blocks below
  double worstBlockMean = 0.0; // largest mean |a - b| (over pixels and channels) of one block
  int worstBlockX = 0;         // top-left pixel of that block
  int worstBlockY = 0;
  double meanBlockMean = 0.0;  // mean of the block means (edge blocks weighted like the others)
};

// Both images must have the same size (Error(Input) otherwise, naming the
// sizes); blockSize >= 1 (Error(Usage)). A block at the right or bottom edge
// that is cut short is averaged over the pixels it has, so a local error at
// the border is not diluted by pixels that do not exist.
ImageMetrics compareRgb(const RgbImage& a, const RgbImage& b, int blockSize = 8);

struct ImagePair {
  RgbImage a;
  RgbImage b;
};
// Reads two PNGs that must be the same size; errors name the offending file
// (unreadable, not a PNG, or sizes that differ, with both sizes).
ImagePair readComparablePngs(const std::filesystem::path& a, const std::filesystem::path& b);

// readComparablePngs + compareRgb.
ImageMetrics compareRgbFiles(const std::filesystem::path& a, const std::filesystem::path& b, int blockSize = 8);

// |a - b| per channel times gain, clamped to 255: small errors become visible
// while identical pixels stay black.
RgbImage amplifiedDifference(const RgbImage& a, const RgbImage& b, double gain);

}  // namespace lattice::io
