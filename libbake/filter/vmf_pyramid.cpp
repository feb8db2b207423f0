// Builds vMF mixture MIP maps (see vmf_pyramid.h).
#include "libbake/filter/vmf_pyramid.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

#include "formats/error.h"
#include "formats/mip_levels.h"
#include "libbake/core/parallel.h"
#include "libbake/core/vmf_lobe.h"
#include "libbake/filter/vmf_normal_chunks.h"

namespace mbk {
namespace {

struct LevelGeometry {
  std::vector<std::vector<MipWeight>> wx, wy;  // finest texels under each column / row
};

LevelGeometry geometry(const NormalMap& map, uint32_t w, uint32_t h) {
  return {mip_texel_weights(w, map.width), mip_texel_weights(h, map.height)};
}

// visit(x, row, normal) for each normal texel (i, j) covers, with its area weight, rows outermost.
template <class Visit>
void for_each_texel_normal(const NormalMap& map, const LevelGeometry& g, uint32_t i, uint32_t j, Visit visit) {
  for (const MipWeight& y : g.wy[j])
    for (const MipWeight& x : g.wx[i])
      visit(x.index, y.index, WeightedNormal{map.at(x.index, y.index).cast<double>(), x.weight * y.weight});
}

// The normals (and features) texel (i, j) covers, with their area weights.
void gather(const NormalMap& map, const Image* features, const LevelGeometry& g, uint32_t i, uint32_t j,
            std::vector<WeightedNormal>& normals, std::vector<float>& texel_features) {
  normals.clear();
  texel_features.clear();
  for_each_texel_normal(map, g, i, j, [&](uint32_t x, uint32_t row, const WeightedNormal& n) {
    normals.push_back(n);
    if (features)
      for (uint32_t c = 0; c < features->channels; ++c) texel_features.push_back(features->at(x, row, c));
  });
}

void store_mixture(const std::vector<VmfComponent>& mixture, float* out) {
  for (size_t j = 0; j < mixture.size(); ++j) {
    const VmfComponent& c = mixture[j];
    out[4 * j] = float(c.alpha);
    // With alignment mu differs from r / |r|: store the fitted length along the aligned direction.
    const Vec3 r = c.alpha > 0.0 ? Vec3(c.r.norm() * c.mu) : Vec3::Zero();
    for (int a = 0; a < 3; ++a) out[4 * j + 1 + a] = float(c.alpha * r[a]);
  }
}

void store_features(const std::vector<VmfComponent>& mixture, const std::vector<double>& y, int F, float* out) {
  for (size_t j = 0; j < mixture.size(); ++j)
    for (int f = 0; f < F; ++f) out[j * F + size_t(f)] = float(mixture[j].alpha * y[j * F + size_t(f)]);
}

std::vector<VmfComponent> decode_texel(const VmfLevel& level, uint32_t i, uint32_t j, int J, double kappa_max) {
  std::vector<VmfComponent> mixture;
  const float* p = &level.lobes[(size_t(j) * level.width + i) * size_t(J) * 4];
  for (int l = 0; l < J; ++l) mixture.push_back(decode_lobe(p + 4 * l, kappa_max));
  return mixture;
}

// The non-empty lobes of the level k-1 texels a texel overlaps: the candidates its EM starts are chosen from.
std::vector<VmfComponent> child_lobes(const VmfLevel& finer, const std::vector<uint32_t>& xs,
                                      const std::vector<uint32_t>& ys, int J, double kappa_max) {
  std::vector<VmfComponent> candidates;
  for (uint32_t y : ys)
    for (uint32_t x : xs)
      for (const VmfComponent& c : decode_texel(finer, x, y, J, kappa_max))
        if (c.alpha > 0.0) candidates.push_back(c);
  return candidates;
}

// The lobe (index into mixture) each slot receives: greedy on alpha_a mu_a . t_s, largest score first; -1 leaves a
// slot empty.
std::vector<int> assign_slots(const std::vector<VmfComponent>& mixture, const std::vector<Vec3>& t) {
  const size_t J = mixture.size();
  std::vector<int> source(J, -1);
  std::vector<bool> lobe_used(J, false);
  for (size_t round = 0; round < J; ++round) {
    double best = -INFINITY;
    size_t ba = J, bs = J;
    for (size_t a = 0; a < J; ++a) {
      if (lobe_used[a] || mixture[a].alpha <= 0.0) continue;
      for (size_t s = 0; s < J; ++s) {
        if (source[s] >= 0) continue;
        const double score = mixture[a].alpha * mixture[a].mu.dot(t[s]);
        if (score > best) best = score, ba = a, bs = s;
      }
    }
    if (ba == J) break;
    source[bs] = int(ba);
    lobe_used[ba] = true;
  }
  return source;
}

// Whether two mixtures have the same lobes, in any order.
bool same_lobes(const std::vector<VmfComponent>& a, const std::vector<VmfComponent>& b) {
  const auto same = [](const VmfComponent& x, const VmfComponent& y) {
    return x.alpha == y.alpha && x.kappa == y.kappa && x.mu == y.mu && x.r == y.r;
  };
  const auto contained = [&](const std::vector<VmfComponent>& from, const std::vector<VmfComponent>& in) {
    return std::all_of(from.begin(), from.end(), [&](const VmfComponent& x) {
      return std::count_if(from.begin(), from.end(), [&](const VmfComponent& y) { return same(x, y); }) ==
             std::count_if(in.begin(), in.end(), [&](const VmfComponent& y) { return same(x, y); });
    });
  };
  return a.size() == b.size() && contained(a, b);
}

// Decreasing amplitude, empty lobes last (stable: ties keep their order).
std::vector<int> by_amplitude(const std::vector<VmfComponent>& mixture) {
  std::vector<int> order(mixture.size());
  for (size_t j = 0; j < order.size(); ++j) order[j] = int(j);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return mixture[size_t(a)].alpha > mixture[size_t(b)].alpha; });
  for (int& j : order)
    if (mixture[size_t(j)].alpha <= 0.0) j = -1;
  return order;
}

