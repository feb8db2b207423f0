// Error metrics between two images of the same size and channel count, B being the reference:
//   MSE           mean over all pixels and channels of (a - b)^2;   RMSE = sqrt(MSE)
//   relative MSE  mean of (a - b)^2 / (b^2 + 0.01): errors relative to the reference's value, the 0.01
//                 keeping black reference pixels from dominating (Rousselle et al. 2011's relMSE)
//   PSNR          10 log10(peak^2 / MSE) dB with peak = 1, the display white of the tone-mapped PNG
//                 and of 8/16-bit files (linear radiance 1 for EXR renders); +infinity when MSE = 0
//   block L1      sum |mean_A - mean_B| / sum |mean_B| over the means of N x N pixel blocks (the last row and
//                 column of blocks may be smaller) and channels: how far A's local brightness is from B's once
//                 per-pixel noise and sparkle positions inside a block are averaged out (glints are judged on
//                 8 x 8 blocks); 0 when both are 0, +infinity when only B is 0
// Values are compared as the files store them: linear for EXR, display-encoded for PNG.
#pragma once

#include <cstdint>

#include "libbake/image/image_io.h"

namespace mbk {

struct ImageDifference {
  double mse = 0, rmse = 0, relative_mse = 0, psnr_db = 0, max_abs = 0;
  uint32_t block = 8;  // block side of block_relative_l1
  double block_relative_l1 = 0;
  uint64_t values = 0;  // pixels x channels compared
};

// Error(invalid_input) when sizes or channel counts differ or a value is not finite (naming it).
// `block` >= 1 is the side of block_relative_l1's blocks.
ImageDifference compare_images(const Image& a, const Image& reference, uint32_t block = 8);

}  // namespace mbk
