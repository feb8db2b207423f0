// Statistics that tell a texture from flat plateaus and seams (issue 18), for tests of multiscale synthesis:
//   - block variance: a 16 x 16-pixel block's normal variance, the mean over its pixels of |n - mean n|^2 (summed over
//     the channels);
//   - plateau fraction: the blocks whose variance is under 10% of a reference (the exemplar's median block
//     variance);
//   - block-column contrast: the largest ratio between the median block variances of two neighbouring block
//     columns (or rows): a window whose left half is flat and right half a texture has a straight regime boundary
//     and a large ratio, a stationary texture a ratio near 1;
//   - step outlier: the largest mean squared step across one pixel column (or row) line, over the median of all
//     such lines: a seam where two regions meet without blending is a line of large steps;
//   - octave spectrum: the power of the window's periodic DFT in octave bands of spatial frequency (cycles per
//     pixel: [1/2^(j+1), 1/2^j) for j = 1, 2, ...; band 0 holds [1/4, 1/2] and the corner frequencies).
// Everything in double, serially: deterministic.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "libbake/image/image_io.h"

namespace mbk::test {

inline constexpr uint32_t kStatisticsBlock = 16;

// Variances of the aligned 16 x 16 blocks, row-major (blocks across = width / 16).
inline std::vector<double> block_variances(const Image& im, uint32_t block = kStatisticsBlock) {
  std::vector<double> out;
  const uint32_t C = im.channels;
  for (uint32_t by = 0; by + block <= im.height; by += block)
    for (uint32_t bx = 0; bx + block <= im.width; bx += block) {
      double var = 0.0;
      for (uint32_t c = 0; c < C; ++c) {
        double mean = 0.0, sq = 0.0;
        for (uint32_t y = by; y < by + block; ++y)
          for (uint32_t x = bx; x < bx + block; ++x) mean += im.at(x, y, c);
        mean /= double(block) * block;
        for (uint32_t y = by; y < by + block; ++y)
          for (uint32_t x = bx; x < bx + block; ++x) sq += (im.at(x, y, c) - mean) * (im.at(x, y, c) - mean);
        var += sq / (double(block) * block);
      }
      out.push_back(var);
    }
  return out;
}

inline double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

inline double plateau_fraction(const std::vector<double>& blocks, double reference_median) {
  size_t flat = 0;
  for (double v : blocks) flat += v < 0.1 * reference_median;
  return blocks.empty() ? 0.0 : double(flat) / double(blocks.size());
}

// The whole window's variance (summed over channels).
inline double window_variance(const Image& im) { return block_variances(im, std::min(im.width, im.height))[0]; }

// Largest ratio (>= 1) between the median block variances of neighbouring block columns, and of neighbouring block
// rows.
inline double block_line_contrast(const Image& im, uint32_t block = kStatisticsBlock) {
  const std::vector<double> v = block_variances(im, block);
  const uint32_t across = im.width / block, down = im.height / block;
  const auto line = [&](uint32_t i, bool column) {
    std::vector<double> l;
    for (uint32_t j = 0; j < (column ? down : across); ++j) l.push_back(column ? v[j * across + i] : v[i * across + j]);
    return std::max(median_of(l), 1e-30);
  };
  double worst = 1.0;
  for (uint32_t i = 0; i + 1 < across; ++i) {
    const double a = line(i, true), b = line(i + 1, true);
    worst = std::max(worst, std::max(a / b, b / a));
  }
  for (uint32_t i = 0; i + 1 < down; ++i) {
    const double a = line(i, false), b = line(i + 1, false);
    worst = std::max(worst, std::max(a / b, b / a));
  }
  return worst;
}

// The largest mean squared step across a vertical or horizontal pixel line, over the median of those lines.
inline double step_line_outlier(const Image& im) {
  const uint32_t C = im.channels;
  std::vector<double> columns, rows;
  for (uint32_t x = 0; x + 1 < im.width; ++x) {
    double s = 0.0;
    for (uint32_t y = 0; y < im.height; ++y)
      for (uint32_t c = 0; c < C; ++c) s += std::pow(im.at(x + 1, y, c) - im.at(x, y, c), 2);
    columns.push_back(s / im.height);
  }
  for (uint32_t y = 0; y + 1 < im.height; ++y) {
    double s = 0.0;
    for (uint32_t x = 0; x < im.width; ++x)
      for (uint32_t c = 0; c < C; ++c) s += std::pow(im.at(x, y + 1, c) - im.at(x, y, c), 2);
    rows.push_back(s / im.width);
  }
  const double mc = std::max(median_of(columns), 1e-30), mr = std::max(median_of(rows), 1e-30);
  return std::max(*std::max_element(columns.begin(), columns.end()) / mc,
                  *std::max_element(rows.begin(), rows.end()) / mr);
}

// Power per octave band of a square power-of-two window's periodic DFT (mean removed), summed over channels, as a
// fraction of the window's variance: band j >= 1 holds frequencies of radius in [1/2^(j+1), 1/2^j) cycles per pixel,
// band 0 those of radius >= 1/4. Separable direct DFT (O(n^3)): for windows up to a few hundred pixels.
inline std::vector<double> octave_spectrum(const Image& im) {
  const uint32_t n = im.width, C = im.channels;
  std::vector<std::complex<double>> twiddle(n);
  for (uint32_t k = 0; k < n; ++k) twiddle[k] = std::polar(1.0, -2.0 * std::numbers::pi * k / n);
  uint32_t log2n = 0;
  while ((1u << (log2n + 1)) <= n) ++log2n;
  std::vector<double> power(std::max(log2n, 2u) - 1, 0.0);  // the last band reaches the lowest radius, 1 / n
  double total = 0.0;
  std::vector<std::complex<double>> rows(size_t(n) * n), full(size_t(n) * n);
  for (uint32_t c = 0; c < C; ++c) {
    double mean = 0.0;
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t x = 0; x < n; ++x) mean += im.at(x, y, c);
    mean /= double(n) * n;
    for (uint32_t y = 0; y < n; ++y)
      for (uint32_t k = 0; k < n; ++k) {
        std::complex<double> s = 0.0;
        for (uint32_t x = 0; x < n; ++x) s += (im.at(x, y, c) - mean) * twiddle[(size_t(k) * x) % n];
        rows[size_t(y) * n + k] = s;
      }
    for (uint32_t k = 0; k < n; ++k)
      for (uint32_t l = 0; l < n; ++l) {
        std::complex<double> s = 0.0;
        for (uint32_t y = 0; y < n; ++y) s += rows[size_t(y) * n + k] * twiddle[(size_t(l) * y) % n];
        full[size_t(l) * n + k] = s;
      }
    for (uint32_t l = 0; l < n; ++l)
      for (uint32_t k = 0; k < n; ++k) {
        const double fx = (k <= n / 2 ? double(k) : double(k) - n) / n,
                     fy = (l <= n / 2 ? double(l) : double(l) - n) / n;
        const double radius = std::hypot(fx, fy);
        if (radius == 0.0) continue;
        const double p = std::norm(full[size_t(l) * n + k]) / (double(n) * n * n * n);  // Parseval: sums to variance
        total += p;
        uint32_t band = 0;
        while (band + 1 < power.size() && radius < 0.25 / double(1u << band)) ++band;
        power[band] += p;
      }
  }
  for (double& p : power) p /= std::max(total, 1e-30);
  return power;
}

}  // namespace mbk::test