// Moves the `width` floats of each lobe to its slot (bit-exact: nothing is re-encoded).
void move_slots(float* texel, const std::vector<int>& source, int width) {
  const std::vector<float> before(texel, texel + source.size() * size_t(width));
  for (size_t s = 0; s < source.size(); ++s)
    for (int f = 0; f < width; ++f)
      texel[s * size_t(width) + size_t(f)] = source[s] < 0 ? 0.0f : before[size_t(source[s]) * width + size_t(f)];
}

// Adds alpha mu of each stored lobe of texel (i, j) to its slot's target (no concentration: the targets need none).
void add_targets(const VmfLevel& level, uint32_t i, uint32_t j, int J, std::vector<Vec3>& t) {
  const float* p = &level.lobes[(size_t(j) * level.width + i) * size_t(J) * 4];
  for (int s = 0; s < J; ++s, p += 4)
    if (p[0] > 0.0f) t[size_t(s)] += double(p[0]) * vmf_direction_from_premultiplied(p[0], Vec3(p[1], p[2], p[3]));
}

// The EM statistics of a level (its log-likelihood is measured on the stored lobes afterwards).
VmfLevelStatistics summarise(const std::vector<EmReport>& reports, const VmfLevel& level, int J) {
  VmfLevelStatistics s;
  if (reports.empty()) return s;
  double iterations = 0.0, converged = 0.0, reseeds = 0.0;
  for (const EmReport& r : reports) iterations += r.iterations, converged += r.converged, reseeds += r.reseeds;
  size_t empty = 0;
  for (size_t l = 0; l < level.lobes.size(); l += 4) empty += level.lobes[l] <= 0.0f;
  const double n = double(reports.size());
  s.mean_iterations = iterations / n;
  s.converged_fraction = converged / n;
  s.mean_reseeds = reseeds / n;
  s.empty_lobe_fraction = double(empty) / (n * J);
  return s;
}

// Texels in parallel, except on levels of few large texels, where each texel's EM splits its own normals
// across the threads instead (vmf_mixture.cpp's chunked E-step; nested parallel loops would run serially):
// fewer texels than 4 per thread, or fewer than 16 per thread when a texel's E-step has two chunks per thread
// (one slow texel would otherwise keep the other threads waiting at the end of the level). Either way each
// texel's result is the same.
template <typename F>
void for_each_texel(int64_t count, uint64_t normals_per_texel, F&& body) {
  const int64_t threads = thread_count();
  const bool splits = normals_per_texel >= 2 * kVmfSumChunk * uint64_t(threads);
  if (count >= 4 * threads && !(splits && count < 16 * threads)) {
    parallel_for(0, count, body);
  } else {
    for (int64_t t = 0; t < count; ++t) body(t);
  }
}

// Normals under one texel of a w x h level (at least).
uint64_t normals_per_texel(const NormalMap& map, uint32_t w, uint32_t h) {
  return uint64_t(map.width / w) * (map.height / h);
}

