// Writing a baked histogram as an asset (see histogram_asset.h).
#include "libbake/histogram/histogram_asset.h"

#include <numbers>

namespace mbk {

AssetWriter histogram_asset_writer(const LoadedNormalMap& input, const HistogramBakeOptions& options, uint64_t seed,
                                   BakedHistogram&& baked) {
  const uint32_t K = baked.bins.theta_bins(), N = baked.bins.phi_bins, B = baked.bins.count();
  const BinCountTable table = baked.table();
  std::vector<uint64_t> totals(B);
  footprint_histogram(table, 0, 0, baked.width, baked.height, totals);
  uint64_t empty = 0;
  for (uint64_t c : totals) empty += c == 0;
  nlohmann::json metadata;
  metadata["inputs"] = nlohmann::json::array({input.record.to_json()});
  metadata["parameters"] = {{"width", baked.width},
                            {"height", baked.height},
                            {"method", "exact"},
                            {"theta_bins", K},
                            {"theta_bins_requested", options.theta_bins},
                            {"phi_bins", N},
                            {"theta_binning", theta_binning_name(options.theta_binning)},
                            {"seed", seed}};
  metadata["conventions"] = normal_map_conventions();
  metadata["conventions"]["bins"] =
      "theta = atan2(sqrt(x^2 + y^2), z) in theta_edges (midpoints of the centres: 1-D k-means centres, or uniform), "
      "phi = "
      "atan2(y, x) in [0, 2 pi) in phi_edges (uniform); bins half-open [lo, hi), the last theta bin also holds pi/2; "
      "phi bin 0 at the pole; bin = theta_bin * phi_bins + phi_bin";
  metadata["conventions"]["bin_counts"] =
      "entry (Y, X, b) = texels of bin b in rows [0, Y) and columns [0, X), row 0 at the top";
  nlohmann::json degrees = nlohmann::json::array();  // the edges as `info` shows them; exact values: theta_edges
  for (double e : baked.theta.edges) degrees.push_back(e * 180.0 / std::numbers::pi);
  metadata["statistics"] = {{"theta_edges_degrees", degrees},
                            {"distinct_theta_values", baked.theta.distinct_values},
                            {"lloyd_iterations", baked.theta.lloyd_iterations},
                            {"theta_rms_error", baked.theta.rms_error},
                            {"empty_bins", empty},
                            {"table_bytes", histogram_table_bytes(baked.width, baked.height, B)}};
  AssetWriter writer("histogram", std::move(metadata));
  writer.add<double>(kHistogramThetaEdgesSection, {K + 1}, baked.theta.edges);
  writer.add<double>(kHistogramThetaCentresSection, {K}, baked.theta.centres);
  writer.add<double>(kHistogramPhiEdgesSection, {N + 1}, histogram_phi_edges(N));
  writer.add(kHistogramCountsSection, {uint64_t(baked.height) + 1, uint64_t(baked.width) + 1, B},
             std::move(baked.counts));
  return writer;
}

}  // namespace mbk
