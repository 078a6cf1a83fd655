#pragma once
// Mean structural similarity of two pictures' luma (Wang, Bovik, Sheikh and
// Simoncelli, "Image quality assessment: from error visibility to structural
// similarity", IEEE Trans. Image Processing 13(4), 2004). Method: Rec. 601
// luma, statistics under an 11x11 Gaussian window (sigma 1.5) taken only
// where the whole window fits, K1 = 0.01, K2 = 0.03, L = 255, as the paper
// recommends; 1 means identical. PSNR answers "how far off is each sample",
// SSIM "does the structure survive", which dithering and coarse runs change
// in different ways, so reports quote both.
#include "foundation/rgb_image.hpp"

namespace lattice::io {

// Same size, at least 11x11 (Error(Input) otherwise, naming the sizes).
double meanSsim(const RgbImage& a, const RgbImage& b);

}  // namespace lattice::io
