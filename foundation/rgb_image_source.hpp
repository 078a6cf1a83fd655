#pragma once
// A RowSource18 over a truecolour image: each 8-bit channel is rounded to the
// nearest of 64 levels, the precision the thesis's *model* produced, so PNG
// input goes through exactly the path a rendered picture takes.
#include "foundation/rgb_image.hpp"
#include "foundation/scanline.hpp"

namespace lattice {

class RgbImageSource final : public RowSource18 {
 public:
  // Keeps a reference: the image must outlive the source.
  explicit RgbImageSource(const RgbImage& image);
  int width() const override { return image_.width; }
  int height() const override { return image_.height; }
  void row(int y, std::span<Color18> out) override;

 private:
  const RgbImage& image_;
};

}  // namespace lattice
