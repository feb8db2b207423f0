// The mean of the reference's specular times cosine over normals drawn from a vMF lobe, by an independent sampler
// (uniform directions kept with probability exp(kappa (mu . n - 1))): what libbake/eval/lobe_specular.h stands for.
#pragma once

#include <cmath>
#include <random>

#include "libbake/eval/microfacet_brdf.h"
#include "libbake/eval/scene_lighting.h"

namespace mbk::test {

// The reference's specular times cosine for one texel normal, bent towards the viewer as the reference bends it.
inline double reference_specular(const Brdf& brdf, const Vec3& normal, const Vec3& l, const Vec3& v) {
  const Vec3 n = facing_viewer(normal, v);
  const double cos_l = n.dot(l);
  return cos_l > 0.0 ? evaluate_specular(brdf, n, l, v)[0] * cos_l : 0.0;
}

// Its mean over `count` normals of vMF(mu, kappa) (red channel).
inline double lobe_mean_by_rejection(const Brdf& brdf, const Vec3& mu, double kappa, const Vec3& l, const Vec3& v,
                                     int count) {
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> uniform;
  double sum = 0.0;
  for (int kept = 0; kept < count;) {
    const Vec3 n = Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();
    if (uniform(rng) >= std::exp(kappa * (mu.dot(n) - 1.0))) continue;
    sum += reference_specular(brdf, n, l, v);
    ++kept;
  }
  return sum / count;
}

}  // namespace mbk::test