// The mean over a level's texels of sum_i w_i log g(n_i), g the stored (float) mixture decoded as a renderer
// decodes it: the mean log-likelihood per finest normal (every texel covers the same area).
double stored_log_likelihood(const NormalMap& map, const VmfLevel& level, int J, double kappa_max) {
  const LevelGeometry g = geometry(map, level.width, level.height);
  const size_t count = size_t(level.width) * level.height;
  std::vector<double> ll(count);
  for_each_texel(int64_t(count), normals_per_texel(map, level.width, level.height), [&](int64_t t) {
    const uint32_t i = uint32_t(size_t(t) % level.width), j = uint32_t(size_t(t) / level.width);
    const std::vector<VmfComponent> mixture = decode_texel(level, i, j, J, kappa_max);
    // The texel's normals in gather's order (for_each_texel_normal), kVmfSumChunk at a time: the E-step sums each chunk
    // on its own and adds the chunks in order (vmf_e_step.h), so this is its sum over the gathered normals to the bit,
    // without holding them all (the top level's texel covers the whole map: 8 MiB at 512^2 that stayed with the
    // thread).
    thread_local std::vector<WeightedNormal> chunk;  // reused: most texels of the fine levels are tiny
    chunk.clear();
    double sum = 0.0;
    for_each_texel_normal(map, g, i, j, [&](uint32_t, uint32_t, const WeightedNormal& n) {
      chunk.push_back(n);
      if (chunk.size() == kVmfSumChunk) sum += vmf_mixture_log_likelihood(chunk, mixture), chunk.clear();
    });
    if (!chunk.empty()) sum += vmf_mixture_log_likelihood(chunk, mixture);
    ll[size_t(t)] = sum;
  });
  double total = 0.0;
  for (double v : ll) total += v;
  return total / double(count);
}

}  // namespace

std::vector<WeightedNormal> vmf_texel_normals(const NormalMap& map, uint32_t w, uint32_t h, uint32_t i, uint32_t j) {
  std::vector<WeightedNormal> normals;
  std::vector<float> unused;
  gather(map, nullptr, geometry(map, w, h), i, j, normals, unused);
  return normals;
}

VmfComponent decode_lobe(const float* stored, double kappa_max) {
  const VmfLobeShape shape = vmf_lobe_from_premultiplied(stored[0], Vec3(stored[1], stored[2], stored[3]), kappa_max);
  VmfComponent c;
  if (shape.alpha <= 0.0) return c;
  c.alpha = shape.alpha;
  c.r = Vec3(stored[1], stored[2], stored[3]) / c.alpha;
  c.kappa = shape.kappa;
  c.mu = shape.mu;
  return c;
}

