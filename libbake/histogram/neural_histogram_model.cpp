// Pyramid lookups and predictions of the neural histogram (see neural_histogram_model.h).
#include "libbake/histogram/neural_histogram_model.h"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>

#include "libbake/histogram/histogram_mlp.h"

namespace mbk {
namespace {

int64_t wrap(int64_t i, int64_t n) { return ((i % n) + n) % n; }

}  // namespace

PyramidGrid neural_pyramid_grid(const NeuralHistogramShape& shape) {
  PyramidGrid grid;
  grid.width = shape.width;
  grid.height = shape.height;
  grid.base = kNeuralHistogramMinFootprint;
  for (uint32_t l = 0; l < shape.levels(); ++l) {
    grid.level_width.push_back(shape.level_width(l));
    grid.level_height.push_back(shape.level_height(l));
    grid.level_offset.push_back(shape.level_offset(l));
  }
  return grid;
}

PyramidLookup pyramid_lookup(const PyramidGrid& grid, double x, double y, double side) {
  PyramidLookup out;
  const double lod = std::clamp(std::log2(side / grid.base), 0.0, double(grid.levels() - 1));
  const uint32_t l0 = uint32_t(lod);
  const uint32_t l1 = std::min(l0 + 1, grid.levels() - 1);
  const double t = lod - l0;
  const uint32_t levels[2] = {l0, l1};
  const double level_weight[2] = {1.0 - t, t};
  for (int k = 0; k < 2; ++k) {
    const uint32_t l = levels[k];
    const int64_t w = grid.level_width[l], h = grid.level_height[l];
    const double u = x * double(w) / grid.width - 0.5, v = y * double(h) / grid.height - 0.5;
    const double fu = std::floor(u), fv = std::floor(v);
    const double du = u - fu, dv = v - fv;
    const int64_t c0 = wrap(int64_t(fu), w), c1 = wrap(int64_t(fu) + 1, w);
    const int64_t r0 = wrap(int64_t(fv), h), r1 = wrap(int64_t(fv) + 1, h);
    const uint64_t base = grid.level_offset[l];
    out.texel[4 * k + 0] = base + uint64_t(r0 * w + c0);
    out.texel[4 * k + 1] = base + uint64_t(r0 * w + c1);
    out.texel[4 * k + 2] = base + uint64_t(r1 * w + c0);
    out.texel[4 * k + 3] = base + uint64_t(r1 * w + c1);
    out.weight[4 * k + 0] = float(level_weight[k] * (1.0 - du) * (1.0 - dv));
    out.weight[4 * k + 1] = float(level_weight[k] * du * (1.0 - dv));
    out.weight[4 * k + 2] = float(level_weight[k] * (1.0 - du) * dv);
    out.weight[4 * k + 3] = float(level_weight[k] * du * dv);
  }
  return out;
}

NeuralHistogramModel::NeuralHistogramModel(const NeuralHistogramShape& s)
    : shape(s),
      grid(neural_pyramid_grid(s)),
      features(s.pyramid_texels() * s.features, 0.0f),
      mlp(s.mlp_parameters(), 0.0f) {}

void NeuralHistogramModel::network_input(const PyramidLookup& lookup, double side, float* input) const {
  const uint32_t F = shape.features;
  std::fill(input, input + F, 0.0f);
  for (int k = 0; k < 8; ++k) {
    const float* f = features.data() + lookup.texel[k] * F;
    for (uint32_t i = 0; i < F; ++i) input[i] += lookup.weight[k] * f[i];
  }
  input[F] = float(std::log2(side / kNeuralHistogramMinFootprint) / 8.0);
}

void NeuralHistogramModel::probabilities(double x, double y, double side, std::span<double> out) const {
  Eigen::MatrixXf input(shape.inputs(), 1);
  network_input(pyramid_lookup(grid, x, y, side), side, input.data());
  MlpPass pass;
  mlp_forward(shape.network(0), mlp.data(), input, pass);
  log_softmax_columns(pass.logits);
  const Eigen::VectorXf log_theta = pass.logits.col(0);
  const uint32_t N = shape.phi_bins;
  for (uint32_t j = 0; j < shape.theta_bins; ++j) {
    mlp_forward(shape.network(1 + j), mlp.data() + shape.network_offset(1 + j), input, pass);
    log_softmax_columns(pass.logits);
    for (uint32_t i = 0; i < N; ++i) out[j * N + i] = std::exp(double(log_theta[j]) + double(pass.logits(i, 0)));
  }
}

void NeuralHistogramModel::round_to_half() {
  for (float& v : features) v = float(Imath::half(v));
  for (float& v : mlp) v = float(Imath::half(v));
}

}  // namespace mbk
