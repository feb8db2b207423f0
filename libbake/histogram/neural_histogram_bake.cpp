// The neural histogram bake (see neural_histogram_bake.h).
#include "libbake/histogram/neural_histogram_bake.h"

#include <random>

#include "libbake/histogram/bin_count_table.h"
#include "libbake/histogram/binned_ndf_source.h"
#include "libbake/histogram/histogram_kl.h"
#include "libbake/histogram/neural_histogram_training.h"

namespace mbk {

uint64_t neural_histogram_training_seed(uint64_t seed, uint64_t kmeans_seed) {
  return seed ^ (kmeans_seed * 0x9e3779b97f4a7c15ull);
}

BakedNeuralHistogram bake_neural_histogram(const NormalMap& map, const NeuralHistogramBakeOptions& options,
                                           uint64_t kmeans_seed, Progress& progress, const std::string& where) {
  BakedHistogram exact = bake_histogram(map, options.bins, kmeans_seed, progress, where);
  BakedNeuralHistogram out;
  out.theta = exact.theta;
  out.bins = exact.bins;
  const std::vector<uint32_t> bins = texel_bins(map, exact.bins);
  out.texel_bins.assign(bins.begin(), bins.end());  // K N <= 64 x 512 fits in 16 bits
  out.exact_table_bytes = histogram_table_bytes(map.width, map.height, exact.bins.count());
  const ExactBinnedNdf source({exact.bins, exact.theta.centres, exact.table()});
  const NeuralHistogramShape shape{
      map.width, map.height, exact.bins.theta_bins(), options.bins.phi_bins, options.features, kNeuralHistogramHidden};
  const uint64_t training_seed = neural_histogram_training_seed(options.seed, kmeans_seed);
  NeuralTrainingOutcome trained =
      train_neural_histogram(shape, source, {options.iterations, options.batch, training_seed}, progress);
  out.training_loss = trained.final_loss;
  out.model = std::move(trained.model);
  out.model.round_to_half();

  std::mt19937_64 random(training_seed + 1);
  const uint32_t B = exact.bins.count();
  std::vector<double> whole(B), p(B), q(B);
  source.footprint_probabilities(whole_map_footprint(map.width, map.height), whole);
  for (uint32_t n = 0; n < kNeuralHistogramHeldOutFootprints; ++n) {
    const SquareFootprint f = sample_training_footprint(random, map.width, map.height);
    source.footprint_probabilities(f, p);
    out.model.probabilities(f.x, f.y, double(square_footprint_texels(f).w), q);
    out.held_out_kl += histogram_kl(p, q) / kNeuralHistogramHeldOutFootprints;
    out.marginal_kl += histogram_kl(p, whole) / kNeuralHistogramHeldOutFootprints;
  }
  return out;
}

}  // namespace mbk
