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

// max |G^-1(G(x)) - x| through the tables over the distinct example values (the same maximum as over all
// texels), in parallel blocks, reduced serially in block order.
double round_trip_error(const StandardizationChannelTables& t, std::span<const float> values) {
  constexpr int64_t kBlock = 4096;
  const int64_t blocks = (int64_t(values.size()) + kBlock - 1) / kBlock;
  std::vector<double> block_max(size_t(blocks), 0.0);
  parallel_for(0, blocks, [&](int64_t b) {
    const size_t end = size_t(std::min<int64_t>(int64_t(values.size()), (b + 1) * kBlock));
    double worst = 0.0;
    for (size_t i = size_t(b * kBlock); i < end; ++i) {
      const double x = values[i];
      worst = std::max(worst, std::abs(t.destandardize(t.standardize(x).value).value - x));
    }
    block_max[size_t(b)] = worst;
  });
  return block_max.empty() ? 0.0 : *std::max_element(block_max.begin(), block_max.end());
}

LutChannelStatistics channel_statistics(const EmpiricalStandardization& g, const StandardizationChannelTables& t) {
  LutChannelStatistics s;
  s.min = g.min();
  s.max = g.max();
  s.distinct_values = g.distinct_values();
  s.gaussian_min = t.z_lo;
  s.gaussian_max = t.z_hi;
  s.round_trip_error = round_trip_error(t, g.distinct());
  // Lower tail below z_lo plus upper tail above z_hi, each through its own side of Phi.
  s.clipped_tail_mass = standard_normal_cdf(t.z_lo) + standard_normal_cdf(-double(t.z_hi));
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
          {"gaussian_min", gaussian_min},
          {"gaussian_max", gaussian_max},
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
      "rows 0 and 1 of every section are n_x and n_y, the x and y components of the unit normal, standardized "
      "separately";
  metadata["conventions"]["gaussian"] = "standard normal N(0, 1)";
  metadata["conventions"]["standardization"] =
      "mid-rank empirical CDF F_k = (c_1 + ... + c_{k-1} + c_k / 2) / N over the distinct values u_k with counts "
      "c_k, linear between them; G = Phi^-1(F), G^-1 its inverse, clamped to [min, max]";
  metadata["conventions"]["domains"] =
      "per channel (x_lo, x_hi, z_lo, z_hi): inverse tables sample G^-1 on [z_lo, z_hi] = [G(min), G(max)]; forward "
      "tables sample, on [x_lo, x_hi] = [min, max], the exact inverse of the inverse table's interpolant (G within "
      "one inverse step where G^-1 is resolved), so that a round trip is within one forward step";
  metadata["conventions"]["lookup"] =
      "sample j of a table over [lo, hi] at lo + j (hi - lo) / (size - 1); linear between samples; clamped "
      "outside [lo, hi] (derivative 0 there); slope j = (v_{j+1} - v_j) / ((hi - lo) / (size - 1)), the exact "
      "derivative of the interpolant on [s_j, s_{j+1})";
  nlohmann::json statistics;
  for (uint32_t c = 0; c < kLutChannels; ++c)
    statistics[std::string(kLutChannelNames[c])] = lut.statistics[c].to_json();
  metadata["statistics"] = statistics;

  std::vector<float> domains, forward, forward_slope, inverse, inverse_slope;
  for (const StandardizationChannelTables& t : lut.tables.channels) {
    domains.insert(domains.end(), {t.x_lo, t.x_hi, t.z_lo, t.z_hi});
    forward.insert(forward.end(), t.forward.begin(), t.forward.end());
    forward_slope.insert(forward_slope.end(), t.forward_slope.begin(), t.forward_slope.end());
    inverse.insert(inverse.end(), t.inverse.begin(), t.inverse.end());
    inverse_slope.insert(inverse_slope.end(), t.inverse_slope.begin(), t.inverse_slope.end());
  }
  AssetWriter writer("lut", std::move(metadata));
  writer.add(std::string(kLutDomainsSection), {kLutChannels, kLutDomainValues}, domains);
  writer.add(std::string(kLutForwardSection), {kLutChannels, size}, forward);
  writer.add(std::string(kLutForwardSlopeSection), {kLutChannels, size - 1}, forward_slope);
  writer.add(std::string(kLutInverseSection), {kLutChannels, size}, inverse);
  writer.add(std::string(kLutInverseSlopeSection), {kLutChannels, size - 1}, inverse_slope);
  return writer;
}

}  // namespace mbk
