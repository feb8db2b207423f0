// Builds SH NDF pyramids (see sh_pyramid.h).
#include "libbake/filter/sh_pyramid.h"

#include <algorithm>
#include <string>

#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/core/sh_basis.h"

namespace mbk {
namespace {

// Whether each texel of the level of `extent` texels covers exactly 1 or 2 whole texels of the level of
// `finer` texels (so its mean is the mean of those).
bool nests(uint32_t finer, uint32_t extent) { return finer == 2 * extent || (finer == 1 && extent == 1); }
bool nests(const LevelSize& finer, const LevelSize& level) {
  return nests(finer.width, level.width) && nests(finer.height, level.height);
}

// Rows of a level from the finest normals: texel (i, j) = sum over its x-list and y-list of wx wy Y(n(x, y)).
class NormalsLevel {
 public:
  NormalsLevel(const NormalMap& map, const ShBasisEvaluator& basis, LevelSize size)
      : map_(map), basis_(basis), size_(size), wy_(mip_texel_weights(size.height, map.height)), columns_(map.width) {
    // Per finest column, the level columns it falls in and its weight in each (the transpose of wx).
    const auto wx = mip_texel_weights(size.width, map.width);
    for (uint32_t i = 0; i < size.width; ++i)
      for (const MipWeight& x : wx[i]) columns_[x.index].push_back({i, x.weight});
  }

  // Row j's width * count coefficients into out.
  void row(uint32_t j, float* out) const {
    const int count = basis_.count();
    thread_local std::vector<double> sum, y;
    sum.assign(size_t(size_.width) * size_t(count), 0.0);
    y.resize(size_t(count));
    for (const MipWeight& fy : wy_[j])
      for (uint32_t x = 0; x < map_.width; ++x) {
        // Normalised in double: a float normal's length is 1 only to ~6e-8, and the basis takes cos(theta) = z,
        // whose error the Legendre recurrence multiplies by ~l^2 near the poles (test:
        // HardCases.ShOrder128NearThePoleFromFloatNormals).
        basis_.evaluate(map_.at(x, fy.index).cast<double>().normalized(), y);
        for (const auto& [i, weight] : columns_[x]) {
          double* s = &sum[size_t(i) * size_t(count)];
          const double f = fy.weight * weight;
          for (int k = 0; k < count; ++k) s[k] += f * y[size_t(k)];
        }
      }
    for (size_t k = 0; k < sum.size(); ++k) out[k] = float(sum[k]);
  }

 private:
  const NormalMap& map_;
  const ShBasisEvaluator& basis_;
  LevelSize size_;
  std::vector<std::vector<MipWeight>> wy_;
  std::vector<std::vector<std::pair<uint32_t, double>>> columns_;
};

// Row of a level that nests in `finer` (see nests()): the box mean of each texel's 1 or 2 x 1 or 2 children,
// coefficients innermost (each child's coefficients read in order, once). finer_rows points at the sy
// consecutive finer rows the row covers.
void children_row(const float* finer_rows, uint32_t finer_width, uint32_t sx, uint32_t sy, uint32_t width, int count,
                  float* out) {
  thread_local std::vector<double> sum;
  sum.resize(size_t(count));
  const size_t finer_row = size_t(finer_width) * size_t(count);
  for (uint32_t i = 0; i < width; ++i) {
    std::fill(sum.begin(), sum.end(), 0.0);
    for (uint32_t dy = 0; dy < sy; ++dy)
      for (uint32_t dx = 0; dx < sx; ++dx) {
        const float* child = finer_rows + dy * finer_row + (size_t(i) * sx + dx) * size_t(count);
        for (int k = 0; k < count; ++k) sum[size_t(k)] += child[k];
      }
    float* o = out + size_t(i) * size_t(count);
    for (int k = 0; k < count; ++k) o[k] = float(sum[size_t(k)] / double(sx * sy));
  }
}

// Collects the rows into whole f32 levels.
class KeepLevels final : public ShRowSink {
 public:
  explicit KeepLevels(ShPyramid& pyramid) : pyramid_(pyramid) {}
  void start(const std::vector<LevelSize>& levels, int count) override {
    count_ = size_t(count);
    for (const LevelSize& s : levels)
      pyramid_.levels.push_back({s.width, s.height, std::vector<float>(size_t(s.width) * s.height * count_)});
  }
  void take_row(size_t k, uint32_t row, const float* coefficients) override {
    ShLevel& level = pyramid_.levels[k - 1];
    const size_t n = size_t(level.width) * count_;
    std::copy(coefficients, coefficients + n, level.coefficients.begin() + ptrdiff_t(row * n));
  }

