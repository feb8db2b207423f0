// Baking the standardization LUT asset (see lut_asset.h).
#include "libbake/glint/lut_asset.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "formats/lut_layout.h"
#include "libbake/core/parallel.h"
#include "libbake/glint/empirical_standardization.h"
#include "libbake/glint/standard_normal.h"
#include "libbake/glint/standardization_sampling.h"

namespace mbk {
namespace {

// max over `count` points of error(i), in parallel blocks, reduced serially in block order (deterministic).
template <typename Error>
double max_error(size_t count, const Error& error) {
  constexpr int64_t kBlock = 4096;
  const int64_t blocks = (int64_t(count) + kBlock - 1) / kBlock;
  std::vector<double> block_max(size_t(blocks), 0.0);
  parallel_for(0, blocks, [&](int64_t b) {
    const size_t end = size_t(std::min<int64_t>(int64_t(count), (b + 1) * kBlock));
    double worst = 0.0;
    for (size_t i = size_t(b * kBlock); i < end; ++i) worst = std::max(worst, error(i));
    block_max[size_t(b)] = worst;
  });
  return block_max.empty() ? 0.0 : *std::max_element(block_max.begin(), block_max.end());
}

LutChannelStatistics channel_statistics(const EmpiricalStandardization& g, const StandardizationChannelTables& t) {
  LutChannelStatistics s;
  s.min = g.min();
  s.max = g.max();
  s.distinct_values = g.distinct_values();
  s.knots = t.knots();
  s.gaussian_min = t.z_lo();
  s.gaussian_max = t.z_hi();
  const std::span<const float> u = g.distinct(), z = t.z();
  s.forward_error =
      max_error(u.size(), [&](size_t i) { return std::abs(t.standardize(u[i]).value - g.forward(u[i])); });
  s.round_trip_error = max_error(
      u.size(), [&](size_t i) { return std::abs(t.destandardize(t.standardize(u[i]).value).value - double(u[i])); });
  // Midpoints of the knot intervals in z (the interpolant's worst places), and the ends.
  s.inverse_error = max_error(z.size(), [&](size_t i) {
    const double q = i + 1 < z.size() ? 0.5 * (double(z[i]) + double(z[i + 1])) : double(z[i]);
    return std::abs(t.destandardize(q).value - g.inverse(q));
  });
  // Lower tail below z_lo plus upper tail above z_hi, each through its own side of Phi.
  s.clipped_tail_mass = standard_normal_cdf(t.z_lo()) + standard_normal_cdf(-double(t.z_hi()));
  return s;
}

std::vector<float> channel_values(const NormalMap& map, int channel) {
  std::vector<float> v(map.texels.size());
  for (size_t i = 0; i < v.size(); ++i) v[i] = map.texels[i][channel];
  return v;
}

}  // namespace

nlohmann::json LutChannelStatistics::to_json() const {
  return {{"min", min},
          {"max", max},
          {"distinct_values", distinct_values},
          {"knots", knots},
          {"gaussian_min", gaussian_min},
          {"gaussian_max", gaussian_max},
          {"forward_error", forward_error},
          {"inverse_error", inverse_error},
          {"round_trip_error", round_trip_error},
          {"clipped_tail_mass", clipped_tail_mass}};
}

BakedLut bake_standardization_lut(const NormalMap& map, uint32_t size, Progress& progress) {
  if (size < kLutMinSize || size > kLutMaxSize)
    throw Error(ExitCode::bad_command_line, "--size must be in " + std::to_string(kLutMinSize) + ".." +
                                                std::to_string(kLutMaxSize) + ", not " + std::to_string(size));
  if (map.texels.empty()) throw Error(ExitCode::runtime_failure, "internal: empty normal map");
  for (const Vec3f& n : map.texels)  // checked here so that nothing throws inside the parallel region below
    if (!n.allFinite()) throw Error(ExitCode::runtime_failure, "internal: non-finite normal in the example");

  progress.start("lut: standardizing n_x, n_y", 2 * kLutChannels);
  std::array<std::optional<EmpiricalStandardization>, kLutChannels> transforms;
  parallel_for(0, kLutChannels, [&](int64_t c) {  // the two sorts run side by side
    transforms[size_t(c)].emplace(channel_values(map, int(c)));
    progress.advance();
  });
  BakedLut baked;
  baked.tables.size = size;
  for (uint32_t c = 0; c < kLutChannels; ++c) {
    baked.tables.channels[c] = sample_standardization(*transforms[c], size);
    baked.statistics[c] = channel_statistics(*transforms[c], baked.tables.channels[c]);
    progress.advance();
  }
  progress.finish();
  return baked;
}

AssetWriter lut_asset_writer(const BakedLut& lut, const InputRecord& input) {
  const uint32_t size = lut.tables.size;
  nlohmann::json metadata;
  metadata["inputs"] = nlohmann::json::array({input.to_json()});
  metadata["parameters"] = {{"size", size}};
  metadata["conventions"] = normal_map_conventions();
  metadata["conventions"]["channels"] =
      "knots_n_x and knots_n_y hold n_x and n_y, the x and y components of the unit normal, standardized "
      "separately";
  metadata["conventions"]["gaussian"] = "standard normal N(0, 1)";
  metadata["conventions"]["standardization"] =
      "mid-rank empirical CDF F_k = (c_1 + ... + c_{k-1} + c_k / 2) / N over the distinct values u_k with counts "
      "c_k, linear between them; G = Phi^-1(F), G^-1 its inverse, clamped to [min, max]";
  metadata["conventions"]["knots"] =
      "per channel, rows (x, z) with z = G(x) rounded to float, strictly increasing in both: G at a uniform grid of "
      "size points over [min, max], at G^-1 of a uniform grid of size points over [G(min), G(max)], and at every "
      "value shared by at least N / size texels";
  metadata["conventions"]["lookup"] =
      "forward G_T: linear between knots read as (x, z), inverse G^-1_T: linear between knots read as (z, x), so "
      "each is the other's inverse; derivative the segment's slope; clamped (derivative 0) outside the knots";
  nlohmann::json statistics;
  for (uint32_t c = 0; c < kLutChannels; ++c)
    statistics[std::string(kLutChannelNames[c])] = lut.statistics[c].to_json();
  metadata["statistics"] = statistics;

  AssetWriter writer("lut", std::move(metadata));
  for (uint32_t c = 0; c < kLutChannels; ++c) {
    const StandardizationChannelTables& t = lut.tables.channels[c];
    std::vector<float> rows(2 * t.knots());
    for (size_t i = 0; i < t.knots(); ++i) rows[2 * i] = t.x()[i], rows[2 * i + 1] = t.z()[i];
    writer.add(std::string(kLutKnotSections[c]), {t.knots(), kLutKnotColumns}, rows);
  }
  return writer;
}

}  // namespace mbk
