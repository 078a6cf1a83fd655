#pragma once
// The picture size as part of a wire budget: the largest picture, up to the
// device's drawable area at the camera's aspect, whose stream fits the
// budget with at least a quality floor (PSNR against the truecolour render
// at that size, as pngquant's --quality sets a floor), for
// `lattice render --wire-seconds S` without --width/--height.
//
// Method: a picture's size is the user's biggest lever on a slow line (a
// 512x512 Plate 6 in 57,600 B is far below 30 dB, a smaller one is not), and
// the best PSNR within a fixed budget falls as the picture grows, close to
// linearly in the logarithm of the scale (Plate 6 and sphere-hole). So the
// search aims each size at the floor along the line through the two sizes
// tried nearest it (a secant; kSizeStep before there are two, and the
// whole area right after a first size that reaches the floor), first to
// bracket the largest size that reaches the floor, then inside the bracket
// (its geometric middle when the aim falls outside) until the bracket's ends
// are within kSizeTolerance of each other. Each size tried is rendered at that size
// (the PSNR is against the truecolour render there, never a resampled one)
// and searched by searchWireBudget (app/wire_budget.hpp). The first size
// tried is the scene's own, fitted to the area; from there it grows or
// shrinks by kSizeStep. When no size down to kMinSide pixels a side reaches
// the floor, the best fitting picture found is sent and the report says so.
//
// Tunables: kSizeStep, kMinStep, kSizeTolerance, kAimAbove, kMinSide.
#include <functional>
#include <string>
#include <vector>

#include "app/wire_budget.hpp"

namespace lattice::app {

// The truecolour render at a size.
using RenderAt = std::function<RgbImage(int width, int height)>;

struct SizeArea {
  int maxWidth = 0, maxHeight = 0;  // the largest picture at the camera's aspect within the device's area
  int startWidth = 0, startHeight = 0;  // the scene's own size fitted to it: the first tried
};

struct SizeTried {
  int width = 0, height = 0;
  double psnr = 0;
  bool fits = false;
};

struct WireSizeSearch {
  WireSearch search;            // at the size chosen
  std::vector<SizeTried> tried;  // in the order tried
  bool reachedFloor = false;
  double floor = 0;
  double seconds = 0;  // the whole search's wall time, renders included
};

// The largest picture of `area` at the camera's aspect: the scene's
// width x height scaled to fit deviceWidth x deviceHeight.
SizeArea sizeAreaFor(int sceneWidth, int sceneHeight, int deviceWidth, int deviceHeight);

WireSizeSearch searchWireSize(const RenderAt& renderAt, const SizeArea& area, double floorDb,
                              const devices::Device& device, const WireBudget& budget,
                              const quantize::QuantizeOptions& quantizer, bool progress);

// One line for the user: the size chosen, the floor, the sizes tried.
std::string describeWireSize(const WireSizeSearch& search, const SizeArea& area);

}  // namespace lattice::app
