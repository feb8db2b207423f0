// Bakes the `rmq` asset kind from a loaded normal map (see rmq_asset.h).
#include "libbake/glint/rmq_asset.h"

#include "libbake/glint/glint_technique.h"
#include "libbake/glint/rmq_table.h"

namespace mbk {
namespace {

nlohmann::json rmq_conventions() {
  nlohmann::json c = normal_map_conventions();
  c["components"] = "n_x, n_y: the x and y components of the unit normal, z dropped ([Wang20])";
  c["table"] =
      "level-major [level][row][x][min_x, max_x, min_y, max_y]; entry (k, x, row) bounds the square "
      "[x, x + 2^k) x [row, row + 2^k) clipped to the example; levels k = 0..log2(patch), every texel";
  c["leaf"] =
      "texel element reach: n +/- (D^x + D^y) * (1/4 + 3 sigma_h / 2) per component, sigma_h = 1.5/sqrt(12) "
      "texels, D^x (D^y) the largest |difference| between horizontally (vertically) adjacent texels of the 3 x 3 "
      "block (pairs outside the example skipped): the 2 x 2 sub-elements' reach; sigma_r not included";
  c["quantization"] =
      "value(q) = lo if q = 0, hi if q = 2^bits - 1, else min(hi, lo + q * ((hi - lo) / (2^bits - 1))); "
      "minima rounded down, maxima rounded up; [lo, hi] per component in section 'range' (rows n_x, n_y)";
  c["borders"] = "not tileable: squares and difference stencils are clipped to the example";
  c["element_sigma_texels"] = kGlintElementSigmaTexels;
  c["spatial_cutoff_sigmas"] = kGlintSpatialCutoffSigmas;
  return c;
}

nlohmann::json rmq_statistics(const RmqLeafLevel& t) {
  const RmqLayout& L = t.layout;
  nlohmann::json levels = nlohmann::json::array(), sides = nlohmann::json::array();
  for (uint32_t k = 0; k < L.levels; ++k) levels.push_back(k), sides.push_back(1u << k);
  const uint64_t bytes_per_entry = 4ull * L.code_bytes();
  return {{"levels_stored", levels},
          {"square_sides", sides},
          {"bytes_per_entry", bytes_per_entry},
          {"bytes_per_level", bytes_per_entry * L.entries_per_level()},
          {"table_bytes", L.table_bytes()},
          {"paper_table_bytes", 8ull * L.entries_per_level() * L.levels},
          {"quantum", {{"x", t.range[0].quantum(L.bits)}, {"y", t.range[1].quantum(L.bits)}}},
          {"leaf_half_width",
           {{"mean_x", t.leaf.mean_half_width_x},
            {"max_x", t.leaf.max_half_width_x},
            {"mean_y", t.leaf.mean_half_width_y},
            {"max_y", t.leaf.max_half_width_y}}},
          {"leaf_slack_quanta", {{"mean", t.leaf.mean_slack_quanta}, {"max", t.leaf.max_slack_quanta}}}};
}

}  // namespace

AssetWriter bake_rmq_asset(const LoadedNormalMap& input, uint32_t patch, uint32_t bits, Progress& progress) {
  auto leaves = std::make_shared<const RmqLeafLevel>(build_rmq_leaf_level(input.map, patch, bits, progress));
  const RmqLeafLevel& t = *leaves;
  nlohmann::json metadata;
  metadata["inputs"] = nlohmann::json::array({input.record.to_json()});
  metadata["parameters"] = t.layout.to_parameters();
  metadata["conventions"] = rmq_conventions();
  metadata["statistics"] = rmq_statistics(t);
  AssetWriter writer("rmq", std::move(metadata));
  // Levels 1..K are built from level 0 while the file is written, each handed to the file as it is built.
  writer.add_produced("table", t.layout.code_type(), t.layout.table_shape(), [leaves](const auto& emit) {
    for_each_rmq_level(*leaves, [&](uint32_t, std::span<const uint8_t> codes) { emit(codes); });
  });
  const std::vector<double> range = {t.range[0].lo, t.range[0].hi, t.range[1].lo, t.range[1].hi};
  writer.add<double>("range", {2, 2}, range);
  return writer;
}

}  // namespace mbk
