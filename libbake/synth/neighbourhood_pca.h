// PCA of neighbourhood vectors ([Han08] thesis Sec. 5.2.2.3 "accelerated matching", after Lefebvre & Hoppe 2005:
// 5 x 5 neighbourhoods projected to a few principal components before nearest-neighbour search). Computed with
// Eigen's self-adjoint eigensolver on the covariance in double, so it is deterministic; components are ordered by
// decreasing variance and each one's sign is fixed (its largest-magnitude coefficient positive).
#pragma once

#include <cstdint>
#include <vector>

#include "libbake/core/eigen.h"

namespace mbk {

struct NeighbourhoodPca {
  Eigen::VectorXd mean;
  Eigen::MatrixXd basis;       // dims x components
  double kept_variance = 1.0;  // fraction of the total variance the components hold (1 for a constant set)
  // Projects n x dims row-major vectors to n x components floats.
  std::vector<float> project(const std::vector<float>& vectors) const;
};

// PCA of n x dims row-major vectors, keeping `components` (clamped to dims).
NeighbourhoodPca fit_pca(const std::vector<float>& vectors, uint32_t dims, uint32_t components);

}  // namespace mbk
