// Training the neural histogram (see neural_histogram_training.h).
#include "libbake/histogram/neural_histogram_training.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "libbake/core/parallel.h"
#include "libbake/histogram/adam_optimizer.h"
#include "libbake/histogram/histogram_mlp.h"

namespace mbk {
namespace {

// Adam's step sizes at the first iteration, decaying exponentially to a tenth at the last. [Shah24] Sec. 5 uses
// 10^-3 for both over 20k batches of 2^18 footprints; our batches are 512 times smaller and our budget a few
// minutes, and larger steps learn much faster there (a 512^2 map, 4000 batches of 512, no decay: held-out KL 0.344
// with these, 0.355 with 10^-2 and 10^-3, against 0.839 for the whole map's histogram; 1000 batches at 10^-3: 0.553).
constexpr double kFeatureLearningRate = 3e-2, kNetworkLearningRate = 3e-3, kFinalLearningRateFactor = 0.1;

double uniform01(std::mt19937_64& random) { return double(random() >> 11) * 0x1p-53; }

}  // namespace

SquareFootprint sample_training_footprint(std::mt19937_64& random, uint32_t width, uint32_t height) {
  const double longer = std::max(width, height);
  SquareFootprint f;
  f.x = uniform01(random) * width;
  f.y = uniform01(random) * height;
  const double x = -std::log1p(-uniform01(random)) / kNeuralTrainingLambda;  // x ~ lambda e^(-lambda x)
  f.side = std::clamp(longer * x, double(kNeuralHistogramMinFootprint),
                      std::max(longer, double(kNeuralHistogramMinFootprint)));
  return f;
}

void chunk_gradient(const NeuralHistogramModel& model, const BinnedNdfSource& exact,
                    std::span<const SquareFootprint> footprints, ChunkGradient& out) {
  const NeuralHistogramShape& shape = model.shape;
  const uint32_t K = shape.theta_bins, N = shape.phi_bins, B = K * N;
  const Eigen::Index C = Eigen::Index(footprints.size());
  out.loss = 0.0;
  out.mlp.assign(shape.mlp_parameters(), 0.0f);
  out.lookups.resize(size_t(C));
  Eigen::MatrixXf x(shape.inputs(), C);
  std::vector<double> p(size_t(C) * B);
  Eigen::MatrixXf p_theta = Eigen::MatrixXf::Zero(K, C);
  for (Eigen::Index c = 0; c < C; ++c) {
    const SquareFootprint& f = footprints[size_t(c)];
    const double side = double(square_footprint_texels(f).w);
    out.lookups[size_t(c)] = pyramid_lookup(model.grid, f.x, f.y, side);
    model.network_input(out.lookups[size_t(c)], side, x.col(c).data());
    const std::span<double> pc(p.data() + size_t(c) * B, B);
    exact.footprint_probabilities(f, pc);
    for (uint32_t j = 0; j < K; ++j)
      for (uint32_t i = 0; i < N; ++i) p_theta(j, c) += float(pc[j * N + i]);
  }

  // The theta network, on every footprint: dL/dlogits = q - p.
  MlpPass pass;
  Eigen::MatrixXf dx;
  mlp_forward(shape.network(0), model.mlp.data(), x, pass);
  log_softmax_columns(pass.logits);
  Eigen::MatrixXf dlogits = pass.logits.array().exp().matrix() - p_theta;
  for (Eigen::Index c = 0; c < C; ++c)
    for (uint32_t j = 0; j < K; ++j)
      if (p_theta(j, c) > 0.0f) out.loss += p_theta(j, c) * (std::log(double(p_theta(j, c))) - pass.logits(j, c));
  mlp_backward(shape.network(0), model.mlp.data(), x, pass, dlogits, out.mlp.data(), dx);
  out.input = dx;

  // The phi network of theta bin j, on the footprints with p_j > 0: dL/dlogits = p_j (q_.|j - p_.|j).
  std::vector<Eigen::Index> columns;
  for (uint32_t j = 0; j < K; ++j) {
    columns.clear();
    for (Eigen::Index c = 0; c < C; ++c)
      if (p_theta(j, c) > 0.0f) columns.push_back(c);
    if (columns.empty()) continue;
    const Eigen::Index n = Eigen::Index(columns.size());
    Eigen::MatrixXf xj(shape.inputs(), n), target(N, n);
    for (Eigen::Index k = 0; k < n; ++k) {
      const Eigen::Index c = columns[size_t(k)];
      xj.col(k) = x.col(c);
      const double* pc = p.data() + size_t(c) * B + size_t(j) * N;
      double row = 0.0;
      for (uint32_t i = 0; i < N; ++i) row += pc[i];
      for (uint32_t i = 0; i < N; ++i) target(i, k) = float(pc[i] / row);
    }
    const uint32_t m = 1 + j;
    const float* parameters = model.mlp.data() + shape.network_offset(m);
    mlp_forward(shape.network(m), parameters, xj, pass);
    log_softmax_columns(pass.logits);
    dlogits = pass.logits.array().exp().matrix() - target;
    for (Eigen::Index k = 0; k < n; ++k) {
      const float weight = p_theta(j, columns[size_t(k)]);
      dlogits.col(k) *= weight;
      double kl = 0.0;
      for (uint32_t i = 0; i < N; ++i)
        if (target(i, k) > 0.0f) kl += target(i, k) * (std::log(double(target(i, k))) - pass.logits(i, k));
      out.loss += weight * kl;
    }
    mlp_backward(shape.network(m), parameters, xj, pass, dlogits, out.mlp.data() + shape.network_offset(m), dx);
    for (Eigen::Index k = 0; k < n; ++k) out.input.col(columns[size_t(k)]) += dx.col(k);
  }
}

void add_feature_gradient(const ChunkGradient& chunk, uint32_t F, std::span<float> features) {
  for (size_t c = 0; c < chunk.lookups.size(); ++c) {
    const PyramidLookup& l = chunk.lookups[c];
    const float* d = chunk.input.col(Eigen::Index(c)).data();
    for (int k = 0; k < 8; ++k) {
      float* g = features.data() + l.texel[k] * F;
      for (uint32_t i = 0; i < F; ++i) g[i] += l.weight[k] * d[i];
    }
  }
}

NeuralHistogramModel initial_neural_histogram(const NeuralHistogramShape& shape, const BinnedNdfSource& exact,
                                              std::mt19937_64& random) {
  NeuralHistogramModel model(shape);
  for (float& v : model.features) v = float(uniform01(random) - 0.5);
  const uint32_t K = shape.theta_bins, N = shape.phi_bins;
  std::vector<double> whole(size_t(K) * N);
  exact.footprint_probabilities(whole_map_footprint(shape.width, shape.height), whole);
  for (uint32_t m = 0; m < shape.networks(); ++m) {
    const MlpShape s = shape.network(m);
    float* p = model.mlp.data() + shape.network_offset(m);
    auto he_uniform = [&](uint64_t at, uint64_t count, uint32_t fan_in, double scale) {
      const double bound = scale * std::sqrt(6.0 / fan_in);
      for (uint64_t i = 0; i < count; ++i) p[at + i] = float((2.0 * uniform01(random) - 1.0) * bound);
    };
    he_uniform(s.w1(), uint64_t(s.hidden) * s.in, s.in, 1.0);
    he_uniform(s.w2(), uint64_t(s.hidden) * s.hidden, s.hidden, 1.0);
    he_uniform(s.w3(), uint64_t(s.out) * s.hidden, s.hidden, 0.1);
    for (uint32_t o = 0; o < s.out; ++o) {
      double mass = 0.0;
      if (m == 0)
        for (uint32_t i = 0; i < N; ++i) mass += whole[o * N + i];
      else {
        double row = 0.0;
        for (uint32_t i = 0; i < N; ++i) row += whole[(m - 1) * N + i];
        mass = row > 0.0 ? whole[(m - 1) * N + o] / row : 1.0 / N;
      }
      p[s.b3() + o] = float(std::log(std::max(mass, 1e-6)));
    }
  }
  return model;
}

NeuralTrainingOutcome train_neural_histogram(const NeuralHistogramShape& shape, const BinnedNdfSource& exact,
                                             const NeuralTrainingOptions& options, Progress& progress) {
  std::mt19937_64 random(options.seed);
  NeuralTrainingOutcome outcome{initial_neural_histogram(shape, exact, random), 0.0};
  NeuralHistogramModel& model = outcome.model;
  AdamOptimizer mlp_adam(model.mlp.size()), feature_adam(model.features.size());
  const uint32_t chunks = (options.batch + kNeuralTrainingChunk - 1) / kNeuralTrainingChunk;
  std::vector<ChunkGradient> work(chunks);
  std::vector<SquareFootprint> batch(options.batch);
  std::vector<float> mlp_gradient(model.mlp.size()), feature_gradient(model.features.size());
  const uint32_t tail = std::min<uint32_t>(100, options.iterations);
  double tail_loss = 0.0, shown_loss = -1.0;
  progress.start("training", options.iterations);
  for (uint32_t iteration = 0; iteration < options.iterations; ++iteration) {
    for (SquareFootprint& f : batch) f = sample_training_footprint(random, shape.width, shape.height);
    parallel_for(0, chunks, [&](int64_t c) {
      const size_t begin = size_t(c) * kNeuralTrainingChunk;
      const size_t count = std::min<size_t>(kNeuralTrainingChunk, batch.size() - begin);
      chunk_gradient(model, exact, std::span(batch).subspan(begin, count), work[size_t(c)]);
    });
    std::fill(mlp_gradient.begin(), mlp_gradient.end(), 0.0f);
    std::fill(feature_gradient.begin(), feature_gradient.end(), 0.0f);
    double loss = 0.0;
    for (const ChunkGradient& chunk : work) {
      loss += chunk.loss;
      for (size_t i = 0; i < mlp_gradient.size(); ++i) mlp_gradient[i] += chunk.mlp[i];
      add_feature_gradient(chunk, shape.features, feature_gradient);
    }
    const float scale = 1.0f / float(options.batch);  // the mean over the batch
    for (float& g : mlp_gradient) g *= scale;
    for (float& g : feature_gradient) g *= scale;
    const double decay = std::pow(kFinalLearningRateFactor, double(iteration) / double(options.iterations));
    mlp_adam.step(model.mlp, mlp_gradient, kNetworkLearningRate * decay);
    feature_adam.step(model.features, feature_gradient, kFeatureLearningRate * decay);
    loss /= options.batch;
    if (iteration + tail >= options.iterations) tail_loss += loss;
    shown_loss = shown_loss < 0.0 ? loss : 0.98 * shown_loss + 0.02 * loss;
    char note[64];
    std::snprintf(note, sizeof note, "KL %.4f", shown_loss);
    progress.note(note);
    progress.advance();
  }
  progress.finish();
  outcome.final_loss = tail_loss / tail;
  return outcome;
}

}  // namespace mbk
