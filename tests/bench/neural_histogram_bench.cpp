// Benchmark of the neural histogram ([Shah24] Sec. 4.2; libbake/histogram/neural_binned_ndf.h) against the exact
// binned P-NDF and against a non-neural compressed baseline of equal bytes (a MIP pyramid of histograms with
// trilinear interpolation, [DLW*22]; libbake/histogram/histogram_pyramid_baseline.h): the mean KL divergence
// D_KL(exact || predicted) per footprint side (8 to 256 texels, 400 footprints each, centres uniform, the same for
// every predictor), next to the whole map's histogram as the prediction, and the bytes. Reads a neural_histogram
// asset and the normal map it was baked from (the exact table is rebuilt in memory with the asset's bins).
//
//   bench_neural_histogram ASSET.mbk MAP [CONVENTION [repair]]     (CONVENTION: auto, +Y or -Y; default auto)
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "formats/asset.h"
#include "formats/error.h"
#include "formats/neural_histogram_layout.h"
#include "libbake/histogram/histogram_kl.h"
#include "libbake/histogram/histogram_pyramid_baseline.h"
#include "libbake/histogram/neural_binned_ndf.h"
#include "libbake/histogram/neural_histogram_bake.h"

int main(int argc, char** argv) try {
  using namespace mbk;
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_neural_histogram ASSET.mbk MAP [CONVENTION [repair]]\n");
    return 1;
  }
  const Asset asset = Asset::open(argv[1]);
  NormalMapLoadOptions load;
  if (argc > 3) load.convention = parse_convention_request(argv[3]);
  if (argc > 4 && std::string(argv[4]) == "repair") load.invalid = InvalidTexelPolicy::repair;
  const LoadedNormalMap map = load_normal_map(argv[2], load);
  const nlohmann::json& p = asset.metadata()["parameters"];
  const HistogramBakeOptions bins{p["theta_bins_requested"].get<uint32_t>(), p["phi_bins"].get<uint32_t>()};
  const BakedHistogram exact_baked =
      bake_histogram(map.map, bins, p["seed"].get<uint64_t>(), Progress::silent(), argv[2]);
  const std::unique_ptr<BinnedNdfSource> neural = open_neural_histogram(asset);
  if (exact_baked.bins.theta_edges != neural->bins().theta_edges)
    throw Error(ExitCode::invalid_input, "the map's bins differ from the asset's: another map or convention?");
  const ExactBinnedNdf exact({exact_baked.bins, exact_baked.theta.centres, exact_baked.table()});
  const NeuralHistogramShape shape = neural_histogram_asset_view(asset).shape;
  const uint64_t model_bytes = neural_predictor_bytes(shape);
  const HistogramPyramidBaseline baseline({exact_baked.bins, exact_baked.theta.centres, exact_baked.table()},
                                          model_bytes);
  const uint64_t file_bytes = asset.header().file_size;
  const uint64_t table_bytes = histogram_table_bytes(shape.width, shape.height, exact_baked.bins.count());

  std::printf("map %s, %ux%u, %u x %u bins, %u iterations x %u footprints, F = %u\n", argv[2], shape.width,
              shape.height, shape.theta_bins, shape.phi_bins, p["iterations"].get<uint32_t>(),
              p["batch"].get<uint32_t>(), shape.features);
  std::printf(
      "bytes: asset %llu (texel bins, pyramid and networks %llu, of which pyramid and networks %llu), exact "
      "table %llu: %.3f%%\n",
      (unsigned long long)file_bytes, (unsigned long long)shape.model_bytes(), (unsigned long long)model_bytes,
      (unsigned long long)table_bytes, 100.0 * double(file_bytes) / double(table_bytes));
  std::printf("baseline: %llu bytes, level 0 %u x %u cells of %.1f texels, %u levels\n",
              (unsigned long long)baseline.bytes(), baseline.grid().level_width[0], baseline.grid().level_height[0],
              baseline.grid().base, baseline.grid().levels());
  std::printf("| side | neural KL | baseline KL | whole-map KL |\n|---|---|---|---|\n");
  const uint32_t B = exact_baked.bins.count();
  std::vector<double> truth(B), whole(B), q(B);
  exact.footprint_probabilities(whole_map_footprint(shape.width, shape.height), whole);
  std::mt19937_64 random(2024);
  std::uniform_real_distribution<double> ux(0.0, shape.width), uy(0.0, shape.height);
  constexpr int kFootprints = 400;
  for (const double side : {8.0, 16.0, 32.0, 64.0, 128.0, 256.0}) {
    double kl_neural = 0.0, kl_baseline = 0.0, kl_whole = 0.0;
    for (int n = 0; n < kFootprints; ++n) {
      const SquareFootprint f{ux(random), uy(random), side};
      exact.footprint_probabilities(f, truth);
      neural->footprint_probabilities(f, q);
      kl_neural += histogram_kl(truth, q) / kFootprints;
      baseline.footprint_probabilities(f, q);
      kl_baseline += histogram_kl(truth, q) / kFootprints;
      kl_whole += histogram_kl(truth, whole) / kFootprints;
    }
    std::printf("| %g | %.4f | %.4f | %.4f |\n", side, kl_neural, kl_baseline, kl_whole);
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "bench_neural_histogram: %s\n", e.what());
  return 3;
}
