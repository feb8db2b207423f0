// Benchmark of the glint P-NDF (libbake/glint/glint_pndf.h; [Wang20] Alg. 3): queries per second by the
// implicit-hierarchy traversal against the brute-force sum over every texel of the footprint, at footprints of
// 16^2, 64^2 and 256^2 texels and intrinsic roughness 0.005 and 0.01, and what 8-bit RMQ tables cost in nodes
// visited and time against 16-bit ones. Prints the rows of the table in examples/results/glint/REPORT.md
// (scripts/bench-glint-pndf.sh runs it and writes the report). One thread; the same fixed queries for every
// column, so every ratio is measured in the same run on the same work.
//
//   bench_glint_pndf [EXAMPLE_SIDE [KIND]]   (default 512 bumps: `microbake gen KIND --size 512 --seed 1`, in memory)
//   bench_glint_pndf 0 PATH                 (a -Y normal map file, read whole, repaired: the real maps)
#include <chrono>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <array>
#include <random>
#include <string>
#include <vector>

#include "formats/lut_layout.h"
#include "libbake/core/progress.h"
#include "libbake/gen/generator.h"
#include "libbake/glint/glint_pndf.h"
#include "libbake/glint/glint_technique.h"
#include "libbake/glint/lut_asset.h"
#include "libbake/glint/rmq_table.h"
#include "libbake/image/normal_map.h"

