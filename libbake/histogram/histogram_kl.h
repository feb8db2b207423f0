// The Kullback-Leibler divergence D_KL(exact || predicted) of two binned P-NDFs, the loss [Shah24] Sec. 5 trains
// the neural histogram on and the measure of its accuracy (tests, statistics, bench).
#pragma once

#include <span>

namespace mbk {

// sum over bins with exact_b > 0 of exact_b ln(exact_b / predicted_b), in nats; a predicted probability below
// 1e-12 is taken as 1e-12, so that a bin the prediction misses costs a large but finite amount.
double histogram_kl(std::span<const double> exact, std::span<const double> predicted);

}  // namespace mbk