 private:
  ShPyramid& pyramid_;
  size_t count_ = 0;
};

}  // namespace

// Levels built from the normals in one pass (stream_sh_pyramid): at most 1 + kMaxChain, the top one with at least
// kMinChainTopRows rows when there are more than two (a task per row of the top level; a task holds up to
// 2^kMaxChain rows of the finest, 21 MiB at 8192^2, order 8).
constexpr size_t kMaxChain = 4;
constexpr uint32_t kMinChainTopRows = 64;

void stream_sh_pyramid(const NormalMap& map, int order, ShRowSink& sink, Progress& progress) {
  const ShBasisEvaluator basis(order);
  const int count = basis.count();
  const auto sizes = mip_level_sizes(map.width, map.height);  // sizes[k] is level k
  const size_t levels = sizes.size();
  sink.start(levels == 0 ? std::vector<LevelSize>{} : std::vector<LevelSize>(sizes.begin() + 1, sizes.end()), count);
  progress.start("sh (levels)", levels == 0 ? 0 : levels - 1);
  auto row_floats = [&](size_t k) { return size_t(sizes[k].width) * size_t(count); };
  // Level k - 1 in f32 while level k is built from its children; empty otherwise.
  std::vector<float> finer;
  size_t k = 1;
  while (k < levels) {
    const LevelSize size = sizes[k];
    // How many coarser levels nest in turn above level k: up to kMaxChain, and beyond the first only while the top
    // one keeps enough rows for the threads (a level that nests in level k is always built with it: level k is
    // never held whole).
    size_t chain = 0;
    while (chain < kMaxChain && k + chain + 1 < levels && nests(sizes[k + chain], sizes[k + chain + 1]) &&
           (chain == 0 || sizes[k + chain + 1].height >= kMinChainTopRows))
      ++chain;
    std::vector<float> level;  // level k in f32, kept only when level k + 1 is built from it
    if (k >= 2 && nests(sizes[k - 1], size)) {
      level.resize(size_t(size.height) * row_floats(k));
      parallel_for(0, size.height, [&](int64_t row) {
        const uint32_t sy = sizes[k - 1].height / size.height;
        float* out = &level[size_t(row) * row_floats(k)];
        children_row(&finer[size_t(row) * sy * row_floats(k - 1)], sizes[k - 1].width, sizes[k - 1].width / size.width,
                     sy, size.width, count, out);
        sink.take_row(k, uint32_t(row), out);
      });
      progress.advance();
    } else if (chain > 0) {
      // Levels k..k + chain in one pass from the normals: a task per row of the top level builds the group of
      // level-k rows under it from the normals, then each coarser level's rows of the group from the finer ones.
      // Only the top level is held whole (in `level`); at 2048^2 levels 1..5, where level 2 alone is 85 MiB in f32.
      const NormalsLevel from_normals(map, basis, size);
      const size_t top = k + chain;
      level.resize(size_t(sizes[top].height) * row_floats(top));
      parallel_for(0, sizes[top].height, [&](int64_t row) {
        thread_local std::vector<float> group[kMaxChain + 1];  // group[i]: the rows of level k + i under `row`
        for (size_t i = 0; i <= chain; ++i) {
          const uint32_t rows = sizes[k + i].height / sizes[top].height, first = uint32_t(row) * rows;
          group[i].resize(rows * row_floats(k + i));
          for (uint32_t r = 0; r < rows; ++r) {
            float* out = &group[i][r * row_floats(k + i)];
            if (i == 0) {
              from_normals.row(first + r, out);
            } else {
              const LevelSize finer_size = sizes[k + i - 1], here = sizes[k + i];
              const uint32_t sy = finer_size.height / here.height;
              children_row(&group[i - 1][r * sy * row_floats(k + i - 1)], finer_size.width,
                           finer_size.width / here.width, sy, here.width, count, out);
            }
            sink.take_row(k + i, first + r, out);
          }
        }
        std::copy(group[chain].begin(), group[chain].end(), &level[size_t(row) * row_floats(top)]);
      });
      progress.advance(chain + 1);
      k = top;  // levels up to `top` are done; `level` holds it
    } else {
      const NormalsLevel from_normals(map, basis, size);
      parallel_for(0, size.height, [&](int64_t row) {
        thread_local std::vector<float> out;
        out.resize(row_floats(k));
        from_normals.row(uint32_t(row), out.data());
        sink.take_row(k, uint32_t(row), out.data());
      });
      progress.advance();
    }
    ++k;
    // `level` is level k - 1 now: kept when level k nests in it.
    if (k < levels && nests(sizes[k - 1], sizes[k]))
      finer = std::move(level);
    else
      std::vector<float>().swap(finer);
  }
  progress.finish();
}

ShPyramid build_sh_pyramid(const NormalMap& map, int order, Progress& progress) {
  ShPyramid pyramid;
  pyramid.order = order;
  KeepLevels keep(pyramid);
  stream_sh_pyramid(map, order, keep, progress);
  return pyramid;
}

}  // namespace mbk
