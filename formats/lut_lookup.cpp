// The lookup convention of standardization tables (see lut_lookup.h).
#include "formats/lut_lookup.h"

#include <algorithm>
#include <cmath>

namespace mbk {

LutSample lut_lookup(const LutTableView& table, double x) {
  const size_t size = table.values.size();
  if (!(x >= table.lo)) return {table.values.front(), 0.0};  // below the domain, or NaN
  if (x > table.hi) return {table.values.back(), 0.0};
  if (!(table.hi > table.lo)) return {table.values.front(), 0.0};  // lo == hi == x: a constant table
  double t = (x - table.lo) / (table.hi - table.lo) * double(size - 1);
  // t is in [0, size - 1] up to rounding for finite domains; an infinite one (which validate refuses) gives NaN.
  // Clamp t before converting it to an index, so that no table can make a lookup read out of bounds.
  if (!(t >= 0.0)) t = 0.0;
  if (t > double(size - 1)) t = double(size - 1);
  const size_t i = std::min(size_t(t), size - 2);
  const double f = t - double(i);
  const double v0 = table.values[i], v1 = table.values[i + 1];
  return {v0 + f * (v1 - v0), table.slopes[i]};
}

}  // namespace mbk
