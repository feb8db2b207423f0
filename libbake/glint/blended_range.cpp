// The range query of the blended microstructure ([Wang20] Sec. 4.3-4.5): see blended_range.h.
#include "libbake/glint/blended_range.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "formats/error.h"

namespace mbk {
namespace {

// Bilinear weight of corner k at local coordinates f (target_patch_grid.h).
double corner_weight(int k, double f0, double f1) { return ((k & 1) ? f0 : 1.0 - f0) * ((k >> 1) ? f1 : 1.0 - f1); }

// Extremes over the box of the bilinear sum_k w_k(f) c_k: at the box's four corners.
std::array<double, 2> bilinear_extremes(const Vec2& f_lo, const Vec2& f_hi, const std::array<double, 4>& c) {
  double lo = INFINITY, hi = -INFINITY;
  for (const double f0 : {f_lo.x(), f_hi.x()})
    for (const double f1 : {f_lo.y(), f_hi.y()}) {
      double v = 0.0;
      for (int k = 0; k < 4; ++k) v += corner_weight(k, f0, f1) * c[k];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  return {lo, hi};
}

// q(t) = (1 - t)^2 + t^2, so that ||w||_2^2 = q(f_0) q(f_1).
double q(double t) { return (1.0 - t) * (1.0 - t) + t * t; }

struct WeightNormRange {
  double min, max;
};
WeightNormRange weight_norm_range(const Vec2& f_lo, const Vec2& f_hi) {
  double q_min = 1.0, q_max = 1.0;
  for (int a = 0; a < 2; ++a) {
    q_min *= q(std::clamp(0.5, f_lo[a], f_hi[a]));
    q_max *= std::max(q(f_lo[a]), q(f_hi[a]));
  }
  return {std::sqrt(q_min), std::sqrt(q_max)};
}

// Bounds of m + N / W for N in [n_lo, n_hi], W in [w.min, w.max] (W > 0).
std::array<double, 2> divide_bounds(double m, double n_lo, double n_hi, const WeightNormRange& w) {
  return {m + n_lo / (n_lo >= 0.0 ? w.max : w.min), m + n_hi / (n_hi >= 0.0 ? w.min : w.max)};
}

// blend_range_bounds with the corners already in blend space (histogram: G of the leaf bounds), so that a caller
// holding G of every code (GlintRangeQuery) skips the forward lookups.
RmqBounds blend_bounds_in_blend_space(GlintBlendMode mode, const Vec2& f_lo, const Vec2& f_hi,
                                      const std::array<RmqBounds, 4>& corner, const Vec2& mean,
                                      const StandardizationLut* lut) {
  std::array<double, 4> out{};  // min_x, max_x, min_y, max_y
  for (int ch = 0; ch < 2; ++ch) {
    std::array<double, 4> lo, hi;
    for (int k = 0; k < 4; ++k) {
      lo[k] = ch == 0 ? corner[k].min_x : corner[k].min_y;
      hi[k] = ch == 0 ? corner[k].max_x : corner[k].max_y;
    }
    double b_lo = 0.0, b_hi = 0.0;
    if (mode == GlintBlendMode::none) {
      b_lo = INFINITY, b_hi = -INFINITY;
      for (int k = 0; k < 4; ++k) {
        const bool reachable0 = (k & 1) ? f_hi.x() >= 0.5 : f_lo.x() < 0.5;
        const bool reachable1 = (k >> 1) ? f_hi.y() >= 0.5 : f_lo.y() < 0.5;
        if (!(reachable0 && reachable1)) continue;
        b_lo = std::min(b_lo, lo[k]);
        b_hi = std::max(b_hi, hi[k]);
      }
    } else if (mode == GlintBlendMode::linear) {
      b_lo = bilinear_extremes(f_lo, f_hi, lo)[0];
      b_hi = bilinear_extremes(f_lo, f_hi, hi)[1];
    } else {
      const bool histogram = mode == GlintBlendMode::histogram;
      const double m = histogram ? 0.0 : mean[ch];
      for (int k = 0; k < 4; ++k) lo[k] -= m, hi[k] -= m;
      const WeightNormRange w = weight_norm_range(f_lo, f_hi);
      b_lo = divide_bounds(m, bilinear_extremes(f_lo, f_hi, lo)[0], 0.0, w)[0];
      b_hi = divide_bounds(m, 0.0, bilinear_extremes(f_lo, f_hi, hi)[1], w)[1];
      if (histogram) {
        b_lo = lut->channels[ch].destandardize(b_lo).value;
        b_hi = lut->channels[ch].destandardize(b_hi).value;
      }
    }
    out[2 * ch] = b_lo - kGlintRangeRoundingMargin;
    out[2 * ch + 1] = b_hi + kGlintRangeRoundingMargin;
  }
  return {out[0], out[1], out[2], out[3]};
}

}  // namespace

RmqBounds blend_range_bounds(GlintBlendMode mode, const Vec2& f_lo, const Vec2& f_hi,
                             const std::array<RmqBounds, 4>& corner, const Vec2& mean, const StandardizationLut* lut) {
  if (mode != GlintBlendMode::histogram) return blend_bounds_in_blend_space(mode, f_lo, f_hi, corner, mean, lut);
  std::array<RmqBounds, 4> standardized;
  const StandardizationChannelTables* c = lut->channels.data();
  for (int k = 0; k < 4; ++k) {
    standardized[k] = {c[0].standardize(corner[k].min_x).value, c[0].standardize(corner[k].max_x).value,
                       c[1].standardize(corner[k].min_y).value, c[1].standardize(corner[k].max_y).value};
  }
  return blend_bounds_in_blend_space(mode, f_lo, f_hi, standardized, mean, lut);
}

GlintRangeQuery::GlintRangeQuery(const GlintPointQuery& point, const RmqTableView& rmq)
    : point_(&point), rmq_(&rmq), side_(point.grid().patch_side() / 2) {
  if (point.grid().patch_side() % 2 != 0)
    throw Error(ExitCode::invalid_input,
                "glint range queries need an even patch side, got " + std::to_string(point.grid().patch_side()),
                "range query");
  if (rmq.layout().width != point.example().width || rmq.layout().height != point.example().height)
    throw Error(ExitCode::invalid_input,
                "rmq table is for a " + std::to_string(rmq.layout().width) + "x" + std::to_string(rmq.layout().height) +
                    " example, the point query's example is " + std::to_string(point.example().width) + "x" +
                    std::to_string(point.example().height),
                "range query");
  if (point.mode() == GlintBlendMode::histogram) {  // G of every code's value, read by corner_bounds
    const uint32_t codes = rmq_code_max(rmq.layout().bits) + 1;
    for (int ch = 0; ch < 2; ++ch) {
      const RmqQuantizer q(rmq.range()[size_t(ch)], rmq.layout().bits);
      gaussian_of_code_[size_t(ch)].resize(codes);
      for (uint32_t c = 0; c < codes; ++c)
        gaussian_of_code_[size_t(ch)][c] = point.lut()->channels[size_t(ch)].standardize(q.value(c)).value;
    }
  }
}

RmqBounds GlintRangeQuery::corner_bounds(const RmqCodes& c) const {
  if (gaussian_of_code_[0].empty()) return rmq_->dequantize(c);
  return {gaussian_of_code_[0][c.min_x], gaussian_of_code_[0][c.max_x], gaussian_of_code_[1][c.min_y],
          gaussian_of_code_[1][c.max_y]};
}

RmqBounds GlintRangeQuery::blend(const Vec2& f_lo, const Vec2& f_hi, const std::array<RmqBounds, 4>& corner) const {
  return blend_bounds_in_blend_space(point_->mode(), f_lo, f_hi, corner, point_->example_mean(), point_->lut());
}

std::array<uint32_t, 2> GlintRangeQuery::example_texel(int64_t patch_i, int64_t patch_j, int corner, uint32_t x,
                                                       uint32_t y) const {
  const int dx = corner & 1, dy = corner >> 1;
  const std::array<uint32_t, 2> origin = point_->grid().patch_origin(patch_i + dx, patch_j + dy);
  return {origin[0] + x + uint32_t(1 - dx) * side_, origin[1] + y + uint32_t(1 - dy) * side_};
}

RmqBounds GlintRangeQuery::node_bounds(const TargetNode& node, uint32_t* lookups) const {
  std::array<RmqBounds, 4> corner;
  uint32_t total = 0;
  for (int k = 0; k < 4; ++k) {
    const std::array<uint32_t, 2> e = example_texel(node.patch_i, node.patch_j, k, node.x0, node.y0);
    uint32_t count = 0;
    corner[k] = corner_bounds(rmq_->query_codes(e[0], e[1], node.width, node.height, &count));
    total += count;
  }
  if (lookups) *lookups = total;
  const double h = side_;
  const Vec2 f_lo((node.x0 + 0.5) / h, (node.y0 + 0.5) / h);
  const Vec2 f_hi((node.x0 + node.width - 0.5) / h, (node.y0 + node.height - 0.5) / h);
  return blend(f_lo, f_hi, corner);
}

RmqBounds GlintRangeQuery::element_bounds(int64_t t0, int64_t t1) const {
  const int64_t h = side_;
  const int64_t i = t0 >= 0 ? t0 / h : -((-t0 - 1) / h) - 1;  // floor division
  const int64_t j = t1 >= 0 ? t1 / h : -((-t1 - 1) / h) - 1;
  const auto x = uint32_t(t0 - i * h), y = uint32_t(t1 - j * h);
  std::array<RmqBounds, 4> corner;
  for (int k = 0; k < 4; ++k) {
    const std::array<uint32_t, 2> e = example_texel(i, j, k, x, y);
    corner[k] = corner_bounds(rmq_->entry(0, e[0], e[1]));
  }
  const Vec2 f((x + 0.5) / double(h), (y + 0.5) / double(h));
  return blend(f, f, corner);
}

}  // namespace mbk
