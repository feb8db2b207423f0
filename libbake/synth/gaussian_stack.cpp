// Gaussian stacks of exemplars (see gaussian_stack.h).
#include "libbake/synth/gaussian_stack.h"

#include <cmath>

#include "formats/error.h"

namespace mbk {
namespace {

// The Gaussian of standard deviation sigma folded onto a circle of m taps, normalised to sum 1.
std::vector<double> folded_gaussian(double sigma, uint32_t m) {
  std::vector<double> w(m, 0.0);
  const int64_t reach = int64_t(std::ceil(6.0 * sigma));
  double sum = 0.0;
  for (int64_t d = -reach; d <= reach; ++d) {
    const double g = std::exp(-0.5 * double(d * d) / (sigma * sigma));
    w[size_t(((d % int64_t(m)) + m) % m)] += g;
    sum += g;
  }
  for (double& x : w) x /= sum;
  return w;
}

// Circular convolution along x (horizontal) or rows (vertical) with the folded kernel w.
Image convolve(const Image& in, const std::vector<double>& w, bool horizontal) {
  Image out = in;
  const uint32_t m = in.width, ch = in.channels;
  std::vector<double> acc(ch);
  for (uint32_t row = 0; row < m; ++row)
    for (uint32_t x = 0; x < m; ++x) {
      std::fill(acc.begin(), acc.end(), 0.0);
      for (uint32_t d = 0; d < m; ++d) {
        if (w[d] == 0.0) continue;
        const uint32_t sx = horizontal ? (x + m - d) % m : x, sr = horizontal ? row : (row + m - d) % m;
        for (uint32_t c = 0; c < ch; ++c) acc[c] += w[d] * in.at(sx, sr, c);
      }
      for (uint32_t c = 0; c < ch; ++c) out.at(x, row, c) = float(acc[c]);
    }
  return out;
}

}  // namespace

int exact_log2(uint32_t v) {
  if (v == 0 || (v & (v - 1)) != 0) return -1;
  int l = 0;
  while ((1u << l) < v) ++l;
  return l;
}

GaussianStack build_gaussian_stack(const Image& exemplar) {
  const int L = exact_log2(exemplar.width);
  if (L < 0 || exemplar.width != exemplar.height)
    throw Error(ExitCode::runtime_failure, "internal: Gaussian stacks need a square power-of-two exemplar");
  GaussianStack s;
  s.levels = uint32_t(L) + 1;
  s.images.resize(s.levels);
  s.images[L] = exemplar;
  for (int k = 0; k < L; ++k) {
    const std::vector<double> w = folded_gaussian(std::ldexp(1.0, L - k - 1), exemplar.width);
    s.images[k] = convolve(convolve(exemplar, w, true), w, false);
  }
  return s;
}

}  // namespace mbk