namespace {

// Side of the square tiles of the coherence pass (align_level).
constexpr uint32_t kAlignTile = 32;

// What every level's fit reads: the map, the optional per-texel features, the options.
struct PyramidFit {
  const NormalMap& map;
  const Image* features;
  const VmfBakeOptions& options;
  int J, F;
  double kappa_max;
};

// Level 0: one lobe per texel, alpha = 1, r = n.
VmfLevel finest_vmf_level(const PyramidFit& p) {
  const int J = p.J, F = p.F;
  VmfLevel finest{p.map.width, p.map.height, std::vector<float>(p.map.texels.size() * J * 4, 0.0f), {}, {}};
  if (F) finest.features.assign(p.map.texels.size() * J * F, 0.0f);
  for (size_t t = 0; t < p.map.texels.size(); ++t) {
    finest.lobes[t * J * 4] = 1.0f;
    for (int a = 0; a < 3; ++a) finest.lobes[t * J * 4 + 1 + a] = p.map.texels[t][a];
    for (int f = 0; f < F; ++f) finest.features[t * J * F + f] = p.features->pixels[t * F + f];
  }
  return finest;
}

// Texel (i, j) of `level`, fitted to the finest normals under it and stored there. Two starts from the child lobes
// (the texels of `finer` under it, `cx`/`cy`), the paper's farthest-apart seeds and the mass-weighted ones, each run
// by plain EM to a fixed point; the better (the paper's on a tie) then continues with the collapse guard. A texel of
// more normals than max_chunks runs both on its chunks (vmf_normal_chunks.h), and the guarded fit then continues by
// plain EM on the normals themselves.
EmReport fit_texel(const PyramidFit& p, const VmfLevel& finer, const std::vector<std::vector<MipWeight>>& cx,
                   const std::vector<std::vector<MipWeight>>& cy, const LevelGeometry& g, uint32_t i, uint32_t j,
                   VmfLevel& level) {
  const int J = p.J, F = p.F;
  std::vector<uint32_t> xs, ys;
  for (const MipWeight& x : cx[i]) xs.push_back(x.index);
  for (const MipWeight& y : cy[j]) ys.push_back(y.index);
  std::vector<WeightedNormal> normals;
  std::vector<float> y;
  gather(p.map, p.features, g, i, j, normals, y);
  std::vector<WeightedNormal> chunks;
  if (p.options.max_chunks > 0 && normals.size() > p.options.max_chunks)
    chunks = vmf_normal_chunks(normals, p.options.max_chunks);
  const std::span<const WeightedNormal> fitted = chunks.empty() ? std::span(normals) : std::span(chunks);
  const std::vector<VmfComponent> candidates = child_lobes(finer, xs, ys, J, p.kappa_max);
  std::vector<VmfComponent> mixture = farthest_apart_seeds(candidates, J, SeedRule::farthest);
  std::vector<VmfComponent> weighted = farthest_apart_seeds(candidates, J, SeedRule::mass_weighted);
  const std::vector<VmfComponent> mixture_before_fit = mixture;
  // SQUAREM on chunks too: lobes at the kappa cap (atoms) are held, not extrapolated (vmf_mixture.h), and it
  // halves the chunked E-steps with a fit no worse on the generated kinds and the real maps (docs/BENCHMARKS.md).
  EmOptions plain = p.options.em;
  plain.reseed = false;
  const EmReport first = fit_vmf_mixture(fitted, mixture, plain);
  int start_iterations = first.iterations;
  if (!same_lobes(mixture_before_fit, weighted)) {  // the same seeds (in another order) would give the same fit
    const EmReport second = fit_vmf_mixture(fitted, weighted, plain);
    if (second.log_likelihood > first.log_likelihood) mixture = std::move(weighted);
    start_iterations += second.iterations;
  }
  EmReport report = fit_vmf_mixture(fitted, mixture, p.options.em);
  report.iterations += start_iterations;
  if (!chunks.empty()) {
    const EmReport guarded_report = report;
    report = fit_vmf_mixture(normals, mixture, plain);
    report.iterations += guarded_report.iterations;
    report.reseeds = guarded_report.reseeds;
  }
  const size_t t = size_t(j) * level.width + i;
  store_mixture(mixture, &level.lobes[t * J * 4]);
  if (F) store_features(mixture, lobe_features(normals, y, F, mixture), F, &level.features[t * J * F]);
  return report;
}

// A w x h level fitted from the level below it (fit_texel per texel).
VmfLevel fit_level(const PyramidFit& p, const VmfLevel& finer, uint32_t w, uint32_t h) {
  const auto cx = mip_texel_weights(w, finer.width), cy = mip_texel_weights(h, finer.height);
  const LevelGeometry g = geometry(p.map, w, h);
  VmfLevel level{w, h, std::vector<float>(size_t(w) * h * p.J * 4), {}, {}};
  if (p.F) level.features.assign(size_t(w) * h * p.J * p.F, 0.0f);
  std::vector<EmReport> reports(size_t(w) * h);
  for_each_texel(int64_t(w) * h, normals_per_texel(p.map, w, h), [&](int64_t t) {
    reports[size_t(t)] = fit_texel(p, finer, cx, cy, g, uint32_t(t % w), uint32_t(t / w), level);
  });
  level.statistics = summarise(reports, level, p.J);
  return level;
}

// Coherence of level k (its parent k + 1 already aligned): each texel's lobes move to the slots that best match its
// parent's and its already-aligned neighbours' (assign_slots), the coarsest by amplitude; with options.em.align > 0
// the levels between are refitted from the permuted lobes towards those targets. Texels go by anti-diagonals, so
// the neighbours a texel reads are final.
void align_level(const PyramidFit& p, VmfPyramid& pyramid, size_t k) {
  const int J = p.J, F = p.F;
  VmfLevel& level = pyramid.levels[k];
  const uint32_t w = level.width, h = level.height;
  const bool top = k + 1 == pyramid.levels.size();
  const bool refit = p.options.em.align > 0.0 && k > 0 && !top;
  const LevelGeometry g = geometry(p.map, w, h);
  std::vector<EmReport> reports;
  if (refit) reports.resize(size_t(w) * h);
  const auto texel_body = [&](uint32_t i, uint32_t j) {
    const std::vector<VmfComponent> mixture = decode_texel(level, i, j, J, p.kappa_max);
    std::vector<Vec3> t(size_t(J), Vec3::Zero());
    if (!top) {
      const VmfLevel& parent = pyramid.levels[k + 1];
      add_targets(parent, uint32_t((i + 0.5) * parent.width / w), uint32_t((j + 0.5) * parent.height / h), J, t);
      if (i > 0) add_targets(level, i - 1, j, J, t);
      if (j > 0) add_targets(level, i, j - 1, J, t);
      if (i > 0 && j > 0) add_targets(level, i - 1, j - 1, J, t);
    }
    const std::vector<int> source = top ? by_amplitude(mixture) : assign_slots(mixture, t);
    const size_t texel = size_t(j) * w + i;
    if (!refit) {
      move_slots(&level.lobes[texel * J * 4], source, 4);
      if (F) move_slots(&level.features[texel * J * F], source, F);
      return;
    }
    std::vector<VmfComponent> permuted(static_cast<size_t>(J));
    for (int s = 0; s < J; ++s)
      if (source[size_t(s)] >= 0) permuted[size_t(s)] = mixture[size_t(source[size_t(s)])];
    std::vector<WeightedNormal> normals;
    std::vector<float> y;
    gather(p.map, p.features, g, i, j, normals, y);
    reports[texel] = fit_vmf_mixture(normals, permuted, p.options.em, t);
    store_mixture(permuted, &level.lobes[texel * J * 4]);
    if (F) store_features(permuted, lobe_features(normals, y, F, permuted), F, &level.features[texel * J * F]);
  };
  // Square tiles of texels by anti-diagonals of tiles, each tile in scanline order: the left, up and up-left
  // neighbours a texel reads are final, either earlier in its tile or in a tile of an earlier diagonal, so the
  // result is that of one texel at a time by anti-diagonals. Ordering alone is a few hundred operations per texel:
  // tiles of kAlignTile^2 texels keep the barriers few; refits are EM runs, one texel per tile.
  const uint32_t tile = refit ? 1 : kAlignTile, tw = (w + tile - 1) / tile, th = (h + tile - 1) / tile;
  for (uint32_t d = 0; d + 1 < tw + th; ++d) {
    const uint32_t first = d >= th ? d - th + 1 : 0, last = std::min(d, tw - 1);
    const auto tile_body = [&](int64_t offset) {
      const uint32_t ti = first + uint32_t(offset), tj = d - ti;
      for (uint32_t j = tj * tile; j < std::min(h, (tj + 1) * tile); ++j)
        for (uint32_t i = ti * tile; i < std::min(w, (ti + 1) * tile); ++i) texel_body(i, j);
    };
    for_each_texel(int64_t(last) + 1 - first, refit ? normals_per_texel(p.map, w, h) : uint64_t(tile) * tile,
                   tile_body);
  }
  if (refit) level.statistics = summarise(reports, level, J);
  level.statistics.mean_log_likelihood = stored_log_likelihood(p.map, level, J, p.kappa_max);
}

}  // namespace

