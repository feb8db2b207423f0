// Multiscale synthesis of windows (see multiscale_synthesis.h).
#include "libbake/synth/multiscale_synthesis.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "formats/error.h"
#include "libbake/core/hash.h"
#include "libbake/core/parallel.h"
#include "libbake/core/uninitialized_vector.h"
#include "libbake/synth/loop_transitions.h"

namespace mbk {
namespace {

constexpr int kReach = 2;  // the 5 x 5 neighbourhood's radius
constexpr uint32_t kMaxLevel = 40;

constexpr int kLanes = 4;                // candidates whose errors are summed side by side
constexpr uint32_t kMaxCandidates = 16;  // K at most (formats/graph_layout.h)
// kLanes floats or doubles side by side (GCC vector extensions: SSE2 pairs on baseline x86-64, one AVX register where
// the target has it); element-wise IEEE operations, so each lane computes exactly what the scalar code does.
typedef float LaneFloats __attribute__((vector_size(kLanes * sizeof(float))));
typedef double LaneDoubles __attribute__((vector_size(kLanes * sizeof(double))));

// Trivially constructible, so a level's buffer is not zero-filled before the parallel loop that writes every pixel.
struct Pixel {
  uint32_t e, k, x, y;  // texel pointer
  float R[4];           // cumulative transfer offset
  float loop[4];        // the share of R that loop transitions added (fades: loop_transitions.h)
  bool magnified;       // its parent was stuck at the finest level (see stuck())
};
using Pixels = UninitializedVector<Pixel>;

struct Region {
  int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int64_t width() const { return x1 - x0; }
  int64_t height() const { return y1 - y0; }
  Region grown(int64_t by) const { return {x0 - by, y0 - by, x1 + by, y1 + by}; }
};

int64_t floor_div2(int64_t v) { return v >= 0 ? v / 2 : -((-v + 1) / 2); }

// v mod m for the power-of-two exemplar side m (formats/graph_layout.h checks it), also for negative v.
uint32_t wrap(int64_t v, uint32_t m) { return uint32_t(uint64_t(v) & (m - 1)); }

// The transfer offset of a candidate that has none (the same exemplar's texel, or correction without transfer).
constexpr float kNoOffset[4] = {0, 0, 0, 0};

// A texel competing in correction: pointer, transfer offset and the contrast a loop matches at (0: no loop).
struct Candidate {
  uint32_t e, k, x, y;
  const float* b;
  double contrast;
};

// The 5 x 5 samples of kLanes candidates (their toroidal rows and columns in their stack levels) and their transfer
// offsets per channel.
struct LaneSamples {
  const float* row[kLanes][2 * kReach + 1];
  size_t column[kLanes][2 * kReach + 1];
  LaneFloats b[4];
};

// Eq. 5.1's sums of the lanes against the neighbourhood n, as one vector: each lane's operations are the scalar
// error's, in its order (float texel + offset, then the double difference squared and added), so each sum is bit for
// bit the one-by-one sum (no contraction into fused multiply-adds: ISO C++ mode). Stops after the first row of samples
// at which every lane has reached bound.
template <uint32_t C>
[[gnu::always_inline]] inline void lane_sums(const LaneSamples& s, const double* n, double bound, double* out) {
  LaneDoubles sum = {0, 0, 0, 0};
  for (int dy = 0; dy < 2 * kReach + 1; ++dy) {
    for (int dx = 0; dx < 2 * kReach + 1; ++dx, n += C) {
      const float* v[kLanes];
      for (int l = 0; l < kLanes; ++l) v[l] = s.row[l][dy] + s.column[l][dx];
      for (uint32_t ch = 0; ch < C; ++ch) {
        const LaneFloats value = LaneFloats{v[0][ch], v[1][ch], v[2][ch], v[3][ch]} + s.b[ch];
        const LaneDoubles d = n[ch] - __builtin_convertvector(value, LaneDoubles);
        sum += d * d;
      }
    }
    if (sum[0] >= bound && sum[1] >= bound && sum[2] >= bound && sum[3] >= bound) break;  // checked once a row
  }
  for (int l = 0; l < kLanes; ++l) out[l] = sum[l];
}

// lane_sums for C channels, compiled for AVX2 as well as the baseline and chosen once at load (the same bits either
// way: the lanes' operations are element-wise IEEE operations).
[[gnu::target_clones("avx2", "default")]] void lane_sums(const LaneSamples& s, const double* n, double bound,
                                                         uint32_t C, double* out) {
  switch (C) {  // the channel count as a constant: unrolled sample loops
    case 1:
      return lane_sums<1>(s, n, bound, out);
    case 2:
      return lane_sums<2>(s, n, bound, out);
    case 3:
      return lane_sums<3>(s, n, bound, out);
    default:
      return lane_sums<4>(s, n, bound, out);
  }
}

class Synthesizer {
 public:
  Synthesizer(const GraphTables& g, const SynthesisOptions& o)
      : g_(g),
        o_(o),
        L_(g.layout.levels - 1),
        admissible_(admissible_levels(g.layout.exemplars, g.layout.edges, g.layout.levels)),
        loops_(loop_contrast_of_stacks(g.stacks.data(), g.layout.exemplars, g.layout.levels, g.layout.side,
                                       g.layout.channels)),
        admits_stride_(size_t(g.layout.exemplars) * g.layout.levels),
        admits_(admits_stride_ * admits_stride_, 0) {
    const uint32_t levels = g.layout.levels;
    for (uint32_t i = 0; i < g.layout.exemplars; ++i)
      for (uint32_t k = 0; k < levels; ++k)
        for (const StackLevel& l : admissible_[i][k])
          if (loop_transition_allowed(i, k, l.exemplar, l.level, L_))
            admits_[(size_t(i) * levels + k) * admits_stride_ + size_t(l.exemplar) * levels + l.level] = 1;
  }

