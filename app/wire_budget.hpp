#pragma once
// A time budget on the wire: the most accurate picture whose stream fits
// (`lattice render --wire-seconds S [--baud B]` or `--wire-bytes N`).
//
// Method: the truecolour picture is rendered once and kept; for each palette
// size (the device's largest down to 2) and dithering (none,
// Floyd-Steinberg) it is quantized, and the device's real driver encodes it
// into a byte counter (never a model of the encoder). A picture that does
// not fit at lambda = 0 is tried with rate-distortion runs
// (quantize/rate_distortion_runs.hpp, error measured against the truecolour
// picture) at the smallest lambda of a doubling ladder that fits, found by
// bisection (bytes fall as lambda grows) and refined between the rungs. Of
// all fitting pictures the one with the highest PSNR against the truecolour
// picture wins (fewer bytes break ties). Pruning, sound for dithered and
// smoothed pictures alike: no picture in a palette is nearer the truecolour
// one than each pixel at its nearest entry, so once a fitting choice is
// found, a setting whose palette's bound is no better is not tried. (Before,
// a setting whose lossless PSNR was below the best was dropped, which missed
// dithered pictures that runs make more accurate.) The device's
// wireSettings (forms that draw the same screen in fewer bytes, off by
// default) are the caller's to turn on (wireSettingsToAdd). With `shrink`,
// when nothing fits, the picture is made smaller (each side x0.8,
// area-averaged) and the search runs again.
//
// Tunables: kLadderSteps (50 x 2^k squared-error units a byte), kRefineSteps
// (bisections between rungs), the palette sizes tried, kShrinkSteps.
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
  bool prune = true;                   // false: every setting searched (tests check the pruning loses nothing)
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
  int encodings = 0;  // real encodes counted
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