VmfPyramid build_vmf_pyramid(const NormalMap& map, const Image* features, const VmfBakeOptions& options,
                             Progress& progress) {
  const int J = options.lobes;
  if (J < 1 || J > kVmfMaxLobes)
    throw Error(ExitCode::runtime_failure, "internal: " + std::to_string(J) + " vMF lobes");
  if (features && (features->width != map.width || features->height != map.height))
    throw Error(ExitCode::invalid_input,
                "material image is " + std::to_string(features->width) + "x" + std::to_string(features->height) +
                    ", the normal map " + std::to_string(map.width) + "x" + std::to_string(map.height),
                "--material");
  const PyramidFit p{map, features, options, J, features ? int(features->channels) : 0, options.em.kappa_max};
  const auto sizes = mip_level_sizes(map.width, map.height);
  VmfPyramid pyramid;
  pyramid.lobes = J;
  pyramid.feature_count = p.F;
  progress.start("vmf (fit levels, then align)", 2 * sizes.size());
  pyramid.levels.push_back(finest_vmf_level(p));
  progress.advance();
  for (size_t k = 1; k < sizes.size(); ++k) {  // fitting, finest to coarsest
    VmfLevel level = fit_level(p, pyramid.levels[k - 1], sizes[k].width, sizes[k].height);
    pyramid.levels.push_back(std::move(level));
    progress.advance();
  }
  for (size_t k = sizes.size(); k-- > 0;) {  // coherence, coarsest to finest
    align_level(p, pyramid, k);
    progress.advance();
  }
  progress.finish();
  return pyramid;
}

}  // namespace mbk
