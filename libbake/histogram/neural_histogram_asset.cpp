// Writing a baked neural histogram as an asset (see neural_histogram_asset.h).
#include "libbake/histogram/neural_histogram_asset.h"

#include <Imath/half.h>

#include <numbers>

#include "formats/error.h"

namespace mbk {
namespace {

// The f16 values of `values`; Error(runtime_failure) when one is not finite in f16 (training diverged).
std::vector<Imath::half> halves(const std::vector<float>& values, const char* what) {
  std::vector<Imath::half> out(values.begin(), values.end());
  for (const Imath::half& h : out)
    if (!h.isFinite())
      throw Error(ExitCode::runtime_failure,
                  std::string("neural histogram training diverged: a value of its ") + what + " is not finite in f16");
  return out;
}

}  // namespace

AssetWriter neural_histogram_asset_writer(const LoadedNormalMap& input, const NeuralHistogramBakeOptions& options,
                                          uint64_t kmeans_seed, BakedNeuralHistogram&& baked) {
  const NeuralHistogramShape& shape = baked.model.shape;
  const uint32_t K = shape.theta_bins;
  nlohmann::json metadata;
  metadata["inputs"] = nlohmann::json::array({input.record.to_json()});
  metadata["parameters"] = {{"width", shape.width},
                            {"height", shape.height},
                            {"method", "neural"},
                            {"theta_bins", K},
                            {"theta_bins_requested", options.bins.theta_bins},
                            {"phi_bins", shape.phi_bins},
                            {"theta_binning", theta_binning_name(options.bins.theta_binning)},
                            {"seed", kmeans_seed},
                            {"features", shape.features},
                            {"hidden", shape.hidden},
                            {"levels", shape.levels()},
                            {"min_footprint", kNeuralHistogramMinFootprint},
                            {"iterations", options.iterations},
                            {"batch", options.batch},
                            {"training_seed", options.seed}};
  metadata["conventions"] = normal_map_conventions();
  metadata["conventions"]["bins"] =
      "as kind histogram: theta = atan2(sqrt(x^2 + y^2), z) in theta_edges, phi = atan2(y, x) in [0, 2 pi) in N "
      "uniform bins; bin = theta_bin * phi_bins + phi_bin";
  metadata["conventions"]["model"] =
      "P(bin j N + i) = softmax(mlp 0)_j softmax(mlp 1 + j)_i of the features interpolated trilinearly at the "
      "footprint's centre and log2(side / 8), then log2(side / 8) / 8; footprints below 8 x 8 counted from texel_bins";
  nlohmann::json degrees = nlohmann::json::array();
  for (double e : baked.theta.edges) degrees.push_back(e * 180.0 / std::numbers::pi);
  metadata["statistics"] = {{"theta_edges_degrees", degrees},
                            {"distinct_theta_values", baked.theta.distinct_values},
                            {"lloyd_iterations", baked.theta.lloyd_iterations},
                            {"theta_rms_error", baked.theta.rms_error},
                            {"training_loss", baked.training_loss},
                            {"held_out_kl", baked.held_out_kl},
                            {"marginal_kl", baked.marginal_kl},
                            {"exact_table_bytes", baked.exact_table_bytes}};
  AssetWriter writer("neural_histogram", std::move(metadata));
  writer.add<double>(kHistogramThetaEdgesSection, {K + 1}, baked.theta.edges);
  writer.add<double>(kHistogramThetaCentresSection, {K}, baked.theta.centres);
  writer.add<uint16_t>(kNeuralHistogramTexelBinsSection, {shape.height, shape.width}, baked.texel_bins);
  writer.add<Imath::half>(kNeuralHistogramFeaturesSection, {shape.pyramid_texels(), shape.features},
                          halves(baked.model.features, "features"));
  writer.add<Imath::half>(kNeuralHistogramMlpSection, {shape.mlp_parameters()}, halves(baked.model.mlp, "networks"));
  return writer;
}

AssetWriter bake_neural_histogram_asset(const LoadedNormalMap& input, const NeuralHistogramBakeOptions& options,
                                        Progress& progress, const std::string& where) {
  const uint64_t kmeans_seed = histogram_seed(input.record.content_hash);
  return neural_histogram_asset_writer(input, options, kmeans_seed,
                                       bake_neural_histogram(input.map, options, kmeans_seed, progress, where));
}

}  // namespace mbk
