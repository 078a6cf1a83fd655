#pragma once
// A time budget on the wire: the most accurate picture whose stream fits
// (`lattice render --wire-seconds S [--baud B]` or `--wire-bytes N`).
//
// Method: the truecolour picture is rendered once and kept. A setting is a
// palette size (256 down to 2, at most what the device shows) and a
// dithering (none, Floyd-Steinberg): the picture is quantized, and the
// device's real driver encodes it into a byte counter (never a model of the
// encoder). A picture that does not fit at lambda = 0 gets rate-distortion
// runs (quantize/rate_distortion_runs.hpp, error measured against the
// truecolour picture) at the smallest lambda that fits (app/wire_lambda.hpp).
// Of all fitting pictures the one with the highest PSNR against the
// truecolour picture wins (fewer bytes break ties).
//
// Coarse to fine, because each lambda tried is a dynamic programme over the
// whole picture and searching all 24 settings so took 8-20 s for Plate 6:
// settings are first ranked on a proxy, every kProxyRowStep-th row of the
// picture (the programme works row by row, so a quarter of the rows is a
// quarter of the work) against the limit scaled by the ratio of the two
// lossless streams, walking palette sizes from 64 towards the better
// neighbour while the score rises; then the best kFullSettings settings are
// searched on the whole picture, each from its proxy's lambda. Pruning,
// sound: no picture in a palette is nearer the truecolour one than each
// pixel at its nearest entry, so a setting whose bound is no better than a
// fitting choice is not searched. `exhaustive` searches every setting on
// the whole picture instead, to measure what the proxy loses
// (tests/app/wire_budget_test.cpp, bench/wire-search.sh). The device's
// wireSettings (forms that draw the same screen in fewer bytes, off by
// default) are the caller's to turn on (wireSettingsToAdd). With `shrink`,
// when nothing fits, the picture is made smaller (each side x0.8,
// area-averaged) and the search runs again.
//
// Tunables (wire_budget.cpp): the palette sizes, kProxyRowStep,
// kWalkStartColours, kFullSettings, kShrinkSteps.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "devices/device.hpp"
#include "foundation/indexed_image.hpp"
#include "foundation/rgb_image.hpp"
#include "quantize/quantize_options.hpp"

namespace lattice::app {

struct WireBudget {
  std::optional<std::uint64_t> bytes;  // --wire-bytes
  std::optional<double> seconds;       // --wire-seconds, at `baud`
  int baud = 0;                        // 0: the device profile's line rate
  bool shrink = false;                 // --wire-shrink: smaller pictures when nothing fits
  double quality = 30;                 // --wire-quality: the PSNR floor of the size search (app/wire_size.hpp)
  bool exhaustive = false;             // every setting searched at full size: what the coarse-to-fine search is measured against
};

struct WireChoice {
  int colors = 0;
  quantize::Dither dither = quantize::Dither::None;
  double lambda = 0;
  int width = 0, height = 0;
  std::uint64_t bytes = 0;
  double seconds = 0;  // at the budget's line
  double psnr = 0;     // the picture sent (its palette colours) against the truecolour one, dB
  double ssim = 0;
  bool fits = false;
};

struct WireSearch {
  IndexedImage picture;  // what to send
  RgbImage reference;    // the truecolour picture at the size sent
  WireChoice choice;     // the winner, or (nothing fits) the smallest stream
  std::uint64_t limit = 0;
  int baud = 0;
  int encodings = 0;       // real encodings of whole pictures
  int proxyEncodings = 0;  // and of the proxy's rows (app/wire_budget.cpp)
  double seconds = 0;  // the search's wall time
  std::vector<std::string> settings;  // profile settings the budget turned on (Device::wireSettings)
};

// The device's wireSettings whose keys the user's settings do not name.
std::vector<std::string> wireSettingsToAdd(const devices::Device& device, const std::vector<std::string>& user);

// Throws Error(Usage) when the device has no serial line and no --baud, or
// (with lambdas to try) no run costs.
WireSearch searchWireBudget(const RgbImage& truecolour, const devices::Device& device, const WireBudget& budget,
                            const quantize::QuantizeOptions& quantizer, bool progress);

// The picture into a sink: begin, every row, end.
void sendPicture(const IndexedImage& picture, IndexedSink& sink);

// One line for the user: settings, bytes, seconds at the baud, PSNR, SSIM.
std::string describeWireChoice(const WireSearch& search);

}  // namespace lattice::app
