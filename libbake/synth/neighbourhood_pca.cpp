// PCA of neighbourhood vectors (see neighbourhood_pca.h).
#include "libbake/synth/neighbourhood_pca.h"

#include <Eigen/Eigenvalues>

namespace mbk {

NeighbourhoodPca fit_pca(const std::vector<float>& vectors, uint32_t dims, uint32_t components) {
  const size_t n = vectors.size() / dims;
  components = std::min(components, dims);
  NeighbourhoodPca pca;
  pca.mean = Eigen::VectorXd::Zero(dims);
  for (size_t i = 0; i < n; ++i)
    for (uint32_t d = 0; d < dims; ++d) pca.mean[d] += vectors[i * dims + d];
  if (n > 0) pca.mean /= double(n);
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(dims, dims);
  Eigen::VectorXd x(dims);
  for (size_t i = 0; i < n; ++i) {
    for (uint32_t d = 0; d < dims; ++d) x[d] = vectors[i * dims + d] - pca.mean[d];
    cov.selfadjointView<Eigen::Lower>().rankUpdate(x);
  }
  cov = cov.selfadjointView<Eigen::Lower>();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(cov);
  // Eigen returns increasing eigenvalues: take the last `components` columns, largest first.
  pca.basis.resize(dims, components);
  double kept = 0.0;
  const double total = eig.eigenvalues().sum();
  for (uint32_t c = 0; c < components; ++c) {
    Eigen::VectorXd v = eig.eigenvectors().col(dims - 1 - c);
    Eigen::Index largest = 0;
    v.cwiseAbs().maxCoeff(&largest);
    if (v[largest] < 0) v = -v;
    pca.basis.col(c) = v;
    kept += std::max(0.0, eig.eigenvalues()[dims - 1 - c]);
  }
  pca.kept_variance = total > 0.0 ? kept / total : 1.0;
  return pca;
}

std::vector<float> NeighbourhoodPca::project(const std::vector<float>& vectors) const {
  const Eigen::Index dims = mean.size(), components = basis.cols();
  const size_t n = vectors.size() / size_t(dims);
  std::vector<float> out(n * size_t(components));
  Eigen::VectorXd x(dims);
  for (size_t i = 0; i < n; ++i) {
    for (Eigen::Index d = 0; d < dims; ++d) x[d] = vectors[i * dims + d] - mean[d];
    const Eigen::VectorXd y = basis.transpose() * x;
    for (Eigen::Index c = 0; c < components; ++c) out[i * components + c] = float(y[c]);
  }
  return out;
}

}  // namespace mbk
