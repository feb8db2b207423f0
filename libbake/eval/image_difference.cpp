// Image error metrics for `compare` (see image_difference.h).
#include "libbake/eval/image_difference.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "formats/error.h"

namespace mbk {
namespace {

std::string size_text(const Image& i) {
  return std::to_string(i.width) + "x" + std::to_string(i.height) + " with " + std::to_string(i.channels) + " channels";
}

// sum over blocks and channels of |block mean of a - block mean of b| / sum of |block mean of b|.
double block_relative_l1(const Image& a, const Image& b, uint32_t block) {
  double diff = 0, ref = 0;
  for (uint32_t by = 0; by < a.height; by += block)
    for (uint32_t bx = 0; bx < a.width; bx += block)
      for (uint32_t c = 0; c < a.channels; ++c) {
        double sa = 0, sb = 0;
        const uint32_t y1 = std::min(a.height, by + block), x1 = std::min(a.width, bx + block);
        for (uint32_t y = by; y < y1; ++y)
          for (uint32_t x = bx; x < x1; ++x) {
            const size_t i = (size_t(y) * a.width + x) * a.channels + c;
            sa += a.pixels[i], sb += b.pixels[i];
          }
        const double n = double(y1 - by) * double(x1 - bx);
        diff += std::abs(sa - sb) / n;
        ref += std::abs(sb) / n;
      }
  if (ref > 0) return diff / ref;
  return diff > 0 ? std::numeric_limits<double>::infinity() : 0.0;
}

}  // namespace

ImageDifference compare_images(const Image& a, const Image& b, uint32_t block) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels)
    throw Error(ExitCode::invalid_input, "images differ in size: " + size_text(a) + " vs " + size_text(b));
  ImageDifference d;
  d.values = a.pixels.size();
  if (d.values == 0) throw Error(ExitCode::invalid_input, "empty images");
  double sum_sq = 0, sum_rel = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) {
    const double x = a.pixels[i], y = b.pixels[i];
    if (!std::isfinite(x) || !std::isfinite(y)) {
      const size_t pixel = i / a.channels;
      throw Error(ExitCode::invalid_input, std::string("non-finite value in image ") + (std::isfinite(x) ? "B" : "A"),
                  "pixel (" + std::to_string(pixel % a.width) + ", " + std::to_string(pixel / a.width) + ")");
    }
    const double e = x - y;
    sum_sq += e * e;
    sum_rel += e * e / (y * y + 0.01);
    d.max_abs = std::max(d.max_abs, std::abs(e));
  }
  d.mse = sum_sq / double(d.values);
  d.rmse = std::sqrt(d.mse);
  d.relative_mse = sum_rel / double(d.values);
  d.psnr_db = d.mse > 0 ? 10.0 * std::log10(1.0 / d.mse) : std::numeric_limits<double>::infinity();
  if (block == 0) throw Error(ExitCode::runtime_failure, "internal: block side 0");
  d.block = block;
  d.block_relative_l1 = block_relative_l1(a, b, block);
  return d;
}

}  // namespace mbk
