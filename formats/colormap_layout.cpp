// The colour map C, its closed-form Gaussian convolution and the table lookup of the `colormap` kind (see
// colormap_layout.h for the conventions and the derivation).
#include "formats/colormap_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "formats/asset.h"
#include "formats/number_text.h"
#include "formats/error.h"

namespace mbk {
namespace {

// Beyond 40 standard deviations Phi is 0 or 1 and phi is 0 in double precision (Phi(-38.5) is below the
// smallest subnormal), so the limits are exact.
constexpr double kExactTail = 40.0;

// E[(X - a)_+] for X ~ N(m, sigma^2), t = m - a.
double expected_hinge(double t, double sigma) {
  if (sigma == 0.0 || std::abs(t) > kExactTail * sigma) return std::max(t, 0.0);
  const double z = t / sigma;
  const double cdf = 0.5 * std::erfc(-z / std::sqrt(2.0));
  const double pdf = std::exp(-0.5 * z * z) / std::sqrt(2.0 * M_PI);
  return t * cdf + sigma * pdf;
}

// E[H(X - a)], H right-continuous (H(0) = 1).
double expected_step(double t, double sigma) {
  if (sigma == 0.0 || std::abs(t) > kExactTail * sigma) return t >= 0.0 ? 1.0 : 0.0;
  return 0.5 * std::erfc(-(t / sigma) / std::sqrt(2.0));
}

}  // namespace

std::string colormap_curve_problem(const ColormapCurve& curve) {
  const size_t K = curve.knots.size();
  if (K == 0) return "no knots";
  if (K > kColormapMaxKnots) return std::to_string(K) + " knots, more than " + std::to_string(kColormapMaxKnots);
  if (curve.colors.size() != K) return "knot and colour counts differ";
  for (size_t k = 0; k < K; ++k) {
    if (!std::isfinite(curve.knots[k])) return "knot " + std::to_string(k) + " is not finite";
    for (double c : curve.colors[k])
      if (!std::isfinite(c)) return "colour " + std::to_string(k) + " is not finite";
    if (k > 0 && curve.knots[k] < curve.knots[k - 1])
      return "knot " + std::to_string(k) + " (" + number_text(curve.knots[k]) + ") is below knot " +
             std::to_string(k - 1) + " (" + number_text(curve.knots[k - 1]) + ")";
    if (k > 1 && curve.knots[k] == curve.knots[k - 2])
      return "knots " + std::to_string(k - 2) + ".." + std::to_string(k) + " share one position";
  }
  return {};
}

std::array<double, 3> ColormapCurve::at(double x) const { return convolved(x, 0.0); }

// [Heitz13] Eq. (10) for the piecewise-linear C, term by term (colormap_layout.h), grouped by knot position: at
// each position p the slope changes by (slope after p) - (slope before p), one hinge, and a jump adds one step, so
// erfc and exp run once per position rather than once per segment end.
std::array<double, 3> ColormapCurve::convolved(double mean, double sigma) const {
  std::array<double, 3> sum = colors.front(), slope_before{0.0, 0.0, 0.0};
  const size_t K = knots.size();
  for (size_t k = 0; k < K;) {
    const double p = knots[k];
    const size_t right = k + 1 < K && knots[k + 1] == p ? k + 1 : k;  // the later knot of a jump
    const double hinge = expected_hinge(mean - p, sigma);
    const double step = right != k ? expected_step(mean - p, sigma) : 0.0;
    for (int c = 0; c < 3; ++c) {
      const double slope_after =
          right + 1 < K ? (colors[right + 1][c] - colors[right][c]) / (knots[right + 1] - p) : 0.0;
      sum[c] += (slope_after - slope_before[c]) * hinge + (colors[right][c] - colors[k][c]) * step;
      slope_before[c] = slope_after;
    }
    k = right + 1;
  }
  return sum;
}

double ColormapTable::mean_at(uint32_t i) const {
  if (i + 1 >= width) return mean_max;
  return mean_min + (mean_max - mean_min) * (double(i) / double(width - 1));
}

double ColormapTable::sigma_at(uint32_t j) const {
  if (j + 1 >= height) return sigma_max;
  return sigma_max * (double(j) / double(height - 1));
}

std::array<double, 3> ColormapTable::lookup(double mean, double sigma) const {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  if (!std::isfinite(mean) || !std::isfinite(sigma)) return {nan, nan, nan};
  // Continuous indices, clamped to the table (the convention of colormap_layout.h).
  const double fx =
      mean_max > mean_min ? std::clamp((mean - mean_min) / (mean_max - mean_min), 0.0, 1.0) * double(width - 1) : 0.0;
  const double fy = sigma_max > 0.0 ? std::clamp(sigma / sigma_max, 0.0, 1.0) * double(height - 1) : 0.0;
  const uint32_t x0 = std::min(uint32_t(fx), width - 2), y0 = std::min(uint32_t(fy), height - 2);
  const double ax = fx - x0, ay = fy - y0;
  std::array<double, 3> out{};
  for (int c = 0; c < 3; ++c) {
    auto v = [&](uint32_t x, uint32_t y) { return double(values[(size_t(y) * width + x) * 3 + c]); };
    out[c] = (1 - ay) * ((1 - ax) * v(x0, y0) + ax * v(x0 + 1, y0)) +
             ay * ((1 - ax) * v(x0, y0 + 1) + ax * v(x0 + 1, y0 + 1));
  }
  return out;
}

ColormapTable read_colormap_table(const Asset& asset) {
  const auto& p = asset.metadata()["parameters"];
  auto number = [&](const char* key) {
    if (!p.is_object() || !p.contains(key) || !p[key].is_number())
      throw Error(ExitCode::invalid_input, std::string("colormap asset lacks parameters.") + key);
    return p[key].get<double>();
  };
  ColormapTable t;
  const double w = number("width"), h = number("height");
  t.mean_min = number("mean_min");
  t.mean_max = number("mean_max");
  t.sigma_max = number("sigma_max");
  if (!(w >= kColormapMinSide && w <= kColormapMaxSide && h >= kColormapMinSide && h <= kColormapMaxSide) ||
      w != std::floor(w) || h != std::floor(h) || !(t.mean_max > t.mean_min) || !(t.sigma_max > 0.0) ||
      !std::isfinite(t.mean_max) || !std::isfinite(t.mean_min) || !std::isfinite(t.sigma_max))
    throw Error(ExitCode::invalid_input, "colormap asset parameters out of range");
  t.width = uint32_t(w);
  t.height = uint32_t(h);
  if (asset.section(std::string(kColormapTableSection)).shape != std::vector<uint64_t>{t.height, t.width, 3})
    throw Error(ExitCode::invalid_input, "colormap table shape does not match its parameters");
  t.values = asset.read<float>(std::string(kColormapTableSection));
  return t;
}

}  // namespace mbk
