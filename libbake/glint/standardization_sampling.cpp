// Sampling the standardization transform into tables (see standardization_sampling.h).
#include "libbake/glint/standardization_sampling.h"

#include <algorithm>

#include "formats/error.h"
#include "formats/lut_layout.h"

namespace mbk {
namespace {

// Samples f at the lookup positions of [lo, hi] (formats/lut_layout.h). Serial: even 65536 samples take only a
// few milliseconds.
template <typename F>
std::vector<float> sample_table(double lo, double hi, uint32_t size, const F& f) {
  std::vector<float> values(size);
  for (uint32_t j = 0; j < size; ++j) values[j] = float(f(lut_sample_position(lo, hi, size, j)));
  return values;
}

// Slope entry j of the stored table: the exact derivative of its interpolant on [s_j, s_{j+1}).
std::vector<float> slopes_of(const std::vector<float>& values, double lo, double hi) {
  const uint32_t size = uint32_t(values.size());
  std::vector<float> slopes(size - 1);
  for (uint32_t j = 0; j + 1 < size; ++j) slopes[j] = float(lut_interval_slope(lo, hi, size, values[j], values[j + 1]));
  return slopes;
}

// The forward sample at x: the inverse of the inverse table's interpolant (lut_lookup.h) at x, as a Gaussian
// value. The interpolant passes through (s_j, v_j); where it is flat at x (a run v_a = ... = v_b = x of equal
// floats) the middle of the run is taken, as mid-ranks do for ties. Requires v_0 <= x <= v_{size-1}.
double invert_interpolant(const std::vector<float>& v, double z_lo, double z_hi, double x) {
  const uint32_t size = uint32_t(v.size());
  const size_t a = size_t(std::lower_bound(v.begin(), v.end(), x, [](float e, double q) { return e < q; }) - v.begin());
  const size_t b = size_t(std::upper_bound(v.begin(), v.end(), x, [](double q, float e) { return q < e; }) - v.begin());
  double t;  // in sample units
  if (a < b) {
    t = 0.5 * (double(a) + double(b - 1));  // v_a .. v_{b-1} equal x
  } else {
    // v_{a-1} < x < v_a, with 1 <= a <= size - 1 because v_0 <= x <= v_{size-1}.
    const size_t j = std::clamp<size_t>(a, 1, size - 1) - 1;
    t = double(j) + (x - double(v[j])) / (double(v[j + 1]) - double(v[j]));
  }
  return z_lo + (z_hi - z_lo) * (t / double(size - 1));
}

}  // namespace

StandardizationChannelTables sample_standardization(const EmpiricalStandardization& transform, uint32_t size) {
  if (size < kLutMinSize || size > kLutMaxSize)
    throw Error(ExitCode::runtime_failure, "internal: lut size " + std::to_string(size) + " outside 2..65536");
  StandardizationChannelTables t;
  if (transform.max() - transform.min() < kFlatChannelSpread) {
    t.x_lo = t.x_hi = float(transform.min());
    t.z_lo = t.z_hi = 0.0f;
    t.forward.assign(size, 0.0f);
    t.inverse.assign(size, t.x_lo);
    t.forward_slope.assign(size - 1, 0.0f);
    t.inverse_slope.assign(size - 1, 0.0f);
    return t;
  }
  // min and max are float texel values: exact in float.
  t.x_lo = float(transform.min());
  t.x_hi = float(transform.max());
  t.z_lo = float(transform.gaussian_min());
  t.z_hi = float(transform.gaussian_max());
  t.inverse = sample_table(t.z_lo, t.z_hi, size, [&](double z) { return transform.inverse(z); });
  t.inverse.front() = t.x_lo, t.inverse.back() = t.x_hi;
  t.forward =
      sample_table(t.x_lo, t.x_hi, size, [&](double x) { return invert_interpolant(t.inverse, t.z_lo, t.z_hi, x); });
  t.forward.front() = t.z_lo, t.forward.back() = t.z_hi;
  t.forward_slope = slopes_of(t.forward, t.x_lo, t.x_hi);
  t.inverse_slope = slopes_of(t.inverse, t.z_lo, t.z_hi);
  return t;
}

}  // namespace mbk
