// FLANN exact k-nearest neighbours (see neighbourhood_search.h).
#include "libbake/synth/neighbourhood_search.h"

#include <algorithm>
#include <numeric>

#include <flann/flann.hpp>

namespace mbk {

std::vector<uint32_t> nearest_neighbours(const std::vector<float>& points, const std::vector<float>& queries,
                                         uint32_t dims, uint32_t k) {
  const size_t n = points.size() / dims, q = queries.size() / dims;
  k = uint32_t(std::min<size_t>(k, n));
  std::vector<uint32_t> out(q * k);
  std::vector<float> dist(q * k);
  if (k == 0 || q == 0) return out;
  flann::Matrix<float> data(const_cast<float*>(points.data()), n, dims);
  flann::Matrix<float> query(const_cast<float*>(queries.data()), q, dims);
  flann::Index<flann::L2<float>> index(data, flann::KDTreeSingleIndexParams(10));
  index.buildIndex();
  std::vector<size_t> raw(q * k);
  flann::Matrix<size_t> indices(raw.data(), q, k);
  flann::Matrix<float> d(dist.data(), q, k);
  flann::SearchParams params(flann::FLANN_CHECKS_UNLIMITED);
  params.cores = 1;  // the caller parallelises; one order of results
  index.knnSearch(query, indices, d, k, params);
  for (size_t i = 0; i < q; ++i) {
    // Ties in distance ordered by index, so that equal neighbourhoods always resolve the same way.
    std::vector<uint32_t> order(k);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
      return dist[i * k + a] < dist[i * k + b] ||
             (dist[i * k + a] == dist[i * k + b] && raw[i * k + a] < raw[i * k + b]);
    });
    for (uint32_t j = 0; j < k; ++j) out[i * k + j] = uint32_t(raw[i * k + order[j]]);
  }
  return out;
}

}  // namespace mbk
