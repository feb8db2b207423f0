// `microbake histogram --method neural` ([Shah24] Sec. 4.2): the adaptive bins of the exact bake (histogram_bake.h),
// every texel's bin (what footprints below 8 x 8 texels count), and a neural histogram (neural_histogram_model.h)
// trained on the CPU against the exact integral images, which exist only in memory during the bake
// (neural_histogram_training.h); weights and features are then rounded to f16, as the asset stores them, and the
// statistics measure the rounded model.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/asset_writer.h"
#include "libbake/core/progress.h"
#include "libbake/histogram/histogram_bake.h"
#include "libbake/histogram/neural_histogram_model.h"

namespace mbk {

// A 1024^2 map at 9 x 32 bins trains in 196 s on 2 cores with these (docs/commands/histogram.md), well inside
// the 15 minutes issue 13 allows.
inline constexpr uint32_t kNeuralHistogramDefaultIterations = 20000;
inline constexpr uint32_t kNeuralHistogramDefaultBatch = 512;
inline constexpr uint32_t kNeuralHistogramMaxIterations = 10000000;
inline constexpr uint32_t kNeuralHistogramMaxBatch = 65536;
// Footprints drawn (with another seed than training's) to measure the trained model's KL for the statistics.
inline constexpr uint32_t kNeuralHistogramHeldOutFootprints = 1024;

struct NeuralHistogramBakeOptions {
  HistogramBakeOptions bins;
  uint32_t features = kNeuralHistogramDefaultFeatures;
  uint32_t iterations = kNeuralHistogramDefaultIterations;
  uint32_t batch = kNeuralHistogramDefaultBatch;
  uint64_t seed = 1;  // --seed; training's generator is seeded from it and the input's k-means seed
};

struct BakedNeuralHistogram {
  ThetaBins theta;
  HistogramBins bins;
  std::vector<uint16_t> texel_bins;  // [H, W]
  NeuralHistogramModel model;        // rounded to f16
  double training_loss = 0.0;        // mean KL of the last batches (f32 model)
  double held_out_kl = 0.0;          // mean KL of the f16 model over held-out footprints
  double marginal_kl = 0.0;          // the same for the whole map's histogram as the prediction, for scale
  uint64_t exact_table_bytes = 0;
};

// The seed of training's generator for a --seed and a k-means seed (the input's content hash): the --seed xor the
// k-means seed times 0x9e3779b97f4a7c15 (mod 2^64); held-out footprints use this seed + 1.
uint64_t neural_histogram_training_seed(uint64_t seed, uint64_t kmeans_seed);

// Bakes a map of unit normals with z >= 0 (Error(invalid_input) for any other texel, or when the exact table the
// training reads would exceed kHistogramMaxTableBytes).
BakedNeuralHistogram bake_neural_histogram(const NormalMap& map, const NeuralHistogramBakeOptions& options,
                                           uint64_t kmeans_seed, Progress& progress, const std::string& where);

}  // namespace mbk
