// The layout and lookup convention of asset kind 7, `colormap` (prefiltered colour maps, [Heitz13] Sec. 4.2,
// Eq. 10; formats/SPEC.md "Kind 7: colormap"), shared by the baker (libbake/colormap/colormap_table.h), the
// evaluator's lookups and `validate` (formats/kind_colormap.cpp), so that all three agree.
//
// The colour map C. A colormap asset stores its C exactly: K >= 1 knots x_0 <= x_1 <= ... <= x_{K-1} with linear
// RGB colours c_k (section `knots` f32 [K], `colors` f32 [K, 3]). C is piecewise linear between knots; two knots
// at the same position make a jump (C takes the later colour there: right-continuous); no more than two knots
// share a position. Outside [x_0, x_{K-1}] C is extended by its end colours (clamp):
//   C(x) = c_0 for x < x_0,  C(x) = c_{K-1} for x > x_{K-1}.
// Why clamp: it is what a GPU's CLAMP_TO_EDGE lookup of a gradient texture does, so the unfiltered reference
// (C of the raw driver) and the table agree; every filtered colour stays a convex combination of C's colours (a
// Gaussian average of C), which `validate` checks; and it neither wraps the far end's colour in (repeat) nor
// darkens the ends toward black (zero extension).
//
// The table. Entry (j, i) (section `table` f32 [H, W, 3], rows = standard deviation) is
//   T(j, i) = [C * N(0, sigma_j^2)](m_i) = E[C(m_i + sigma_j Z)],  Z ~ N(0, 1)       ([Heitz13] Eq. 10)
// at m_i = mean_min + i (mean_max - mean_min) / (W - 1) and sigma_j = j sigma_max / (H - 1) (row 0 is sigma = 0,
// i.e. C itself; W, H >= 2). Lookup: bilinear between the four surrounding entries, the mean and sigma clamped to
// [mean_min, mean_max] x [0, sigma_max].
//
// The convolution in closed form (exact for the piecewise-linear C; derivation): write C with hinge and step
// functions, C(x) = c_0 + sum over segments k with x_{k+1} > x_k of s_k [(x - x_k)_+ - (x - x_{k+1})_+] + sum over
// jumps (x_{k+1} == x_k) of (c_{k+1} - c_k) H(x - x_k), s_k = (c_{k+1} - c_k) / (x_{k+1} - x_k); grouped by
// position p, C(x) = c_0 + sum_p [(slope after p - slope before p) (x - p)_+ + jump_p H(x - p)]. With
// X ~ N(m, sigma^2) and t = m - a:
//   E[(X - a)_+] = t Phi(t / sigma) + sigma phi(t / sigma),     E[H(X - a)] = Phi(t / sigma),
// and at sigma = 0 these are t_+ and [t >= 0]. Beyond |t| > 40 sigma, Phi is 0 or 1 and phi is 0 in double,
// so those terms are taken as their limits without calling erfc (exact in double, and O(1) per knot).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace mbk {

class Asset;

inline constexpr uint32_t kColormapKindId = 7;
inline constexpr uint32_t kColormapMinSide = 2;
inline constexpr uint32_t kColormapMaxSide = 8192;
inline constexpr uint32_t kColormapDefaultSide = 256;  // 256 x 256, the paper's setting ([Heitz13] Sec. 7)
inline constexpr uint32_t kColormapMaxKnots = 1u << 20;

inline constexpr std::string_view kColormapKnotsSection = "knots";
inline constexpr std::string_view kColormapColorsSection = "colors";
inline constexpr std::string_view kColormapTableSection = "table";

// C: knots and linear RGB colours (see above).
struct ColormapCurve {
  std::vector<double> knots;
  std::vector<std::array<double, 3>> colors;
  // C(x) at sigma = 0 (right-continuous at jumps, clamped outside the knots).
  std::array<double, 3> at(double x) const;
  // [C * N(0, sigma^2)](mean), the closed form above; sigma >= 0.
  std::array<double, 3> convolved(double mean, double sigma) const;
};

// Empty when the knots are valid (K >= 1, same count as colours, finite, non-decreasing, at most two per
// position); otherwise what is wrong.
std::string colormap_curve_problem(const ColormapCurve& curve);

struct ColormapTable {
  uint32_t width = 0, height = 0;  // W means x H sigmas
  double mean_min = 0.0, mean_max = 1.0, sigma_max = 0.5;
  std::vector<float> values;  // [H, W, 3]
  double mean_at(uint32_t i) const;
  double sigma_at(uint32_t j) const;
  // The bilinear lookup of the convention above. Non-finite mean or sigma gives NaN.
  std::array<double, 3> lookup(double mean, double sigma) const;
};

// The table of a colormap asset (metadata parameters and section `table`); Error(invalid_input) when the
// parameters or the shape do not match.
ColormapTable read_colormap_table(const Asset& asset);

}  // namespace mbk
