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

}  // namespace

ImageDifference compare_images(const Image& a, const Image& b) {
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
  return d;
}

}  // namespace mbk
