// The lookup convention of standardization tables (see lut_lookup.h).
#include "formats/lut_lookup.h"

#include <algorithm>
#include <cmath>

#include "formats/error.h"

namespace mbk {
namespace {

// Index cells per knot interval: the two grids' knots crowd in places (both sides of an atom's rise in x, the
// sparse tails in z), so a finer index keeps the search to a knot or two there (4 bytes per cell).
constexpr size_t kCellsPerKnot = 4;

}  // namespace

KnotInterpolant::KnotInterpolant(std::span<const float> keys, std::span<const float> values)
    : keys_(keys.begin(), keys.end()), values_(values.begin(), values.end()) {
  if (keys_.empty() || keys_.size() != values_.size() || keys_.size() > UINT32_MAX)
    throw Error(ExitCode::runtime_failure, "internal: a knot table needs as many keys as values, at least one");
  const size_t M = keys_.size();
  slopes_.resize(M > 1 ? M - 1 : 0);
  for (size_t i = 0; i + 1 < M; ++i) {
    const double dk = double(keys_[i + 1]) - double(keys_[i]);
    slopes_[i] = dk > 0.0 ? (double(values_[i + 1]) - double(values_[i])) / dk : 0.0;  // 0: unvalidated knots
  }
  const double span = double(keys_.back()) - double(keys_.front());
  if (M < 2 || !(span > 0.0) || !std::isfinite(span)) return;  // constant, or a table validate refuses
  const size_t cells = kCellsPerKnot * (M - 1);
  cell_scale_ = double(cells) / span;
  // first_[c] = the last knot whose cell is below c (0 if none): every x in cell c is >= that knot, because
  // cell_of is non-decreasing in x. first_[cells] = M - 1.
  first_.assign(cells + 1, 0);
  size_t i = 0;
  for (size_t c = 1; c <= cells; ++c) {
    while (i + 1 < M && cell_of(keys_[i + 1]) < c) ++i;
    first_[c] = uint32_t(i);
  }
  first_[cells] = uint32_t(M - 1);
}

// floor((x - k_0) * cells / span), clamped to [0, cells - 1]: non-decreasing in x (each operation is).
size_t KnotInterpolant::cell_of(double x) const {
  const double t = (x - double(keys_.front())) * cell_scale_;
  if (!(t > 0.0)) return 0;
  return std::min(size_t(t), first_.size() - 2);
}

LutSample KnotInterpolant::operator()(double x) const {
  if (!(x >= keys_.front())) return {values_.front(), 0.0};  // below the knots, or NaN
  if (x > keys_.back() || keys_.size() == 1) return {values_.back(), 0.0};
  size_t i;  // the last knot <= x, at most M - 2
  if (first_.empty()) {
    i = size_t(std::upper_bound(keys_.begin(), keys_.end() - 1, x, [](double q, float k) { return q < k; }) -
               keys_.begin());
    i = i == 0 ? 0 : i - 1;
  } else {
    const size_t c = cell_of(x), lo = first_[c], hi = first_[c + 1];
    i = size_t(std::upper_bound(keys_.begin() + ptrdiff_t(lo) + 1, keys_.begin() + ptrdiff_t(hi) + 1, x,
                                [](double q, float k) { return q < k; }) -
               keys_.begin()) -
        1;
  }
  i = std::min(i, keys_.size() - 2);
  return {values_[i] + (x - double(keys_[i])) * slopes_[i], slopes_[i]};
}

}  // namespace mbk