  Image run(Progress& progress, SynthesisStatistics* stats) {
    const Region window{o_.x, o_.y, o_.x + o_.width, o_.y + o_.height};
    const int64_t pad = int64_t(kReach) * 4 * o_.passes;
    // The regions, finest first: level t computes region[t]; its parents must cover what upsampling reads.
    std::vector<Region> region(o_.level + 1);
    region[o_.level] = window.grown(pad);
    for (uint32_t t = o_.level; t > 0; --t) {
      const Region& c = region[t];
      region[t - 1] =
          Region{floor_div2(c.x0) - 1, floor_div2(c.y0) - 1, floor_div2(c.x1 - 1) + 2, floor_div2(c.y1 - 1) + 2}.grown(
              pad);
    }
    uint64_t work = 0;  // pixels over all levels: the finest level is most of it
    for (const Region& r : region) work += uint64_t(r.width() * r.height());
    progress.start("synthesis", work);
    // Buffers for the largest level (a coarse region can be the larger one: every level grows by the same padding).
    size_t largest = 0, largest_parity = 0;
    for (const Region& r : region) {
      largest = std::max(largest, size_t(r.width() * r.height()));
      largest_parity = std::max(largest_parity, size_t((r.height() / 2 + 1) * (r.width() / 2 + 1)));
    }
    corrected_.resize(largest_parity);
    colour_.reserve(largest * g_.layout.channels);
    // Every pixel at texel (0, 0) of the root's level 0, without offsets.
    Pixels level(size_t(region[0].width() * region[0].height()), Pixel{g_.layout.root, 0, 0, 0, {}, {}, false});
    for (uint32_t t = 0; t <= o_.level; ++t) {
      if (t > 0) level = upsample(level, region[t - 1], region[t]);
      jitter(level, region[t], t);
      fill_colours(level, region[t]);
      for (uint32_t pass = 0; pass < o_.passes; ++pass)
        for (int parity = 0; parity < 4; ++parity) correct(level, region[t], parity, t == o_.level);
      if (stats) stats->matching_error.push_back(mean_error(level, region[t]));
      progress.advance(level.size());
    }
    progress.finish();
    const uint32_t C = g_.layout.channels;
    Image out{o_.width, o_.height, C, std::vector<float>(size_t(o_.width) * o_.height * C)};
    const Region& r = region[o_.level];
    parallel_for(0, int64_t(o_.height), [&](int64_t y) {
      for (uint32_t x = 0; x < o_.width; ++x) {
        const Pixel& p = level[size_t(y + pad) * r.width() + (x + pad)];
        for (uint32_t c = 0; c < C; ++c) out.at(x, y, c) = value(p.e, p.k, p.x, p.y, c) + p.R[c];
        if (g_.layout.normal_map && C == 3) {  // unit normals; a vanishing vector (cancelled blur) faces out
          float* n = &out.pixels[(size_t(y) * o_.width + x) * 3];
          const double len = std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
          for (int c = 0; c < 3; ++c) n[c] = len > 0.0 ? float(n[c] / len) : (c == 2 ? 1.0f : 0.0f);
        }
      }
    });
    return out;
  }

