// Reconstruction of a normal map with discontinuities at a point (see crease_reconstruction.h).
#include "formats/crease_reconstruction.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace mbk {
namespace {

// Values carried by a partition vertex: distance, gradient (2), normal (3).
struct Values {
  double d = 0.0, g[2] = {0, 0}, n[3] = {0, 0, 0};
};

Values lerp(const Values& a, const Values& b, double t) {
  Values r;
  r.d = (1 - t) * a.d + t * b.d;
  for (int c = 0; c < 2; ++c) r.g[c] = (1 - t) * a.g[c] + t * b.g[c];
  for (int c = 0; c < 3; ++c) r.n[c] = (1 - t) * a.n[c] + t * b.n[c];
  return r;
}

void accumulate(Values& sum, const Values& v, double w) {
  sum.d += w * v.d;
  for (int c = 0; c < 2; ++c) sum.g[c] += w * v.g[c];
  for (int c = 0; c < 3; ++c) sum.n[c] += w * v.n[c];
}

Values scaled(const Values& v, double w) {
  Values r;
  accumulate(r, v, w);
  return r;
}

struct UnionFind {
  std::array<int, 8> parent = {0, 1, 2, 3, 4, 5, 6, 7};
  int find(int a) { return parent[size_t(a)] == a ? a : parent[size_t(a)] = find(parent[size_t(a)]); }
  void join(int a, int b) { parent[size_t(find(a))] = find(b); }
};

// Barycentric coordinates of p in triangle (a, b, c).
void barycentric(const double p[2], const double a[2], const double b[2], const double c[2], double l[3]) {
  const double det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
  l[1] = ((p[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (p[1] - a[1])) / det;
  l[2] = ((b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1])) / det;
  l[0] = 1.0 - l[1] - l[2];
}

uint32_t clamp_cell(double x, uint32_t cells) {
  const double c = std::floor(x + 0.5);
  return c <= 0.0 ? 0u : c >= double(cells - 1) ? cells - 1 : uint32_t(c);
}

double smoothstep(double t) { return t * t * (3.0 - 2.0 * t); }

// n / |n|, or the tangent-space up vector where n is zero (opposite normals cancelling).
void normalise_or_up(double n[3]) {
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int c = 0; c < 3; ++c) n[c] = len > 0.0 ? n[c] / len : (c == 2 ? 1.0 : 0.0);
}

// The cell's sample at corner k (C0..C3: top-left, top-right, bottom-right, bottom-left).
struct CellCorners {
  uint32_t i[4], j[4];
};

CellCorners cell_corners(uint32_t ci, uint32_t cj) { return {{ci, ci + 1, ci + 1, ci}, {cj, cj, cj + 1, cj + 1}}; }

// The normals of a cell's corners as one region sees them. A sample that lies on a crease (distance under
// kCreaseOnCurveDistance: the crossings beside it were only nudged off it) holds a normal of either side, or a
// mix, so it does not speak for the region when the region reaches a corner off the curve: seen from a
// neighbouring corner along their edge it takes that corner's normal, and at a point p of the cell the
// neighbours' normals weighted by p's distance from it along each edge. So every edge without a crossing
// carries the same values seen from either cell (continuity), and a planar facet is reproduced exactly. A
// corner with no such neighbour in the region takes the mean of the region's corners off the curve; a region
// whose corners all lie on the curve keeps their own normals. Distance and gradient are exact at every sample
// and are not replaced. (Deviation [Parilov05]: the paper assumes every sample lies strictly on one side.)
class RegionCornerNormals {
 public:
  RegionCornerNormals(const CreaseField& f, const CellCorners& c, const bool reach[4]) {
    double mean[3] = {0, 0, 0};
    int trusted = 0;
    bool on_curve[4];
    for (int k = 0; k < 4; ++k) {
      const float* sample = f.sample_normal(c.i[k], c.j[k]);
      for (int a = 0; a < 3; ++a) own_[k][a] = sample[a];
      on_curve[k] = f.distance[f.sample_index(c.i[k], c.j[k])] < kCreaseOnCurveDistance;
      trusted_[k] = reach[k] && !on_curve[k];
      if (trusted_[k]) {
        for (int a = 0; a < 3; ++a) mean[a] += own_[k][a];
        ++trusted;
      }
    }
    for (int k = 0; k < 4; ++k) replaced_[k] = trusted > 0 && reach[k] && on_curve[k];
    for (int a = 0; a < 3; ++a) mean_[a] = trusted ? mean[a] / trusted : 0.0;
  }

  // Corner k's normal seen along its edge from neighbour corner m.
  void along_edge(int k, int m, double out[3]) const {
    const double* n = !replaced_[k] ? own_[k] : trusted_[m] ? own_[m] : mean_;
    std::copy(n, n + 3, out);
  }

