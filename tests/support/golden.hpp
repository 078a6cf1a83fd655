#pragma once
// Golden files under tests/golden/. A test compares what it produced with the
// stored file; with LATTICE_REGENERATE_GOLDENS=1 in the environment it writes
// the file instead (scripts/regenerate-goldens.sh does this for every suite).
// Review regenerated goldens with `git diff --stat tests/golden` before committing.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "io/png.hpp"

namespace lattice::testing {

std::filesystem::path goldenPath(const std::string& relative);
std::filesystem::path sourcePath(const std::string& relative);  // a file of the repository
bool regeneratingGoldens();

// Byte-exact comparison (streams). Fails with the first differing offset.
void checkGoldenBytes(const std::string& relative, std::span<const std::uint8_t> actual);

// Image comparison: the images match when no channel of any pixel differs by
// more than maxChannelDelta and at most maxDifferingPixels pixels differ at all.
struct ImageTolerance {
  int maxChannelDelta = 0;
  long maxDifferingPixels = 0;
};
void checkGoldenPng(const std::string& relative, const RgbImage& actual, ImageTolerance tolerance = {});

// How two images differ: count of differing pixels and the largest channel delta.
struct ImageDifference {
  long differingPixels = 0;
  int maxChannelDelta = 0;
  double meanSquaredError = 0.0;
};
ImageDifference compareImages(const RgbImage& a, const RgbImage& b);

}  // namespace lattice::testing