 private:
  uint32_t spacing(uint32_t k) const { return 1u << (L_ - k); }
  float value(uint32_t e, uint32_t k, uint32_t x, uint32_t y, uint32_t c) const {
    return g_.stacks[g_.texel(e, k, x, y) * g_.layout.channels + c];
  }
  static const Pixel& at(const Pixels& s, const Region& r, int64_t x, int64_t y) {
    x = std::clamp(x, r.x0, r.x1 - 1);
    y = std::clamp(y, r.y0, r.y1 - 1);
    return s[size_t((y - r.y0) * r.width() + (x - r.x0))];
  }

  Pixels upsample(const Pixels& parents, const Region& pr, const Region& cr) const {
    const uint32_t m = g_.layout.side, C = g_.layout.channels;
    Pixels children(size_t(cr.width() * cr.height()));
    parallel_for(cr.y0, cr.y1, [&](int64_t y) {
      for (int64_t x = cr.x0; x < cr.x1; ++x) {
        const Pixel& parent = at(parents, pr, floor_div2(x), floor_div2(y));
        Pixel& c = children[size_t((y - cr.y0) * cr.width() + (x - cr.x0))];
        c.e = parent.e;
        c.k = std::min(parent.k + 1, L_);
        // A pixel stuck at its exemplar's finest level magnifies it: its children keep its texel (h < 1).
        c.magnified = stuck(parent);
        const double h = c.magnified ? 0.0 : spacing(c.k);
        const double dx = (x - 2 * floor_div2(x)) - 0.5, dy = (y - 2 * floor_div2(y)) - 0.5;
        c.x = wrap(int64_t(parent.x) + int64_t(std::floor(h * dx)), m);
        c.y = wrap(int64_t(parent.y) + int64_t(std::floor(h * dy)), m);
        // R bilinear in the four nearest parents: the child's centre at parent coordinates (x + 1/2) / 2 - 1/2,
        // in integers (exact at any position): an even child 2a sits between parents a - 1 and a at weight 3/4
        // on a, an odd child 2a + 1 between a and a + 1 at weight 1/4 on a + 1.
        const int64_t px = floor_div2(x) - ((x & 1) == 0 ? 1 : 0), py = floor_div2(y) - ((y & 1) == 0 ? 1 : 0);
        const double ax = (x & 1) == 0 ? 0.75 : 0.25, ay = (y & 1) == 0 ? 0.75 : 0.25;
        const Pixel &p00 = at(parents, pr, px, py), &p10 = at(parents, pr, px + 1, py),
                    &p01 = at(parents, pr, px, py + 1), &p11 = at(parents, pr, px + 1, py + 1);
        const double w00 = (1 - ax) * (1 - ay), w10 = ax * (1 - ay), w01 = (1 - ax) * ay, w11 = ax * ay;
        for (uint32_t ch = 0; ch < C; ++ch) {
          const double R = w00 * p00.R[ch] + w10 * p10.R[ch] + w01 * p01.R[ch] + w11 * p11.R[ch];
          const double loop = w00 * p00.loop[ch] + w10 * p10.loop[ch] + w01 * p01.loop[ch] + w11 * p11.loop[ch];
          // The loop share fades (loop_transitions.h); exact when there is none.
          c.R[ch] = float(R - (1.0 - kLoopOffsetKept) * loop);
          c.loop[ch] = float(kLoopOffsetKept * loop);
        }
        for (uint32_t ch = C; ch < 4; ++ch) c.R[ch] = c.loop[ch] = 0.0f;  // unused channels: defined bytes
      }
    });
    return children;
  }