  // Corner k's normal at the cell-local point p.
  void at(int k, const double p[2], double out[3]) const {
    if (!replaced_[k]) {
      std::copy(own_[k], own_[k] + 3, out);
      return;
    }
    // Neighbour k + 1 lies along edge k, k - 1 along edge k - 1; p's distance from corner k along each.
    const int next = (k + 1) % 4, prev = (k + 3) % 4;
    const double corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const int next_axis = k % 2 == 0 ? 0 : 1, prev_axis = 1 - next_axis;
    const double w_next = trusted_[next] ? std::abs(p[next_axis] - corner[k][next_axis]) : 0.0;
    const double w_prev = trusted_[prev] ? std::abs(p[prev_axis] - corner[k][prev_axis]) : 0.0;
    if (!(w_next + w_prev > 0.0)) {
      const double* n = trusted_[next] ? own_[next] : trusted_[prev] ? own_[prev] : mean_;
      std::copy(n, n + 3, out);
      return;
    }
    for (int a = 0; a < 3; ++a) out[a] = (w_next * own_[next][a] + w_prev * own_[prev][a]) / (w_next + w_prev);
  }

 private:
  double own_[4][3];
  bool trusted_[4], replaced_[4];
  double mean_[3];
};

// No discontinuity touches the cell: bilinear interpolation (Sec. 4.3), continuous with the partition of a
// neighbour, which is linear along every edge without a crossing. p: the point in cell-local coordinates.
void reconstruct_bilinear(const CreaseField& f, const double p[2], const CellCorners& c, CreaseSample& out) {
  const double w[4] = {(1 - p[0]) * (1 - p[1]), p[0] * (1 - p[1]), p[0] * p[1], (1 - p[0]) * p[1]};
  double g[2] = {0, 0}, side = 0;
  out.distance = 0.0;
  for (int k = 0; k < 4; ++k) {
    const size_t s = f.sample_index(c.i[k], c.j[k]);
    out.distance += w[k] * f.distance[s];
    g[0] += w[k] * f.gradient[2 * s], g[1] += w[k] * f.gradient[2 * s + 1];
    side += f.side[s];
  }
  const double glen = std::hypot(g[0], g[1]);
  if (glen > 1e-12) out.gradient[0] = g[0] / glen, out.gradient[1] = g[1] / glen;
  out.side = side >= 0 ? 1 : -1;
  out.triangle = -1;
  const bool all[4] = {true, true, true, true};
  const RegionCornerNormals corner_normals(f, c, all);
  double n[4][3];
  for (int k = 0; k < 4; ++k) corner_normals.at(k, p, n[k]);
  for (int a = 0; a < 3; ++a) out.normal[a] = w[0] * n[0][a] + w[1] * n[1][a] + w[2] * n[2][a] + w[3] * n[3][a];
  normalise_or_up(out.normal);
}

// The partition of a cell with crossings (Sec. 4.2): vertices C0..C3 (0..3), P0..P3 (4..7) and E (8) in cell-local
// coordinates; triangles T_k = (P_{k-1}, C_k, P_k) and I_k = (E, P_k, P_{k+1}); regions = triangles joined across
// partition edges that are not segments.
struct CellPartition {
  double pos[9][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  int tri[8][3];
  double s02 = 0.0, s13 = 0.0;  // without a junction, E = P0 + s02 (P2 - P0) = P1 + s13 (P3 - P1)
  bool junction = false;        // E is a junction: its spokes are segments
  uint16_t seg = 0;             // the segment bits of the cell's signature
  UnionFind regions;
};

CellPartition cell_partition(const CreaseCellEdges& e) {
  CellPartition c;
  double(&pos)[9][2] = c.pos;
  for (int k = 0; k < 4; ++k) pos[4 + k][0] = e.px[k], pos[4 + k][1] = e.py[k];
  pos[8][0] = e.ex, pos[8][1] = e.ey;
  // Without a junction E is where P0P2 (top to bottom: its parameter is v) crosses P1P3 (right to left: 1 - u).
  c.s02 = e.ey, c.s13 = 1.0 - e.ex;
  c.junction = e.junction;
  for (int k = 0; k < 4; ++k) {
    c.tri[k][0] = 4 + (k + 3) % 4, c.tri[k][1] = k, c.tri[k][2] = 4 + k;
    c.tri[4 + k][0] = 8, c.tri[4 + k][1] = 4 + k, c.tri[4 + k][2] = 4 + (k + 1) % 4;
  }
  c.seg = e.mask & kCreaseSegmentBits;
  for (int k = 0; k < 4; ++k) {
    if (!((c.seg >> ((k + 3) % 4)) & 1u)) c.regions.join(k, 4 + (k + 3) % 4);  // T_k - I_{k-1} across P_{k-1}P_k
    const int spoke = (k + 1) % 4;                                             // I_k - I_{k+1} across E P_{k+1}
    if (!((e.spokes >> spoke) & 1u)) c.regions.join(4 + k, 4 + spoke);
  }
  return c;
}

// The point's triangle: the one where its smallest barycentric coordinate is largest; lambda its coordinates there.
int containing_triangle(const CellPartition& c, const double p[2], double lambda[3]) {
  int best = 0;
  double best_min = -1e300;
  for (int t = 0; t < 8; ++t) {
    double l[3];
    barycentric(p, c.pos[c.tri[t][0]], c.pos[c.tri[t][1]], c.pos[c.tri[t][2]], l);
    const double m = std::min({l[0], l[1], l[2]});
    if (m > best_min) best_min = m, best = t, std::copy(l, l + 3, lambda);
  }
  return best;
}

// The values at the partition's vertices C0..C3 and P0..P3 as seen from `region`: the corners it reaches keep their
// samples; an edge point interpolates the corners of its edge that the region reaches (or takes the one, or the
// region's mean), with distance 0 where a crease crosses the edge. Sets `side` from the reached corners.
void vertex_values(const CreaseField& f, const CreaseCellEdges& e, const CellCorners& cc, const bool reach[4],
                   const double p[2], Values value[9], int& side) {
  const RegionCornerNormals normals(f, cc, reach);
  Values corner[4];
  for (int k = 0; k < 4; ++k) {
    const size_t s = f.sample_index(cc.i[k], cc.j[k]);
    corner[k].d = f.distance[s];
    corner[k].g[0] = f.gradient[2 * s], corner[k].g[1] = f.gradient[2 * s + 1];
    const float* n = f.sample_normal(cc.i[k], cc.j[k]);
    for (int c = 0; c < 3; ++c) corner[k].n[c] = n[c];
  }
  Values region_mean;
  int reached = 0, side_sum = 0;
  for (int k = 0; k < 4; ++k)
    if (reach[k]) {
      accumulate(region_mean, corner[k], 1.0);
      side_sum += f.side[f.sample_index(cc.i[k], cc.j[k])];
      ++reached;
    }
  if (reached) region_mean = scaled(region_mean, 1.0 / reached);
  side = side_sum >= 0 ? 1 : -1;
  for (int k = 0; k < 4; ++k) {
    value[k] = corner[k];
    normals.at(k, p, value[k].n);
  }
  for (int k = 0; k < 4; ++k) {
    const int a = k, b = (k + 1) % 4;
    const double t = e.along[k];
    Values ca = corner[a], cb = corner[b];
    normals.along_edge(a, b, ca.n);
    normals.along_edge(b, a, cb.n);
    Values v;
    if (reach[a] && reach[b])
      v = lerp(ca, cb, t);
    else if (reach[a])
      v = ca;
    else if (reach[b])
      v = cb;
    else
      v = region_mean;
    v.d = e.crossing[k] ? 0.0 : (1 - t) * corner[a].d + t * corner[b].d;
    value[4 + k] = v;
  }
}

// E's value seen from `region` (needed only inside an inner triangle): along the crease through it when the region
// lies on both of its ends, else the mean of the edge points the region touches; distance 0 on a crease.
Values centre_value(const CellPartition& c, int region, const Values value[9]) {
  const bool through02 = (c.seg >> 4) & 1u, through13 = (c.seg >> 5) & 1u;
  bool touches[4] = {false, false, false, false};
  UnionFind regions = c.regions;
  for (int k = 0; k < 4; ++k)
    if (regions.find(4 + k) == region) touches[k] = touches[(k + 1) % 4] = true;
  Values v;
  if (!c.junction && !through02 && !through13) {
    v = lerp(lerp(value[4], value[6], c.s02), lerp(value[5], value[7], c.s13), 0.5);
  } else if (through02 && touches[0] && touches[2]) {
    v = lerp(value[4], value[6], c.s02);
  } else if (through13 && touches[1] && touches[3]) {
    v = lerp(value[5], value[7], c.s13);
  } else {
    int n = 0;
    for (int k = 0; k < 4; ++k)
      if (touches[k]) accumulate(v, value[4 + k], 1.0), ++n;
    v = scaled(v, 1.0 / n);
  }
  if (c.junction || through02 || through13) v.d = 0.0;
  return v;
}

}  // namespace

CreaseSample reconstruct_crease(const CreaseField& f, double x, double y) {
  CreaseSample out;
  const uint32_t ci = clamp_cell(x, f.cells_x()), cj = clamp_cell(y, f.cells_y());
  out.cell_i = ci;
  out.cell_j = cj;
  const double p[2] = {std::clamp(x - (double(ci) - 0.5), 0.0, 1.0), std::clamp(y - (double(cj) - 0.5), 0.0, 1.0)};
  const CreaseCellEdges e = crease_cell_edges(f, ci, cj);
  const CellCorners corners = cell_corners(ci, cj);
  if (!(e.crossing[0] || e.crossing[1] || e.crossing[2] || e.crossing[3])) {
    reconstruct_bilinear(f, p, corners, out);
    return out;
  }
  CellPartition c = cell_partition(e);
  double lambda[3] = {0, 0, 0};
  const int best = containing_triangle(c, p, lambda);
  out.triangle = best;
  const int region = c.regions.find(best);
  bool reach[4];
  for (int k = 0; k < 4; ++k) reach[k] = c.regions.find(k) == region;
  Values value[9];
  vertex_values(f, e, corners, reach, p, value, out.side);
  if (best >= 4) value[8] = centre_value(c, region, value);

  Values r;
  for (int k = 0; k < 3; ++k) accumulate(r, value[c.tri[best][k]], lambda[k]);
  out.distance = std::max(0.0, r.d);
  const double glen = std::hypot(r.g[0], r.g[1]);
  if (glen > 1e-12) {
    out.gradient[0] = r.g[0] / glen, out.gradient[1] = r.g[1] / glen;
  } else {  // opposite gradients cancelling (on a medial axis): take the nearest vertex's
    const int v = c.tri[best][std::max_element(lambda, lambda + 3) - lambda];
    out.gradient[0] = value[v].g[0], out.gradient[1] = value[v].g[1];
  }
  std::copy(r.n, r.n + 3, out.normal);
  normalise_or_up(out.normal);
  return out;
}

void bilinear_normal(const CreaseField& f, double x, double y, double out[3]) {
  const uint32_t ci = clamp_cell(x, f.cells_x()), cj = clamp_cell(y, f.cells_y());
  const double u = std::clamp(x - (double(ci) - 0.5), 0.0, 1.0), v = std::clamp(y - (double(cj) - 0.5), 0.0, 1.0);
  const float* n00 = f.sample_normal(ci, cj);
  const float* n10 = f.sample_normal(ci + 1, cj);
  const float* n01 = f.sample_normal(ci, cj + 1);
  const float* n11 = f.sample_normal(ci + 1, cj + 1);
  for (int c = 0; c < 3; ++c) out[c] = (1 - v) * ((1 - u) * n00[c] + u * n10[c]) + v * ((1 - u) * n01[c] + u * n11[c]);
  normalise_or_up(out);
}

double CreaseProfile::slope(double d, int side) const {
  if (!(d < width)) return 0.0;
  switch (kind) {
    case CreaseProfileKind::v:
      return depth / width;
    case CreaseProfileKind::rounded:
      return 2.0 * depth * d / (width * width);
    case CreaseProfileKind::step:
      return side > 0 ? depth / width : 0.0;
    case CreaseProfileKind::table: {
      const size_t n = table.size();
      const double step = width / double(n - 1);
      const size_t k = std::min(n - 2, size_t(d / step));
      return (table[k + 1] - table[k]) / step;
    }
  }
  return 0.0;
}

double crease_blend(const CreaseProfile& profile, double d) {
  if (d >= profile.blend_end) return 1.0;
  if (d <= profile.blend_start) return 0.0;
  return smoothstep((d - profile.blend_start) / (profile.blend_end - profile.blend_start));
}

namespace {
// In enum order.
constexpr const char* kProfileKindNames[] = {"v", "rounded", "step", "table"};
}  // namespace

std::string crease_profile_kind_names() { return "v, rounded, step, table"; }

const char* crease_profile_kind_name(CreaseProfileKind kind) { return kProfileKindNames[int(kind)]; }

bool parse_crease_profile_kind(const std::string& name, CreaseProfileKind& kind) {
  for (int k = 0; k < 4; ++k)
    if (name == kProfileKindNames[k]) {
      kind = CreaseProfileKind(k);
      return true;
    }
  return false;
}

void crease_normal(const CreaseSample& s, const CreaseProfile& profile, double out[3]) {
  const double b = crease_blend(profile, s.distance);
  const double slope = b < 1.0 ? profile.slope(s.distance, s.side) : 0.0;
  const double bt = b * std::sqrt(slope * slope + 1.0);  // |g| = 1
  out[0] = -(1.0 - b) * slope * s.gradient[0] + bt * s.normal[0];
  out[1] = (1.0 - b) * slope * s.gradient[1] + bt * s.normal[1];  // g's y runs down, tangent y up
  out[2] = (1.0 - b) + bt * s.normal[2];
  const double len = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
  for (int c = 0; c < 3; ++c) out[c] /= len;
}

}  // namespace mbk
