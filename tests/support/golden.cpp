#include "tests/support/golden.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <cmath>

#include "foundation/system/atomic_file.hpp"

namespace lattice::testing {

std::filesystem::path goldenPath(const std::string& relative) {
  return std::filesystem::path(LATTICE_GOLDEN_DIR) / relative;
}

std::filesystem::path sourcePath(const std::string& relative) {
  return std::filesystem::path(LATTICE_SOURCE_DIR) / relative;
}

bool regeneratingGoldens() {
  const char* flag = std::getenv("LATTICE_REGENERATE_GOLDENS");
  return flag != nullptr && std::string(flag) == "1";
}

void checkGoldenBytes(const std::string& relative, std::span<const std::uint8_t> actual) {
  auto path = goldenPath(relative);
  if (regeneratingGoldens()) {
    std::filesystem::create_directories(path.parent_path());
    writeFileAtomically(path, actual);
    WARN("regenerated golden " << path.string());
    return;
  }
  INFO("golden " << path.string() << " (regenerate: scripts/regenerate-goldens.sh)");
  REQUIRE(std::filesystem::exists(path));
  std::vector<std::uint8_t> expected = readWholeFile(path);
  auto mismatch = std::mismatch(expected.begin(), expected.end(), actual.begin(), actual.end());
  INFO("first difference at byte " << (mismatch.first - expected.begin()) << "; expected size "
                                   << expected.size() << ", actual size " << actual.size());
  CHECK((mismatch.first == expected.end() && mismatch.second == actual.end()));
}

ImageDifference compareImages(const RgbImage& a, const RgbImage& b) {
  ImageDifference d;
  if (a.width != b.width || a.height != b.height) {
    d.differingPixels = -1;
    return d;
  }
  double sum = 0;
  for (std::size_t p = 0; p + 2 < a.rgb.size(); p += 3) {
    int delta = 0;
    for (int c = 0; c < 3; ++c) {
      int e = std::abs(int(a.rgb[p + c]) - int(b.rgb[p + c]));
      delta = std::max(delta, e);
      sum += double(e) * double(e);
    }
    if (delta > 0) ++d.differingPixels;
    d.maxChannelDelta = std::max(d.maxChannelDelta, delta);
  }
  d.meanSquaredError = a.rgb.empty() ? 0.0 : sum / double(a.rgb.size());
  return d;
}

void checkGoldenPng(const std::string& relative, const RgbImage& actual, ImageTolerance tolerance) {
  auto path = goldenPath(relative);
  if (regeneratingGoldens()) {
    std::filesystem::create_directories(path.parent_path());
    io::writePng(path, actual);
    WARN("regenerated golden " << path.string());
    return;
  }
  INFO("golden " << path.string() << " (regenerate: scripts/regenerate-goldens.sh)");
  REQUIRE(std::filesystem::exists(path));
  RgbImage expected = io::readPng(path);
  REQUIRE(expected.width == actual.width);
  REQUIRE(expected.height == actual.height);
  ImageDifference d = compareImages(expected, actual);
  INFO("differing pixels " << d.differingPixels << " (allowed " << tolerance.maxDifferingPixels
                           << "), max channel delta " << d.maxChannelDelta << " (allowed "
                           << tolerance.maxChannelDelta << ")");
  CHECK(d.differingPixels <= tolerance.maxDifferingPixels);
  CHECK(d.maxChannelDelta <= tolerance.maxChannelDelta);
}

}  // namespace lattice::testing