  void jitter(Pixels& s, const Region& r, uint32_t t) const {
    const double rt = o_.jitter[std::min<size_t>(t, o_.jitter.size() - 1)];
    if (rt == 0.0) return;
    const uint32_t m = g_.layout.side;
    parallel_for(r.y0, r.y1, [&](int64_t y) {
      for (int64_t x = r.x0; x < r.x1; ++x) {
        Pixel& p = s[size_t((y - r.y0) * r.width() + (x - r.x0))];
        if (stuck(p)) continue;  // below one texel of spacing there is nothing to jitter by
        // Both halves of the 64-bit coordinates: no period of 2^32 pixels.
        const uint32_t h = hash4(hash_combine(o_.seed, t), uint32_t(x) ^ pcg_hash(uint32_t(uint64_t(x) >> 32)),
                                 uint32_t(y), pcg_hash(uint32_t(uint64_t(y) >> 32)));
        const double hx = 2.0 * unit_from_hash(h) - 1.0, hy = 2.0 * unit_from_hash(pcg_hash(h ^ 0x6a09e667u)) - 1.0;
        const double hk = spacing(p.k);
        p.x = wrap(int64_t(p.x) + int64_t(std::floor(hk * hx * rt + 0.5)), m);
        p.y = wrap(int64_t(p.y) + int64_t(std::floor(hk * hy * rt + 0.5)), m);
      }
    });
  }

  // The synthesized colour E(S[p]) + R_p of every pixel of the level (what neighbourhoods read), kept by correct().
  void fill_colours(const Pixels& s, const Region& r) {
    const uint32_t C = g_.layout.channels;
    colour_.resize(s.size() * C);
    parallel_for(0, r.height(), [&](int64_t y) {
      for (size_t i = size_t(y * r.width()); i < size_t((y + 1) * r.width()); ++i) set_colour(s[i], i);
    });
  }
  void set_colour(const Pixel& p, size_t i) {
    const uint32_t C = g_.layout.channels;
    const float* v = &g_.stacks[g_.texel(p.e, p.k, p.x, p.y) * C];
    for (uint32_t c = 0; c < C; ++c) colour_[i * C + c] = v[c] + p.R[c];
  }

  // The synthesized 5 x 5 neighbourhood of p in p's own colour space: E(S[p + Delta]) + R_{p + Delta} - R_p.
  void neighbourhood(const Pixels& s, const Region& r, int64_t x, int64_t y, double* out) const {
    const uint32_t C = g_.layout.channels;
    const Pixel& self = at(s, r, x, y);
    int64_t column[2 * kReach + 1];  // clamped to the region, as at()
    for (int d = -kReach; d <= kReach; ++d) column[d + kReach] = std::clamp(x + d, r.x0, r.x1 - 1) - r.x0;
    for (int dy = -kReach; dy <= kReach; ++dy) {
      const float* row = &colour_[size_t((std::clamp(y + dy, r.y0, r.y1 - 1) - r.y0) * r.width()) * C];
      for (int64_t cx : column) {
        const float* v = row + size_t(cx) * C;
        for (uint32_t c = 0; c < C; ++c) *out++ = v[c] - self.R[c];
      }
    }
  }

  // Eq. 5.1 for the candidate texel (e, k, cx, cy) with offset b, against the neighbourhood n (as doubles); the sum
  // stops once it reaches `bound` (the candidate can no longer win: only a strictly smaller error replaces the best).
  double error(const double* n, uint32_t e, uint32_t k, int64_t cx, int64_t cy, const float* b,
               double bound = std::numeric_limits<double>::infinity(), double contrast = 0.0) const {
    const uint32_t m = g_.layout.side, C = g_.layout.channels;
    const int64_t h = spacing(k);
    const float* level = &g_.stacks[g_.texel(e, k, 0, 0) * C];
    size_t column[2 * kReach + 1], row[2 * kReach + 1];  // the toroidal sample lines, in floats from `level`
    for (int d = -kReach; d <= kReach; ++d) {
      column[d + kReach] = size_t(wrap(cx + d * h, m)) * C;
      row[d + kReach] = size_t(wrap(cy + d * h, m)) * m * C;
    }
    if (contrast > 0.0) {  // a loop transition (loop_transitions.h)
      float d[25 * 4];
      float* out = d;
      for (size_t y : row)
        for (size_t x : column)
          for (uint32_t c = 0; c < C; ++c) *out++ = level[y + x + c];
      bring_to_contrast(d, C, contrast);
      double sum = 0.0;
      for (uint32_t j = 0; j < 25 * C; ++j) {
        const double diff = n[j] - (d[j] + b[j % C]);
        sum += diff * diff;
        if (sum >= bound) return sum;
      }
      return sum;
    }
    double sum = 0.0;
    for (size_t y : row)
      for (size_t x : column) {
        const float* v = level + y + x;
        for (uint32_t c = 0; c < C; ++c) {
          const double d = *n++ - (v[c] + b[c]);
          sum += d * d;
        }
        if (sum >= bound) return sum;
      }
    return sum;
  }

