// Band-by-band radiance on a lat-long grid (see band_radiance_grid.h).
#include "libbake/eval/band_radiance_grid.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "libbake/core/parallel.h"
#include "libbake/core/sh_basis.h"
#include "libbake/eval/sh_lighting.h"

namespace mbk {

BandRadianceGrid::BandRadianceGrid(const std::vector<Vec3>& light_sh)
    : order_(int(std::lround(std::sqrt(double(light_sh.size())))) - 1) {
  rows_ = 4 * std::max(order_, 1) + 1;
  columns_ = 2 * (rows_ - 1);
  const size_t bands = size_t(order_) + 1, per_node = bands * 3;
  bands_.resize(size_t(rows_) * columns_ * per_node);
  const ShBasisEvaluator basis(order_);
  parallel_for(0, rows_, [&](int64_t row) {
    std::vector<double> y(size_t(basis.count()));
    const double theta = std::numbers::pi * double(row) / (rows_ - 1);
    for (int i = 0; i < columns_; ++i) {
      basis.evaluate(lat_long_direction(2.0 * std::numbers::pi * i / columns_, theta), y);
      float* node = bands_.data() + (size_t(row) * columns_ + i) * per_node;
      for (int l = 0; l <= order_; ++l) {
        Vec3 sum = Vec3::Zero();
        for (int m = -l; m <= l; ++m) sum += y[size_t(sh_index(l, m))] * light_sh[size_t(sh_index(l, m))];
        for (int c = 0; c < 3; ++c) node[size_t(l) * 3 + size_t(c)] = float(sum[c]);
      }
    }
  });
}

Vec3 BandRadianceGrid::lobe_radiance(const Vec3& r, std::span<const double> lambda) const {
  const Vec2 angles = lat_long_angles(r);
  const double phi = angles.x(), theta = angles.y();
  const double y = theta / std::numbers::pi * (rows_ - 1), x = phi / (2.0 * std::numbers::pi) * columns_;
  const int row0 = std::min(int(y), rows_ - 2), column0 = int(x) % columns_;
  const double ty = y - row0, tx = x - std::floor(x);
  const int column1 = (column0 + 1) % columns_;
  const size_t bands = size_t(order_) + 1, per_node = bands * 3;
  const float* taps[4] = {bands_.data() + (size_t(row0) * columns_ + column0) * per_node,
                          bands_.data() + (size_t(row0) * columns_ + column1) * per_node,
                          bands_.data() + (size_t(row0 + 1) * columns_ + column0) * per_node,
                          bands_.data() + (size_t(row0 + 1) * columns_ + column1) * per_node};
  const double weights[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
  Vec3 out = Vec3::Zero();
  for (int t = 0; t < 4; ++t) {
    Vec3 sum = Vec3::Zero();
    for (size_t l = 0; l < bands; ++l) sum += lambda[l] * Vec3(taps[t][3 * l], taps[t][3 * l + 1], taps[t][3 * l + 2]);
    out += weights[t] * sum;
  }
  return out;
}

}  // namespace mbk
