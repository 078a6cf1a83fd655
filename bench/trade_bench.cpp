// trade_bench REF.png TEST.png
//
// The image-error half of the speed-for-accuracy benchmark (bench/trade.sh):
// prints one line "psnr_db max_error ssim" comparing TEST against REF (the
// double-precision full ray trace).
//   psnr_db    10 log10(255^2 / MSE) over all R, G, B samples; "inf" when equal
//   max_error  the largest |difference| of one 8-bit sample (0..255)
//   ssim       mean structural similarity of the luma (Wang, Bovik, Sheikh and
//              Simoncelli, "Image quality assessment: from error visibility to
//              structural similarity", IEEE Trans. Image Processing 13(4), 2004):
//              io/ssim.hpp; 1 means identical.
//
// PSNR and max error answer "how far off is each sample"; SSIM answers "does
// the structure (edges, texture) survive", which is what dithering and a
// coarse lattice change in different ways, so the table reports all three.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "io/png.hpp"
#include "io/ssim.hpp"
#include "foundation/error.hpp"

namespace {

using lattice::Error;
using lattice::ErrorKind;
using lattice::RgbImage;

int run(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() != 2)
    throw Error(ErrorKind::Usage, "usage: trade_bench REF.png TEST.png  (prints: psnr_db max_error ssim)");
  const RgbImage ref = lattice::io::readPng(args[0]);
  const RgbImage test = lattice::io::readPng(args[1]);
  if (test.width != ref.width || test.height != ref.height)
    throw Error(ErrorKind::Input, fmt::format("{} is {}x{} but the reference {} is {}x{}; render both at one size",
                                              args[1], test.width, test.height, args[0], ref.width, ref.height));
  double squares = 0.0;
  int maxError = 0;
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const int d = std::abs(int(ref.pixel(x, y)[c]) - int(test.pixel(x, y)[c]));
        squares += double(d) * double(d);
        maxError = std::max(maxError, d);
      }
  const double mse = squares / (3.0 * double(ref.width) * double(ref.height));
  const std::string psnr = mse == 0.0 ? "inf" : fmt::format("{:.2f}", 10.0 * std::log10(255.0 * 255.0 / mse));
  const double ssim = lattice::io::meanSsim(ref, test);
  fmt::print("{} {} {:.4f}\n", psnr, maxError, ssim);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    fmt::print(stderr, "trade_bench: {}\n", e.what());
    return 1;
  }
}