  // The index of the first candidate of least Eq. 5.1 error (-1 for none). Consecutive candidates without a loop
  // transform are summed in groups of kLanes, each sum in the order error() sums, and a group stops once every lane
  // has reached the best error of the earlier groups (a candidate there cannot win): the same sums, so the same
  // winner, as evaluating them one by one; the independent sums side by side keep the floating-point units busy.
  int first_best(const double* n, const Candidate* competing, int count) const {
    double best_error = std::numeric_limits<double>::infinity();
    int best = -1;
    for (int i = 0; i < count;) {
      const Candidate& c = competing[i];
      if (c.contrast > 0.0) {
        const double err = error(n, c.e, c.k, c.x, c.y, c.b, best_error, c.contrast);
        if (err < best_error) best_error = err, best = i;
        ++i;
        continue;
      }
      int lanes = 0;
      while (lanes < kLanes && i + lanes < count && competing[i + lanes].contrast == 0.0) ++lanes;
      double err[kLanes];
      lane_errors(n, competing + i, lanes, best_error, err);
      for (int j = 0; j < lanes; ++j)
        if (err[j] < best_error) best_error = err[j], best = i + j;
      i += lanes;
    }
    return best;
  }

  // error() of up to kLanes candidates side by side (no loop transform), stopped (at values >= bound) after the first
  // row of samples at which all have reached bound.
  void lane_errors(const double* n, const Candidate* c, int lanes, double bound, double* out) const {
    const uint32_t m = g_.layout.side, C = g_.layout.channels;
    LaneSamples samples;
    for (int l = 0; l < kLanes; ++l) {
      const Candidate& cl = c[std::min(l, lanes - 1)];  // spare lanes repeat the last candidate
      const int64_t h = spacing(cl.k);
      const float* level = &g_.stacks[g_.texel(cl.e, cl.k, 0, 0) * C];
      for (int d = -kReach; d <= kReach; ++d) {
        samples.row[l][d + kReach] = level + size_t(wrap(cl.y + d * h, m)) * m * C;
        samples.column[l][d + kReach] = size_t(wrap(cl.x + d * h, m)) * C;
      }
      for (uint32_t ch = 0; ch < C; ++ch) samples.b[ch][l] = cl.b[ch];
    }
    double sum[kLanes];
    lane_sums(samples, n, bound, C, sum);
    for (int l = 0; l < lanes; ++l) out[l] = sum[l];
  }

