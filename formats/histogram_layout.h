// The `histogram` asset's bins and summed-area tables (formats/kind_histogram.cpp, formats/SPEC.md "Kind 11:
// histogram"): the binned P-NDF of [Shah24] Sec. 4.1 / Eq. 3, stored as [GGN18]'s integral images of per-bin counts.
// Everything a reader needs lives here, shared with the baker (libbake/histogram/), so that both assign a normal to
// the same bin and read a footprint's counts the same way.
//
// Bins: theta = atan2(sqrt(x^2 + y^2), z) (Eq. 10, written so that it stays accurate near the pole) in K bins with
// edges e_0 = 0 < e_1 < ... < e_K = pi/2; phi = atan2(y, x) in [0, 2 pi) in N uniform bins with edges
// 2 pi i / N. Every bin is half-open, [e_j, e_{j+1}), except the last theta bin, which also holds theta = pi/2 (the
// horizon, where repaired texels land), and the last phi bin, which holds what rounds to 2 pi. A normal exactly on
// an edge belongs to the bin above it. At the pole (x = y = 0, either sign of zero) phi is undefined: such a normal
// is in phi bin 0. Bin index = theta_bin * N + phi_bin.
//
// Table: `bin_counts` u32 [H + 1, W + 1, B], entry (Y, X, b) = the number of texels of bin b in rows [0, Y) and
// columns [0, X) (row 0 at the top of the image). A side is at most 16384 texels, so every count fits in 32 bits.
#pragma once

#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

namespace mbk {

inline constexpr uint32_t kHistogramKindId = 11;
inline constexpr uint32_t kHistogramMaxSide = 16384;  // the normal maps' (kMaxNormalMapSide)
inline constexpr uint32_t kHistogramMaxThetaBins = 64;
inline constexpr uint32_t kHistogramMaxPhiBins = 512;
inline constexpr uint32_t kHistogramDefaultThetaBins = 9;  // the paper's 9 x 32
inline constexpr uint32_t kHistogramDefaultPhiBins = 32;
// The largest table `microbake histogram` writes: 4 GiB. At the paper's 9 x 32 bins that is about a 1930^2 map;
// 2048^2 needs 4.84 GB (the paper's 4.8 GB), which is why the neural form exists.
inline constexpr uint64_t kHistogramMaxTableBytes = uint64_t(1) << 32;
inline constexpr double kHistogramThetaMax = std::numbers::pi / 2;

// Names of the sections.
inline constexpr const char* kHistogramThetaEdgesSection = "theta_edges";
inline constexpr const char* kHistogramThetaCentresSection = "theta_centres";
inline constexpr const char* kHistogramPhiEdgesSection = "phi_edges";
inline constexpr const char* kHistogramCountsSection = "bin_counts";

// The polar angle of a (not necessarily unit) direction, in [0, pi] (Eq. 10).
double histogram_theta(double x, double y, double z);
// The theta bin of `theta` for edges e_0..e_K (K >= 1): the j with e_j <= theta < e_{j+1}, clamped to [0, K - 1].
uint32_t histogram_theta_bin(std::span<const double> theta_edges, double theta);
// The uniform phi edges 2 pi i / N, i = 0..N: what the asset stores and the reader compares with.
double histogram_phi_edge(uint32_t i, uint32_t phi_bins);
std::vector<double> histogram_phi_edges(uint32_t phi_bins);
// The phi bin of direction (x, y): 0 at the pole, else the i with edge_i <= phi < edge_{i+1}.
uint32_t histogram_phi_bin(double x, double y, uint32_t phi_bins);

struct HistogramBins {
  std::vector<double> theta_edges;  // K + 1, from 0 to pi/2
  uint32_t phi_bins = 0;
  uint32_t theta_bins() const { return uint32_t(theta_edges.size() - 1); }
  uint32_t count() const { return theta_bins() * phi_bins; }
  // The bin of a direction (theta_bin * phi_bins + phi_bin).
  uint32_t bin_of(double x, double y, double z) const;
};

// The invariants of stored theta bins (K >= 1, edges K + 1 values, centres K), shared by the validators of the
// kinds that store them: the edges rise strictly from 0 to pi/2 (`edges_ok`); each centre lies in its bin and each
// interior edge is the midpoint of its two centres (else `bad_centre` is the first centre that does not).
struct ThetaBinsCheck {
  bool edges_ok = true;
  int64_t bad_centre = -1;
  bool ok() const { return edges_ok && bad_centre < 0; }
};
ThetaBinsCheck check_theta_bins(std::span<const double> edges, std::span<const double> centres);

// Entries and bytes of the table of a W x H map with `bins` bins.
uint64_t histogram_table_entries(uint32_t width, uint32_t height, uint32_t bins);
uint64_t histogram_table_bytes(uint32_t width, uint32_t height, uint32_t bins);

// A read-only view of a table.
struct BinCountTable {
  uint32_t width = 0, height = 0, bins = 0;
  std::span<const uint32_t> counts;  // [H + 1, W + 1, bins]
  const uint32_t* at(uint32_t row, uint32_t column) const {
    return counts.data() + (uint64_t(row) * (width + 1) + column) * bins;
  }
};

// The histogram of the footprint of w x h texels (w, h >= 1) whose top-left texel is (x0, row0), on the map
// repeated in both directions: x0 and row0 are any integers (taken modulo the sides), and a footprint wider or
// taller than the map counts its texels as often as it covers them. `out` (bins values) receives the counts, which
// sum to w * h. O(bins): at most 16 corner reads, whatever the footprint's size.
void footprint_histogram(const BinCountTable& table, int64_t x0, int64_t row0, uint64_t w, uint64_t h,
                         std::span<uint64_t> out);

class Asset;

// A `histogram` asset as a reader uses it: its bins, theta centres and a view of its table (into the asset's bytes,
// valid while the asset lives). The asset must have passed its kind's checks (Asset::open/parse run them).
struct HistogramAssetView {
  HistogramBins bins;
  std::vector<double> theta_centres;
  BinCountTable table;
};
HistogramAssetView histogram_asset_view(const Asset& asset);

}  // namespace mbk
