// Training the neural histogram on the CPU ([Shah24] Sec. 5): Adam ([KB14]; step sizes in the .cpp) on the KL
// divergence D_KL(exact || predicted) over batches of random square footprints, centre uniform on the map and side
// S x with x ~ lambda e^(-lambda x), lambda = 16, S the map's longer side, clamped to [8, max(8, S)]; the exact
// histograms come from the exact source (the integral images of bin_count_table.h, the same code as the `histogram`
// asset). Eq. 11 splits the loss:
//   D_KL = sum_j p_j ln(p_j / q_j) + sum_j p_j sum_i p_i|j ln(p_i|j / q_i|j),
// so the theta network learns from every footprint and the phi network of bin j from those with p_j > 0, weighted
// by p_j. Forward and backward passes are hand-written (histogram_mlp.h), features receive the inputs' gradients
// through the trilinear weights.
//
// Deterministic whatever the thread count: the footprints of a batch are drawn serially from one std::mt19937_64,
// the batch is cut into chunks of kNeuralTrainingChunk footprints (independent of the thread count), each chunk's
// gradient is computed by one thread, and the chunks' gradients are summed serially in chunk order.
#pragma once

#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "libbake/core/progress.h"
#include "libbake/histogram/binned_ndf_source.h"
#include "libbake/histogram/neural_histogram_model.h"

namespace mbk {

inline constexpr uint32_t kNeuralTrainingChunk = 32;
inline constexpr double kNeuralTrainingLambda = 16.0;

struct NeuralTrainingOptions {
  uint32_t iterations = 1;
  uint32_t batch = 512;
  uint64_t seed = 0;  // the generator's seed (initial weights and footprints)
};

// One random footprint as training draws them, for a W x H map.
SquareFootprint sample_training_footprint(std::mt19937_64& random, uint32_t width, uint32_t height);

// The gradient of the summed D_KL(exact || predicted) over some footprints (side >= 8): the loss, dL/dmlp [M], and
// dL/dinput [F + 1, footprints] with each footprint's lookup, from which add_feature_gradient gives dL/dfeatures.
struct ChunkGradient {
  double loss = 0.0;
  std::vector<float> mlp;
  Eigen::MatrixXf input;
  std::vector<PyramidLookup> lookups;
};
void chunk_gradient(const NeuralHistogramModel& model, const BinnedNdfSource& exact,
                    std::span<const SquareFootprint> footprints, ChunkGradient& out);
// Adds a chunk's dL/dfeatures to `features` [P, F], footprint by footprint and corner by corner.
void add_feature_gradient(const ChunkGradient& chunk, uint32_t features_per_texel, std::span<float> features);

// A model of `shape` initialised from `random`: features uniform in [-1/2, 1/2], weights He-uniform (the output
// layer's scaled by 1/10), hidden biases 0 and output biases the logarithms of the whole map's P(theta_j) and
// P(phi_i | theta_j), so that training starts from the map's marginal histogram.
NeuralHistogramModel initial_neural_histogram(const NeuralHistogramShape& shape, const BinnedNdfSource& exact,
                                              std::mt19937_64& random);

struct NeuralTrainingOutcome {
  NeuralHistogramModel model;  // f32
  double final_loss = 0.0;     // mean KL per footprint over the last min(100, iterations) batches
};

// Trains a model of `shape` (whose bins are `exact`'s) and reports progress with the running loss.
NeuralTrainingOutcome train_neural_histogram(const NeuralHistogramShape& shape, const BinnedNdfSource& exact,
                                             const NeuralTrainingOptions& options, Progress& progress);

}  // namespace mbk