  // The candidates competing for the pixel whose 3 x 3 neighbours (row by row, around[4] the pixel) are given, in
  // the order that breaks ties (Eq. 5.1: the earliest wins), into `competing`; returns how many.
  int competing_candidates(const Pixel* const around[9], bool output_level, Candidate* competing) const {
    const uint32_t m = g_.layout.side, C = g_.layout.channels, K = g_.layout.candidates;
    const Pixel& self = *around[4];
    const uint32_t* admits = &admits_[(size_t(self.e) * g_.layout.levels + self.k) * admits_stride_];
    // Only texels of the admissible levels of the pixel's level compete (Sec. 5.2.1.2): at an exemplar's
    // finest level that excludes the pixel's own texel, so correction moves it on to a finer exemplar (or,
    // through a loop, back up its own stack) instead of getting stuck; a level with no admissible level
    // keeps its pixel.
    const auto allowed = [&](uint32_t e, uint32_t k) {
      return admits[size_t(e) * g_.layout.levels + k] != 0 ||
             (output_level && e == self.e && k == L_ && self.k == L_ && !self.magnified);
    };
    // Deviation [Han08]: a texel one of the 8 neighbours already holds on the same level is not taken (a
    // coherent neighbour holds a texel one spacing away; the same texel twice magnifies it, and a region of one
    // texel is its own best match at every later level: issue 18's plateaus).
    uint64_t held[8];  // the 8 neighbours' texels (texel_key)
    for (int i = 0, j = 0; i < 9; ++i)
      if (i != 4) held[j++] = texel_key(around[i]->e, around[i]->k, around[i]->x, around[i]->y);
    const auto held_by_neighbour = [&](uint64_t key) {
      bool found = false;
      for (uint64_t h : held) found |= h == key;
      return found;
    };
    int count = 0;  // the pixel's own texel first
    const uint64_t self_key = texel_key(self.e, self.k, self.x, self.y);
    if (allowed(self.e, self.k) && !held_by_neighbour(self_key))
      competing[count++] = {self.e, self.k, self.x, self.y, kNoOffset, 0.0};
    // Coherent neighbours often propose the same texel with the same offset: evaluate each once.
    struct Seen {
      uint64_t key;
      const float* b;
    };
    Seen seen[64];
    seen[0] = {self_key, kNoOffset};
    int seen_count = 1;
    // One bit per hashed key: a key whose bit is clear is in no entry of `seen`, and skips the scan.
    const auto key_bit = [](uint64_t key) { return uint64_t(1) << ((key * 0x9e3779b97f4a7c15ull) >> 58); };
    uint64_t seen_bits = key_bit(self_key);
    const auto consider = [&](uint32_t e, uint32_t k, int64_t cx, int64_t cy, const float* b) {
      if (!allowed(e, k)) return;
      const uint32_t wx = wrap(cx, m), wy = wrap(cy, m);
      const uint64_t key = texel_key(e, k, wx, wy), bit = key_bit(key);
      if (seen_bits & bit)
        for (int i = 0; i < seen_count; ++i)
          if (seen[i].key == key && (seen[i].b == b || std::equal(b, b + C, seen[i].b))) return;
      seen_bits |= bit;
      if (seen_count < 64) seen[seen_count++] = {key, b};
      if (held_by_neighbour(key)) return;
      competing[count++] = {e, k, wx, wy, b, loops_.target(self.e, self.k, e, k)};
    };
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const Pixel& q = *around[(dy + 1) * 3 + dx + 1];
        const int64_t hq = spacing(q.k);
        if (dx != 0 || dy != 0) consider(q.e, q.k, int64_t(q.x) - dx * hq, int64_t(q.y) - dy * hq, kNoOffset);
        const size_t slots = g_.texel(q.e, q.k, q.x, q.y) * K;
        for (uint32_t c = 0; c < K; ++c) {
          const uint32_t* cand = &g_.candidates[(slots + c) * 4];
          if (cand[0] == kGraphNoCandidate) continue;
          const int64_t hl = spacing(cand[1]);
          const float* b = o_.correct_inconsistency ? &g_.transfer[(slots + c) * C] : kNoOffset;
          consider(cand[0], cand[1], int64_t(cand[2]) - dx * hl, int64_t(cand[3]) - dy * hl, b);
        }
      }
    return count;
  }

  // The pixel at (x, y) after correction: the best of the competing candidates, its offsets added (the pixel itself
  // when none competes).
  Pixel corrected_pixel(const Pixels& s, const Region& r, int64_t x, int64_t y, bool output_level) const {
    const uint32_t C = g_.layout.channels, K = g_.layout.candidates;
    const Pixel* around[9];  // the 3 x 3 neighbours, row by row (around[4] is the pixel)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) around[(dy + 1) * 3 + dx + 1] = &at(s, r, x + dx, y + dy);
    for (const Pixel* q : around)  // their candidate slots are read below: fetched while n is gathered
      __builtin_prefetch(&g_.candidates[g_.texel(q->e, q->k, q->x, q->y) * K * 4]);
    double n[25 * 4];
    neighbourhood(s, r, x, y, n);
    const Pixel& self = *around[4];
    Candidate competing[1 + 8 + 9 * kMaxCandidates];
    const int count = competing_candidates(around, output_level, competing);
    Pixel best = self;
    const int winner = first_best(n, competing, count);
    if (winner >= 0) {
      const Candidate& w = competing[winner];
      best.e = w.e;
      best.k = w.k;
      best.x = w.x;
      best.y = w.y;
      for (uint32_t c = 0; c < C; ++c) {
        best.R[c] = self.R[c] + w.b[c];
        best.loop[c] = w.contrast > 0.0 ? self.loop[c] + w.b[c] : self.loop[c];
      }
    }
    return best;
  }

