// Forward and backward passes of the neural histogram's MLPs (see histogram_mlp.h).
#include "libbake/histogram/histogram_mlp.h"

namespace mbk {
namespace {

using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using ConstMatrix = Eigen::Map<const RowMajor>;
using ConstVector = Eigen::Map<const Eigen::VectorXf>;

}  // namespace

void mlp_forward(const MlpShape& s, const float* p, const Eigen::MatrixXf& x, MlpPass& pass) {
  const ConstMatrix w1(p + s.w1(), s.hidden, s.in), w2(p + s.w2(), s.hidden, s.hidden), w3(p + s.w3(), s.out, s.hidden);
  const ConstVector b1(p + s.b1(), s.hidden), b2(p + s.b2(), s.hidden), b3(p + s.b3(), s.out);
  pass.z1.noalias() = w1 * x;
  pass.z1.colwise() += b1;
  pass.a1 = pass.z1.cwiseMax(0.0f);
  pass.z2.noalias() = w2 * pass.a1;
  pass.z2.colwise() += b2;
  pass.a2 = pass.z2.cwiseMax(0.0f);
  pass.logits.noalias() = w3 * pass.a2;
  pass.logits.colwise() += b3;
}

void mlp_backward(const MlpShape& s, const float* p, const Eigen::MatrixXf& x, const MlpPass& pass,
                  const Eigen::MatrixXf& dlogits, float* g, Eigen::MatrixXf& dx) {
  using Matrix = Eigen::Map<RowMajor>;
  using Vector = Eigen::Map<Eigen::VectorXf>;
  const ConstMatrix w1(p + s.w1(), s.hidden, s.in), w2(p + s.w2(), s.hidden, s.hidden), w3(p + s.w3(), s.out, s.hidden);
  Matrix(g + s.w3(), s.out, s.hidden).noalias() += dlogits * pass.a2.transpose();
  Vector(g + s.b3(), s.out) += dlogits.rowwise().sum();
  Eigen::MatrixXf dz2 = w3.transpose() * dlogits;
  dz2.array() *= (pass.z2.array() > 0.0f).cast<float>();
  Matrix(g + s.w2(), s.hidden, s.hidden).noalias() += dz2 * pass.a1.transpose();
  Vector(g + s.b2(), s.hidden) += dz2.rowwise().sum();
  Eigen::MatrixXf dz1 = w2.transpose() * dz2;
  dz1.array() *= (pass.z1.array() > 0.0f).cast<float>();
  Matrix(g + s.w1(), s.hidden, s.in).noalias() += dz1 * x.transpose();
  Vector(g + s.b1(), s.hidden) += dz1.rowwise().sum();
  dx.noalias() = w1.transpose() * dz1;
}

void log_softmax_columns(Eigen::MatrixXf& logits) {
  for (Eigen::Index c = 0; c < logits.cols(); ++c) {
    auto column = logits.col(c);
    const float top = column.maxCoeff();
    column.array() -= top;
    column.array() -= std::log(column.array().exp().sum());
  }
}

}  // namespace mbk
