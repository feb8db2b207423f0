// Adaptive theta bins of the binned P-NDF ([Shah24] Sec. 4.1): the bin centres are a 1-D k-means clustering of the
// polar angles of all the map's normals, seeded by greedy k-means++ ([AV07]: each new centre is the best, by the
// k-means cost, of 2 + floor(ln K) candidates drawn with probability proportional to D^2), then Lloyd's iterations;
// the edges are the midpoints of the sorted centres, with 0 and pi/2 outside them (formats/histogram_layout.h).
//
// Exact and deterministic: the values are sorted and merged into distinct values with multiplicities, so each
// cluster is a run of them and a Lloyd step costs O(K log n) with prefix sums; the draws come from integer hashes
// of the seed (the command passes the input file's content hash), never a global generator, and every sum runs
// serially in one order, so the bins are the same whatever the thread count.
//
// Hard cases: with at most K distinct values (a flat map: one), every distinct value is its own centre and there
// are that many bins, fewer than K: a duplicate centre would make an empty bin of zero width (edges not increasing),
// and an arbitrary split of [0, pi/2] would make bins no normal falls in. A Lloyd step that would leave a cluster
// empty is not taken (the previous centres, a valid clustering of no greater cost, are kept).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace mbk {

struct ThetaBins {
  std::vector<double> centres;   // K' <= K, strictly increasing, in [0, pi/2]
  std::vector<double> edges;     // K' + 1: 0, the midpoints of consecutive centres, pi/2
  uint64_t distinct_values = 0;  // distinct theta values among the inputs
  uint32_t lloyd_iterations = 0;
  double rms_error = 0.0;  // sqrt of the mean squared distance of the values to their centres (radians)
};

// `thetas` in [0, pi/2] (any order; at least one), `k` >= 1 bins requested.
ThetaBins adaptive_theta_bins(std::vector<double> thetas, uint32_t k, uint64_t seed);

// The baseline the adaptive bins are measured against ([Shah24] Fig. 3): k bins of equal width pi / (2 k), centred
// (c_j = (j + 1/2) pi / (2 k), the edges their midpoints as above), whatever the values; bins no value falls in
// stay (a flat map has k - 1 empty bins). distinct_values and rms_error as for the adaptive bins.
ThetaBins uniform_theta_bins(std::vector<double> thetas, uint32_t k);

}  // namespace mbk