  // One sub-pass: the pixels of one parity read the level as it was before it and are written after it.
  void correct(Pixels& s, const Region& r, int parity, bool output_level) {
    // The corrected pixels of this parity, two to a row and column apart: row (y - y0) / 2, column (x - x0) / 2; one
    // buffer for every sub-pass and level, sized for the largest level by run().
    const int64_t stride = r.width() / 2 + 1;
    Pixels& corrected = corrected_;
    parallel_for(r.y0, r.y1, [&](int64_t y) {
      if (((y & 1) << 1 | 0) != (parity & 2)) return;
      for (int64_t x = r.x0; x < r.x1; ++x)
        if ((x & 1) == (parity & 1))
          corrected[size_t((y - r.y0) / 2 * stride + (x - r.x0) / 2)] = corrected_pixel(s, r, x, y, output_level);
    });
    parallel_for(r.y0, r.y1, [&](int64_t y) {
      if (((y & 1) << 1 | 0) != (parity & 2)) return;
      for (int64_t x = r.x0; x < r.x1; ++x)
        if ((x & 1) == (parity & 1)) {
          const size_t i = size_t((y - r.y0) * r.width() + (x - r.x0));
          s[i] = corrected[size_t((y - r.y0) / 2 * stride + (x - r.x0) / 2)];
          set_colour(s[i], i);
        }
    });
  }

  double mean_error(const Pixels& s, const Region& r) const {
    std::vector<double> rows(size_t(r.height()), 0.0);
    parallel_for(r.y0, r.y1, [&](int64_t y) {
      double n[25 * 4];
      for (int64_t x = r.x0; x < r.x1; ++x) {
        neighbourhood(s, r, x, y, n);
        const Pixel& p = at(s, r, x, y);
        rows[size_t(y - r.y0)] += error(n, p.e, p.k, p.x, p.y, kNoOffset) / 25.0;
      }
    });
    double sum = 0.0;
    for (double v : rows) sum += v;  // serial, in row order: deterministic
    return sum / double(s.size());
  }

  // One number per texel pointer: texel coordinates below 2^12 (formats/graph_layout.h), levels below 2^8.
  static uint64_t texel_key(uint32_t e, uint32_t k, uint32_t x, uint32_t y) {
    return uint64_t(e) << 32 | uint64_t(k) << 24 | uint64_t(y) << 12 | x;
  }

  // At its exemplar's finest level with nowhere to go (no admissible level there: the exemplar has no outgoing
  // edge of r >= 1).
  bool stuck(const Pixel& p) const { return p.k == L_ && admissible_[p.e][L_].empty(); }

  const GraphTables& g_;
  const SynthesisOptions& o_;
  uint32_t L_;
  std::vector<std::vector<std::vector<StackLevel>>> admissible_;
  LoopContrast loops_;
  // Whether correction may move a pixel of (i, k) to (j, l): admissible (Sec. 5.2.1.2) and not a loop below the
  // finest level (loop_transitions.h); [(i * levels + k) * admits_stride_ + j * levels + l].
  size_t admits_stride_;
  std::vector<uint32_t> admits_;
  Pixels corrected_;                   // correct()'s buffer
  UninitializedVector<float> colour_;  // fill_colours()
};

}  // namespace

Image synthesize_window(const GraphTables& graph, const SynthesisOptions& options, Progress& progress,
                        SynthesisStatistics* statistics) {
  if (options.width == 0 || options.height == 0)
    throw Error(ExitCode::bad_command_line, "the window must have a positive width and height", "--window");
  // ~100 bytes per pixel of the padded finest region (pointers, offsets, a copy per sub-pass): 2^24 pixels (a
  // 4096 x 4096 window) stays under 2 GB; larger images are tiles, which are exact.
  if (uint64_t(options.width) * options.height > (uint64_t(1) << 24))
    throw Error(ExitCode::bad_command_line,
                "the window may hold at most 2^24 pixels (4096 x 4096): synthesize it as tiles", "--window");
  constexpr int64_t kMaxCoordinate = kMaxSynthesisCoordinate;
  if (options.x < -kMaxCoordinate || options.y < -kMaxCoordinate || options.x > kMaxCoordinate - options.width ||
      options.y > kMaxCoordinate - options.height)
    throw Error(ExitCode::bad_command_line, "the window must lie within +-2^62 pixels", "--window");
  if (options.level > kMaxLevel)
    throw Error(ExitCode::bad_command_line, "--level must be at most " + std::to_string(kMaxLevel), "--level");
  if (options.jitter.empty()) throw Error(ExitCode::bad_command_line, "--jitter needs at least one value", "--jitter");
  for (double r : options.jitter)
    if (!(r >= 0.0 && r <= 1.0))
      throw Error(ExitCode::bad_command_line, "--jitter values must be in [0, 1]", "--jitter");
  if (options.passes == 0 || options.passes > 8)
    throw Error(ExitCode::bad_command_line, "--passes must be 1..8", "--passes");
  return Synthesizer(graph, options).run(progress, statistics);
}

}  // namespace mbk
