// Fit quality and time of the vMF mixture pyramid (libbake/filter/vmf_pyramid.h) against the multi-start
// reference EM (libbake/filter/vmf_reference_fit.h): per level, the mean log-likelihood per finest normal of the
// stored lobes over every texel (the asset's statistic), and over up to SAMPLE evenly spaced texels the same for
// the stored lobes and for the best of STARTS reference runs, with the EM statistics and the top texel's lobes.
//
//   bench_vmf_fit [--lobes J] [--max-iterations N] [--max-chunks C] [--sample M] [--starts S] INPUT...
//   INPUT: gen:KIND:SIZE (`microbake gen KIND --size SIZE --seed 1`, in memory) or PATH.png[:-Y]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "libbake/core/progress.h"
#include "libbake/core/vmf_lobe.h"
#include "libbake/filter/vmf_pyramid.h"
#include "libbake/filter/vmf_reference_fit.h"
#include "libbake/gen/generator.h"

namespace {

using namespace mbk;

NormalMap load(const std::string& input) {
  if (input.rfind("gen:", 0) == 0) {
    const size_t colon = input.find(':', 4);
    const uint32_t size = uint32_t(std::stoul(input.substr(colon + 1)));
    return generate_normal_map(input.substr(4, colon - 4), MapSize{size, size}, 1, Progress::silent());
  }
  const bool minus_y = input.size() > 3 && input.substr(input.size() - 3) == ":-Y";
  const std::string path = minus_y ? input.substr(0, input.size() - 3) : input;
  return load_normal_map(path, {minus_y ? YConvention::minus_y : YConvention::plus_y, InvalidTexelPolicy::repair}).map;
}

}  // namespace

int main(int argc, char** argv) {
  VmfBakeOptions options;
  int sample = 16, starts = 3;
  std::vector<std::string> inputs;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--lobes" && a + 1 < argc) {
      options.lobes = std::atoi(argv[++a]);
    } else if (arg == "--max-iterations" && a + 1 < argc) {
      options.em.max_iterations = std::atoi(argv[++a]);
    } else if (arg == "--max-chunks" && a + 1 < argc) {
      options.max_chunks = size_t(std::atol(argv[++a]));
    } else if (arg == "--sample" && a + 1 < argc) {
      sample = std::atoi(argv[++a]);
    } else if (arg == "--starts" && a + 1 < argc) {
      starts = std::atoi(argv[++a]);
    } else {
      inputs.push_back(arg);
    }
  }
  for (const std::string& input : inputs) {
    const NormalMap map = load(input);
    const auto t0 = std::chrono::steady_clock::now();
    const VmfPyramid p = build_vmf_pyramid(map, nullptr, options, Progress::silent());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%s: %ux%u, J = %d, max_iterations %d, bake %.2f s\n", input.c_str(), map.width, map.height,
                options.lobes, options.em.max_iterations, seconds);
    std::printf("level  texels  ll_all    | sampled  ll_fit    ll_ref    ref-fit  | iters  conv  reseeds empty\n");
    VmfReferenceOptions reference;
    reference.lobes = options.lobes;
    reference.starts = starts;
    for (size_t k = 1; k < p.levels.size(); ++k) {
      const VmfLevel& level = p.levels[k];
      const size_t count = size_t(level.width) * level.height, step = std::max<size_t>(1, count / size_t(sample));
      double fit = 0.0, ref = 0.0;
      size_t n = 0;
      for (size_t t = step / 2; t < count; t += step, ++n) {
        const uint32_t i = uint32_t(t % level.width), j = uint32_t(t / level.width);
        const auto normals = vmf_texel_normals(map, level.width, level.height, i, j);
        std::vector<VmfComponent> stored;
        for (int l = 0; l < p.lobes; ++l)
          stored.push_back(decode_lobe(&level.lobes[(t * size_t(p.lobes) + size_t(l)) * 4], kVmfKappaMax));
        fit += vmf_mixture_log_likelihood(normals, stored);
        ref += multi_start_vmf_fit(normals, reference).log_likelihood;
      }
      const VmfLevelStatistics& s = level.statistics;
      std::printf("%5zu %7zu %9.5f | %7zu %9.5f %9.5f %8.5f | %6.1f %5.2f %6.3f %5.3f\n", k, count,
                  s.mean_log_likelihood, n, fit / double(n), ref / double(n), (ref - fit) / double(n),
                  s.mean_iterations, s.converged_fraction, s.mean_reseeds, s.empty_lobe_fraction);
    }
    std::printf("top texel lobes (alpha, kappa):");
    for (int l = 0; l < p.lobes; ++l) {
      const VmfComponent c = decode_lobe(&p.levels.back().lobes[size_t(l) * 4], kVmfKappaMax);
      std::printf(" (%.3g, %.3g)", c.alpha, c.kappa);
    }
    std::printf("\nreference top lobes (alpha, kappa):");
    const VmfLevel& top = p.levels.back();
    for (const VmfComponent& c :
         multi_start_vmf_fit(vmf_texel_normals(map, top.width, top.height, 0, 0), reference).mixture)
      std::printf(" (%.3g, %.3g)", c.alpha, c.kappa);
    std::printf("\n\n");
  }
  return 0;
}
