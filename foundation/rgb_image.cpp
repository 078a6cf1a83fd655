#include "foundation/rgb_image.hpp"

namespace lattice {

RgbImage toRgbImage(const IndexedImage& img) {
  RgbImage out;
  out.width = img.width;
  out.height = img.height;
  out.rgb = img.toRgb();
  return out;
}

}  // namespace lattice
