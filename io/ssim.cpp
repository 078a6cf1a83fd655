#include "io/ssim.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <vector>

#include "foundation/error.hpp"

namespace lattice::io {
namespace {

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

double planeSsim(const Plane& a, const Plane& b) {
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

}  // namespace

double meanSsim(const RgbImage& a, const RgbImage& b) {
  if (a.width != b.width || a.height != b.height)
    throw Error(ErrorKind::Input, fmt::format("SSIM compares pictures of one size; these are {}x{} and {}x{}", a.width,
                                              a.height, b.width, b.height));
  return planeSsim(luma(a), luma(b));
}

}  // namespace lattice::io
