// The small MLPs of the neural histogram ([Shah24] Sec. 4.2.2: 64 x 2, ReLU): in -> hidden -> hidden -> out, the
// parameters in one flat array in the order of formats/neural_histogram_layout.h (MlpShape). A forward pass over a
// batch (one column per sample, Eigen), the log-softmax of its logits, and the hand-written backward pass that
// training needs (the gradient of a loss given its gradient with respect to the logits).
#pragma once

#include <Eigen/Core>

#include "formats/neural_histogram_layout.h"

namespace mbk {

// What a forward pass keeps for the backward one: pre-activations and activations of both hidden layers, logits.
struct MlpPass {
  Eigen::MatrixXf z1, a1, z2, a2, logits;  // [hidden, B] x 4, [out, B]
};

// `x` is [in, B]; fills `pass`.
void mlp_forward(const MlpShape& shape, const float* parameters, const Eigen::MatrixXf& x, MlpPass& pass);

// Given dL/dlogits [out, B] of the pass that read `x`: adds dL/dparameters to `gradient` (the parameters' layout)
// and sets `dx` to dL/dx [in, B].
void mlp_backward(const MlpShape& shape, const float* parameters, const Eigen::MatrixXf& x, const MlpPass& pass,
                  const Eigen::MatrixXf& dlogits, float* gradient, Eigen::MatrixXf& dx);

// Replaces every column by its log-softmax (log of the normalised exponentials), stably.
void log_softmax_columns(Eigen::MatrixXf& logits);

}  // namespace mbk
