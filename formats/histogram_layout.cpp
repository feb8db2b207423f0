// Bins and footprint lookups of the `histogram` asset (see histogram_layout.h).
#include "formats/histogram_layout.h"

#include <algorithm>
#include <cmath>

#include "formats/asset.h"

namespace mbk {

double histogram_theta(double x, double y, double z) { return std::atan2(std::hypot(x, y), z); }

uint32_t histogram_theta_bin(std::span<const double> theta_edges, double theta) {
  // The interior edges e_1..e_{K-1}: the bin is how many of them are <= theta.
  const auto interior = theta_edges.subspan(1, theta_edges.size() - 2);
  return uint32_t(std::upper_bound(interior.begin(), interior.end(), theta) - interior.begin());
}

double histogram_phi_edge(uint32_t i, uint32_t phi_bins) { return 2.0 * std::numbers::pi * i / phi_bins; }

std::vector<double> histogram_phi_edges(uint32_t phi_bins) {
  std::vector<double> edges(phi_bins + 1);
  for (uint32_t i = 0; i <= phi_bins; ++i) edges[i] = histogram_phi_edge(i, phi_bins);
  return edges;
}

uint32_t histogram_phi_bin(double x, double y, uint32_t phi_bins) {
  if (x == 0.0 && y == 0.0) return 0;  // the pole: phi undefined
  double phi = std::atan2(y, x);
  if (phi < 0.0) phi += 2.0 * std::numbers::pi;
  // The formula's guess, then corrected against the stored edges so that edge_i <= phi < edge_{i+1} holds exactly.
  int64_t i = int64_t(std::floor(phi * phi_bins / (2.0 * std::numbers::pi)));
  i = std::clamp<int64_t>(i, 0, int64_t(phi_bins) - 1);
  while (i > 0 && phi < histogram_phi_edge(uint32_t(i), phi_bins)) --i;
  while (i + 1 < int64_t(phi_bins) && phi >= histogram_phi_edge(uint32_t(i + 1), phi_bins)) ++i;
  return uint32_t(i);
}

uint32_t HistogramBins::bin_of(double x, double y, double z) const {
  return histogram_theta_bin(theta_edges, histogram_theta(x, y, z)) * phi_bins + histogram_phi_bin(x, y, phi_bins);
}

ThetaBinsCheck check_theta_bins(std::span<const double> edges, std::span<const double> centres) {
  ThetaBinsCheck check;
  check.edges_ok = edges.front() == 0.0 && edges.back() == kHistogramThetaMax;
  for (size_t j = 0; j + 1 < edges.size(); ++j) check.edges_ok = check.edges_ok && edges[j] < edges[j + 1];  // NaN
  if (!check.edges_ok) return check;
  for (size_t j = 0; j < centres.size(); ++j) {
    const bool inside = centres[j] >= edges[j] && centres[j] <= edges[j + 1];
    const bool midpoint = j == 0 || edges[j] == 0.5 * (centres[j - 1] + centres[j]);
    if (!inside || !midpoint) {
      check.bad_centre = int64_t(j);
      return check;
    }
  }
  return check;
}

uint64_t histogram_table_entries(uint32_t width, uint32_t height, uint32_t bins) {
  return (uint64_t(width) + 1) * (uint64_t(height) + 1) * bins;
}

uint64_t histogram_table_bytes(uint32_t width, uint32_t height, uint32_t bins) {
  return histogram_table_entries(width, height, bins) * sizeof(uint32_t);
}

void footprint_histogram(const BinCountTable& table, int64_t x0, int64_t row0, uint64_t w, uint64_t h,
                         std::span<uint64_t> out) {
  const uint32_t W = table.width, H = table.height, B = table.bins;
  // The prefix count over [0, X) x [0, Y) of the repeated map is
  //   S(Y mod H, X mod W) + qx S(Y mod H, W) + qy S(H, X mod W) + qx qy S(H, W),   qx = X div W, qy = Y div H,
  // and a footprint's counts are four such corners. With the origin wrapped into the map, its corners have
  // qx = 0 or qy = 0. Unsigned arithmetic wraps modulo 2^64, and the true result is in range, so it is exact.
  const uint64_t X0 = uint64_t(((x0 % W) + W) % W), Y0 = uint64_t(((row0 % H) + H) % H);
  const uint64_t X1 = X0 + w, Y1 = Y0 + h;
  const uint64_t qx = X1 / W, rx = X1 % W, qy = Y1 / H, ry = Y1 % H;
  const uint32_t* s11 = table.at(uint32_t(ry), uint32_t(rx));
  const uint32_t* s1W = table.at(uint32_t(ry), W);
  const uint32_t* sH1 = table.at(H, uint32_t(rx));
  const uint32_t* sHW = table.at(H, W);
  const uint32_t* s01 = table.at(uint32_t(Y0), uint32_t(rx));
  const uint32_t* s0W = table.at(uint32_t(Y0), W);
  const uint32_t* s10 = table.at(uint32_t(ry), uint32_t(X0));
  const uint32_t* sH0 = table.at(H, uint32_t(X0));
  const uint32_t* s00 = table.at(uint32_t(Y0), uint32_t(X0));
  for (uint32_t b = 0; b < B; ++b) {
    const uint64_t f11 = s11[b] + qx * s1W[b] + qy * sH1[b] + qx * qy * sHW[b];
    const uint64_t f01 = s01[b] + qx * s0W[b];
    const uint64_t f10 = s10[b] + qy * sH0[b];
    out[b] = f11 - f01 - f10 + s00[b];
  }
}

HistogramAssetView histogram_asset_view(const Asset& asset) {
  const nlohmann::json& p = asset.metadata()["parameters"];
  HistogramAssetView view;
  view.bins = {asset.read<double>(kHistogramThetaEdgesSection), p["phi_bins"].get<uint32_t>()};
  view.theta_centres = asset.read<double>(kHistogramThetaCentresSection);
  const std::span<const uint8_t> bytes = asset.bytes_of(asset.section(kHistogramCountsSection));
  view.table = {p["width"].get<uint32_t>(),
                p["height"].get<uint32_t>(),
                view.bins.count(),
                {reinterpret_cast<const uint32_t*>(bytes.data()), bytes.size() / sizeof(uint32_t)}};
  return view;
}

}  // namespace mbk