namespace {

using mbk::GlintFootprint;
using mbk::Vec2;

struct Query {
  GlintFootprint footprint;
  Vec2 s;
};

struct Timing {
  double per_second = 0.0;
  uint64_t done = 0;  // queries answered
  double mean_nodes = 0.0, mean_elements = 0.0;
  std::vector<double> values;
};

// Runs the queries in order, repeating the whole list until at least `min_seconds` have passed (at least once).
template <class F>
Timing time_queries(const std::vector<Query>& queries, double min_seconds, F&& evaluate) {
  using clock = std::chrono::steady_clock;
  Timing t;
  t.values.resize(queries.size());
  const auto start = clock::now();
  uint64_t done = 0;
  mbk::PndfStatistics stats;
  double elapsed = 0.0;
  do {
    for (size_t i = 0; i < queries.size(); ++i) {
      t.values[i] = evaluate(queries[i], done < queries.size() ? &stats : nullptr);
      ++done;
      elapsed = std::chrono::duration<double>(clock::now() - start).count();
      if (elapsed >= min_seconds && done >= 20) break;
    }
  } while (elapsed < min_seconds);
  t.per_second = double(done) / elapsed;
  t.done = done;
  const double first = double(std::min<uint64_t>(done, queries.size()));
  t.mean_nodes = double(stats.nodes_visited) / first;
  t.mean_elements = double(stats.elements_evaluated) / first;
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  const uint32_t side = argc > 1 ? uint32_t(std::atoi(argv[1])) : 512;
  const std::string kind = argc > 2 ? argv[2] : "bumps";
  // A kind to generate, or the path of a -Y normal map (the real maps beside the repository), read whole.
  const bool file = std::filesystem::is_regular_file(kind);
  const mbk::NormalMap example =
      file ? mbk::load_normal_map(kind, {mbk::YConvention::minus_y, mbk::InvalidTexelPolicy::repair}).map
           : mbk::generate_normal_map(kind, {side, side}, 1, mbk::Progress::silent());
  const std::string name = file ? std::filesystem::path(kind).stem().string() : kind;
  const mbk::BakedLut lut = mbk::bake_standardization_lut(example, mbk::kLutDefaultSize, mbk::Progress::silent());
  constexpr uint32_t kPatch = 64;
  const mbk::RmqTable rmq16 = mbk::build_rmq_table(example, kPatch, 16, mbk::Progress::silent());
  const mbk::RmqTable rmq8 = mbk::build_rmq_table(example, kPatch, 8, mbk::Progress::silent());
  const mbk::RmqTableView view16 = rmq16.view(), view8 = rmq8.view();
  const mbk::GlintPointQuery point(example, kPatch, 1, mbk::GlintBlendMode::histogram, &lut.tables);
  const mbk::GlintRangeQuery range16(point, view16), range8(point, view8);

  const std::array<mbk::RmqRange, 2>& normal_range = view16.range();
  for (const bool reflected : {true, false})
    for (const double sigma_r : {0.005, 0.01}) {
      const mbk::GlintPndf pndf16(range16, sigma_r), pndf8(range8, sigma_r);
      for (const double width : {16.0, 64.0, 256.0}) {
        // Fixed queries: footprint centres anywhere in +/- 10^4 texels; s = the normal at a random point of the
        // footprint moved by up to 3 sigma_r (`reflected`: a half vector that some texels reflect), or uniform
        // over the example's box of normals (a half vector anywhere the NDF may be non-zero).
        std::mt19937_64 rng(uint64_t(width * 1000 + sigma_r * 1e6));
        std::uniform_real_distribution<double> unit(0.0, 1.0);
        std::vector<Query> queries(200);
        for (Query& q : queries) {
          q.footprint = {Vec2((2 * unit(rng) - 1) * 1e4, (2 * unit(rng) - 1) * 1e4),
                         width / (2 * mbk::kGlintFootprintCutoffSigmas)};
          const Vec2 inside = q.footprint.center + width * Vec2(unit(rng) - 0.5, unit(rng) - 0.5);
          q.s = point.evaluate(inside).n + 3 * sigma_r * Vec2(2 * unit(rng) - 1, 2 * unit(rng) - 1);
          if (!reflected)
            q.s = Vec2(normal_range[0].lo + unit(rng) * (normal_range[0].hi - normal_range[0].lo),
                       normal_range[1].lo + unit(rng) * (normal_range[1].hi - normal_range[1].lo));
        }
        const Timing t16 = time_queries(queries, 1.0, [&](const Query& q, mbk::PndfStatistics* st) {
          return pndf16.evaluate(q.footprint, q.s, st);
        });
        const Timing t8 = time_queries(queries, 1.0, [&](const Query& q, mbk::PndfStatistics* st) {
          return pndf8.evaluate(q.footprint, q.s, st);
        });
        const Timing aggregated = time_queries(queries, 1.0, [&](const Query& q, mbk::PndfStatistics* st) {
          return pndf16.evaluate(q.footprint, q.s, st, true);
        });
        const Timing brute = time_queries(queries, 2.0, [&](const Query& q, mbk::PndfStatistics*) {
          return pndf16.evaluate_brute_force(q.footprint, q.s);
        });
        // Agreement over the queries the brute force finished (all of them at 16^2 and 64^2).
        double worst = 0.0;
        const size_t checked = std::min<size_t>(queries.size(), std::min(t16.done, brute.done));
        for (size_t i = 0; i < checked; ++i)
          if (brute.values[i] != 0.0) worst = std::max(worst, std::abs(t16.values[i] / brute.values[i] - 1.0));
        // The aggregated traversal's error as a fraction of its stated bound (glint_pndf.h): <= 1 holds it.
        const double peak = 1.0 / (2.0 * std::numbers::pi * sigma_r * sigma_r);
        double of_bound = 0.0;
        const size_t checked_aggregated = std::min<size_t>(queries.size(), std::min(aggregated.done, brute.done));
        for (size_t i = 0; i < checked_aggregated; ++i)
          of_bound = std::max(
              of_bound, std::abs(aggregated.values[i] - brute.values[i]) / (0.03 * brute.values[i] + 0.006 * peak));
        const double texels = width * width;
        std::printf(
            "| %s %u^2 | %s | %.0f^2 | %.3f | %.0f | %.1f | %.2f | %.0f | %.0f | %.2f | %.0f | %.2f | %.0f | %.1e | "
            "%.0f | "
            "%.1f | %.2f |\n",
            name.c_str(), example.width, reflected ? "reflected" : "any", width, sigma_r, t16.per_second,
            brute.per_second, t16.per_second / brute.per_second, texels, t16.mean_nodes, t8.mean_nodes / t16.mean_nodes,
            t8.per_second, t16.per_second / t8.per_second, t16.mean_elements, worst, aggregated.per_second,
            aggregated.per_second / brute.per_second, of_bound);
        std::fflush(stdout);
      }
    }
  return 0;
}
