// Box-filtered MIP pyramids (see box_pyramid.h). A level is built row by row from the finest image: each finest row of
// a level row's rectangle is swept once, left to right, so the reads are sequential whatever the level.
#include "libbake/image/box_pyramid.h"

#include <algorithm>
#include <cmath>

#include "formats/error.h"
#include "formats/mip_levels.h"
#include "libbake/core/parallel.h"

namespace mbk {
namespace {

// mip_texel_weights of one axis in one array: level texel i's weights are weights[begin[i] .. begin[i + 1]).
struct FlatAxisWeights {
  std::vector<size_t> begin;
  std::vector<MipWeight> weights;
};

FlatAxisWeights flat_axis_weights(uint32_t level_extent, uint32_t extent) {
  FlatAxisWeights flat;
  flat.begin.push_back(0);
  for (const std::vector<MipWeight>& texel : mip_texel_weights(level_extent, extent)) {
    flat.weights.insert(flat.weights.end(), texel.begin(), texel.end());
    flat.begin.push_back(flat.weights.size());
  }
  return flat;
}

// One row of a level: `mean` (level width x C doubles, zero on entry) accumulates the rows `wy` of `finest`
// (W texels of C floats per row) in the order box_pyramid.h states. kC is C when known at compile time (the
// channel loops then unroll), 0 otherwise; `along` holds C doubles.
template <uint32_t kC>
void accumulate_level_row(const float* finest, size_t finest_row_floats, uint32_t channels, const FlatAxisWeights& wx,
                          const std::vector<MipWeight>& wy, std::span<double> mean, std::span<double> along) {
  const uint32_t C = kC != 0 ? kC : channels;
  const size_t level_width = wx.begin.size() - 1;
  for (const MipWeight& y : wy) {
    const float* row = finest + size_t(y.index) * finest_row_floats;
    for (size_t i = 0; i < level_width; ++i) {
      for (uint32_t c = 0; c < C; ++c) along[c] = 0.0;
      for (size_t t = wx.begin[i]; t < wx.begin[i + 1]; ++t) {
        const MipWeight& x = wx.weights[t];
        const float* texel = row + size_t(x.index) * C;
        for (uint32_t c = 0; c < C; ++c) along[c] += x.weight * double(texel[c]);
      }
      double* out = &mean[i * C];
      for (uint32_t c = 0; c < C; ++c) out[c] += y.weight * along[c];
    }
  }
}

void accumulate_level_row_any(const float* finest, size_t finest_row_floats, uint32_t channels,
                              const FlatAxisWeights& wx, const std::vector<MipWeight>& wy, std::span<double> mean,
                              std::span<double> along) {
  switch (channels) {
    case 1:
      return accumulate_level_row<1>(finest, finest_row_floats, channels, wx, wy, mean, along);
    case 2:
      return accumulate_level_row<2>(finest, finest_row_floats, channels, wx, wy, mean, along);
    case 3:
      return accumulate_level_row<3>(finest, finest_row_floats, channels, wx, wy, mean, along);
    case 4:
      return accumulate_level_row<4>(finest, finest_row_floats, channels, wx, wy, mean, along);
    default:
      return accumulate_level_row<0>(finest, finest_row_floats, channels, wx, wy, mean, along);
  }
}

}  // namespace

std::vector<Image> build_coarser_levels(std::span<const float> finest, uint32_t width, uint32_t height,
                                        uint32_t channels) {
  std::vector<Image> levels;
  const auto sizes = mip_level_sizes(width, height);
  if (sizes.empty()) return levels;
  const uint32_t C = channels;
  if (C == 0 || finest.size() != size_t(width) * height * C)
    throw Error(ExitCode::runtime_failure, "internal: image pixel count does not match its size");
  for (size_t k = 1; k < sizes.size(); ++k) {
    Image level;
    level.width = sizes[k].width;
    level.height = sizes[k].height;
    level.channels = C;
    level.pixels.resize(size_t(level.width) * level.height * C);
    const FlatAxisWeights wx = flat_axis_weights(level.width, width);
    const auto wy = mip_texel_weights(level.height, height);
    parallel_for(0, level.height, [&](int64_t row) {
      std::vector<double> mean(size_t(level.width) * C, 0.0), along(C);
      accumulate_level_row_any(finest.data(), size_t(width) * C, C, wx, wy[size_t(row)], mean, along);
      float* out = &level.pixels[size_t(row) * level.width * C];
      for (size_t i = 0; i < mean.size(); ++i) out[i] = float(mean[i]);
    });
    levels.push_back(std::move(level));
  }
  return levels;
}

std::vector<Image> build_box_pyramid(Image finest) {
  std::vector<Image> pyramid;
  if (finest.width == 0 || finest.height == 0) return pyramid;
  std::vector<Image> coarser = build_coarser_levels(finest.pixels, finest.width, finest.height, finest.channels);
  pyramid.push_back(std::move(finest));
  for (Image& level : coarser) pyramid.push_back(std::move(level));
  return pyramid;
}

}  // namespace mbk
