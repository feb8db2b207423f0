// Periodic height fields -> integrable normal maps (see height_field.h).
#include "libbake/gen/height_field.h"

#include <cmath>

#include "libbake/core/parallel.h"

namespace mbk {
namespace {

// Central-difference gradient (dh/dx, dh/dy) at (x, row), wrapping at the borders; y is up.
Vec2 gradient(const HeightField& f, uint32_t x, uint32_t row) {
  const uint32_t xl = x == 0 ? f.width - 1 : x - 1, xr = x + 1 == f.width ? 0 : x + 1;
  const uint32_t up = row == 0 ? f.height - 1 : row - 1, down = row + 1 == f.height ? 0 : row + 1;
  return {0.5 * (f.at(xr, row) - f.at(xl, row)), 0.5 * (f.at(x, up) - f.at(x, down))};
}

}  // namespace

HeightField sample_height_field(uint32_t width, uint32_t height, const std::function<double(uint32_t, uint32_t)>& fn,
                                Progress& progress) {
  HeightField f;
  f.width = width;
  f.height = height;
  f.h.resize(size_t(width) * height);
  parallel_for(0, height, [&](int64_t row) {
    for (uint32_t x = 0; x < width; ++x) f.h[size_t(row) * width + x] = fn(x, uint32_t(row));
    progress.advance();
  });
  return f;
}

Vec2 texel_uv(uint32_t x, uint32_t row, uint32_t width, uint32_t height) {
  return {(x + 0.5) / width, 1.0 - (row + 0.5) / height};
}

double rms_slope(const HeightField& field) {
  // Per-row sums in parallel, then a serial sum in row order: the same bits for any thread count.
  std::vector<double> rows(field.height, 0.0);
  parallel_for(0, field.height, [&](int64_t row) {
    double s = 0.0;
    for (uint32_t x = 0; x < field.width; ++x) s += gradient(field, x, uint32_t(row)).squaredNorm();
    rows[row] = s;
  });
  double total = 0.0;
  for (double s : rows) total += s;
  return field.h.empty() ? 0.0 : std::sqrt(total / double(field.h.size()));
}

NormalMap normals_from_height(const HeightField& field, double scale) {
  NormalMap map;
  map.width = field.width;
  map.height = field.height;
  map.texels.resize(field.h.size());
  parallel_for(0, field.height, [&](int64_t row) {
    for (uint32_t x = 0; x < field.width; ++x) {
      const Vec2 g = scale * gradient(field, x, uint32_t(row));
      map.at(x, uint32_t(row)) = Vec3(-g.x(), -g.y(), 1.0).normalized().cast<float>();
    }
  });
  return map;
}

NormalMap normals_with_rms_slope(const HeightField& field, double target) {
  const double rms = rms_slope(field);
  // A constant field (e.g. a 1 x 1 map) has no slope to scale: it gives the flat map.
  return normals_from_height(field, rms > 0.0 ? target / rms : 0.0);
}

}  // namespace mbk
