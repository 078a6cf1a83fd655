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
//              11x11 Gaussian window, sigma 1.5, K1 = 0.01, K2 = 0.03, L = 255,
//              as the paper recommends; 1 means identical.
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
#include "foundation/error.hpp"

namespace {

using lattice::Error;
using lattice::ErrorKind;
using lattice::RgbImage;

struct Plane {
  int width = 0;
  int height = 0;
  std::vector<double> v;
  double& at(int x, int y) { return v[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)]; }
  double at(int x, int y) const { return v[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)]; }
};

// Rec. 601 luma, the weighting the SSIM paper's grey-scale images carry.
Plane luma(const RgbImage& image) {
  const int width = image.width, height = image.height;
  Plane p{width, height, std::vector<double>(static_cast<std::size_t>(width) * static_cast<std::size_t>(height))};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::uint8_t* c = image.pixel(x, y);
      p.at(x, y) = 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2];
    }
  return p;
}

// Gaussian blur restricted to "valid" positions (the window entirely inside
// the image), separable: the paper's statistics are taken only where the
// whole window fits, so the output is (w-10) x (h-10).
constexpr int kRadius = 5;
constexpr double kSigma = 1.5;

std::array<double, 2 * kRadius + 1> gaussianWeights() {
  std::array<double, 2 * kRadius + 1> w{};
  double sum = 0.0;
  for (int i = -kRadius; i <= kRadius; ++i) {
    w[static_cast<std::size_t>(i + kRadius)] = std::exp(-double(i * i) / (2.0 * kSigma * kSigma));
    sum += w[static_cast<std::size_t>(i + kRadius)];
  }
  for (double& x : w) x /= sum;
  return w;
}

Plane blurValid(const Plane& in) {
  static const auto w = gaussianWeights();
  const int ow = in.width - 2 * kRadius, oh = in.height - 2 * kRadius;
  Plane rows{ow, in.height, std::vector<double>(static_cast<std::size_t>(ow) * static_cast<std::size_t>(in.height))};
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      for (int k = 0; k <= 2 * kRadius; ++k) s += w[static_cast<std::size_t>(k)] * in.at(x + k, y);
      rows.at(x, y) = s;
    }
  Plane out{ow, oh, std::vector<double>(static_cast<std::size_t>(ow) * static_cast<std::size_t>(oh))};
  for (int y = 0; y < oh; ++y)
    for (int x = 0; x < ow; ++x) {
      double s = 0.0;
      for (int k = 0; k <= 2 * kRadius; ++k) s += w[static_cast<std::size_t>(k)] * rows.at(x, y + k);
      out.at(x, y) = s;
    }
  return out;
}

Plane product(const Plane& a, const Plane& b) {
  Plane p = a;
  for (std::size_t i = 0; i < p.v.size(); ++i) p.v[i] = a.v[i] * b.v[i];
  return p;
}

double meanSsim(const Plane& a, const Plane& b) {
  if (a.width <= 2 * kRadius || a.height <= 2 * kRadius)
    throw Error(ErrorKind::Input, fmt::format("SSIM needs images of at least {0}x{0} pixels; these are {1}x{2}",
                                              2 * kRadius + 1, a.width, a.height));
  constexpr double L = 255.0, C1 = (0.01 * L) * (0.01 * L), C2 = (0.03 * L) * (0.03 * L);
  const Plane muA = blurValid(a), muB = blurValid(b);
  const Plane aa = blurValid(product(a, a)), bb = blurValid(product(b, b)), ab = blurValid(product(a, b));
  double sum = 0.0;
  for (std::size_t i = 0; i < muA.v.size(); ++i) {
    const double ma = muA.v[i], mb = muB.v[i];
    const double va = aa.v[i] - ma * ma, vb = bb.v[i] - mb * mb, cov = ab.v[i] - ma * mb;
    sum += ((2 * ma * mb + C1) * (2 * cov + C2)) / ((ma * ma + mb * mb + C1) * (va + vb + C2));
  }
  return sum / double(muA.v.size());
}

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
  const double ssim = meanSsim(luma(ref), luma(test));
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
