// The exact histogram bake (see histogram_bake.h).
#include "libbake/histogram/histogram_bake.h"

#include <cmath>

#include "formats/error.h"
#include "formats/number_text.h"
#include "libbake/histogram/bin_count_table.h"

namespace mbk {

void check_histogram_table_size(uint32_t width, uint32_t height, const HistogramBakeOptions& options,
                                const std::string& where) {
  const uint64_t bytes = histogram_table_bytes(width, height, options.theta_bins * options.phi_bins);
  if (bytes > kHistogramMaxTableBytes)
    throw Error(ExitCode::invalid_input,
                "the histogram table of a " + number_text(width) + "x" + number_text(height) + " map with " +
                    number_text(options.theta_bins) + " x " + number_text(options.phi_bins) + " bins would take " +
                    number_text(bytes) + " bytes, above the limit of " + number_text(kHistogramMaxTableBytes) +
                    " (4 GiB); use fewer bins (--theta-bins, --phi-bins) or a smaller map",
                where);
}

const char* theta_binning_name(ThetaBinning binning) {
  return binning == ThetaBinning::uniform ? "uniform" : "adaptive";
}

uint64_t histogram_seed(const std::string& content_hash) {
  const size_t colon = content_hash.find(':');
  return std::stoull(content_hash.substr(colon + 1), nullptr, 16);
}

BakedHistogram bake_histogram(const NormalMap& map, const HistogramBakeOptions& options, uint64_t seed,
                              Progress& progress, const std::string& where) {
  check_histogram_table_size(map.width, map.height, options, where);
  std::vector<double> thetas(map.texels.size());
  for (size_t t = 0; t < thetas.size(); ++t) {
    const Vec3f& n = map.texels[t];
    if (!n.allFinite() || n.z() < 0.0f)
      throw Error(ExitCode::invalid_input,
                  "texel (" + number_text(t % map.width) + ", " + number_text(t / map.width) +
                      ") is not a unit normal with z >= 0",
                  where);
    thetas[t] = histogram_theta(n.x(), n.y(), n.z());
  }
  BakedHistogram out;
  out.width = map.width;
  out.height = map.height;
  out.theta = options.theta_binning == ThetaBinning::uniform
                  ? uniform_theta_bins(std::move(thetas), options.theta_bins)
                  : adaptive_theta_bins(std::move(thetas), options.theta_bins, seed);
  out.bins = {out.theta.edges, options.phi_bins};
  out.counts = bin_count_table(texel_bins(map, out.bins), map.width, map.height, out.bins.count(), progress);
  return out;
}

}  // namespace mbk
