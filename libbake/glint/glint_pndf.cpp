// The P-NDF by implicit-hierarchy traversal, brute force and sampling ([Wang20] Eqs. 1-3, Alg. 3, Sec. 5.2-5.3):
// see glint_pndf.h.
#include "libbake/glint/glint_pndf.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include "formats/error.h"
#include "libbake/glint/glint_technique.h"

namespace mbk {
namespace {

constexpr int kK = kGlintSubElementsPerAxis;

// Position of sub-element a (0..K-1) of texel t along one axis: t + (a + 1/2) / K.
double sub_element_position(int64_t t, int a) { return double(t) + (a + 0.5) / kK; }

int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a - 1) / b) - 1; }

// The separable factor of the sub-element masses along one axis, K per texel in order (texel lo's first):
// exp(-(x - c)^2 / (2 (sigma_p^2 + sigma_h'^2))) at each sub-element position x.
std::vector<double> axis_weights(int64_t lo, int64_t hi, double c, double sigma_p) {
  const double var = sigma_p * sigma_p + kGlintSubElementSigmaTexels * kGlintSubElementSigmaTexels;
  std::vector<double> w;
  w.reserve(size_t(hi - lo + 1) * kK);
  for (int64_t t = lo; t <= hi; ++t)
    for (int a = 0; a < kK; ++a) {
      const double d = sub_element_position(t, a) - c;
      w.push_back(std::exp(-0.5 * d * d / var));
    }
  return w;
}

// The element of normal sample q at u with spatial sigma sigma_h, as the footprint's slope field sees it
// (glint_pndf.h): n' = n - K (u - c), J' = J - K.
PositionNormalElement element_at(const NormalSample& q, const Vec2& u, double sigma_h,
                                 const GlintFootprint& footprint) {
  const Mat2& k = footprint.slope;
  return {u, q.n - k * (u - footprint.center), q.jacobian - k, sigma_h};
}

// The centre of sub-element (a0, a1) of texel (t0, t1).
Vec2 sub_element_centre(int64_t t0, int64_t t1, int a0, int a1) {
  return Vec2(sub_element_position(t0, a0), sub_element_position(t1, a1));
}

// Whether G^-1 bends within the sub-element's range of z (glint_technique.h): per channel, with z its blend before
// G^-1 and dz its gradient, the range z +- delta, delta = (|dz_0| + |dz_1|) times kGlintRefinementReachSigmas
// sub-element sigmas, and the tangent slope g = dn / dz at z, the error e = max |G^-1(z +- delta) - (n +- g delta)|
// exceeds both kGlintRefinementSigmas sigma_r and kGlintRefinementBend |g| delta. Two inverse lookups per channel;
// only under histogram blending.
bool bends_within(const GlintPointQuery& point, const NormalSample& q, const NormalSample& z, double sigma_r) {
  constexpr double reach = kGlintRefinementReachSigmas * kGlintSubElementSigmaTexels;
  for (int ch = 0; ch < 2; ++ch) {
    const Vec2 dz = z.jacobian.row(ch).transpose();
    const double delta = (std::abs(dz.x()) + std::abs(dz.y())) * reach;
    if (!(delta > 0.0)) continue;
    const double g = q.jacobian.row(ch).dot(dz.transpose()) / dz.squaredNorm();  // J = g dz
    const StandardizationChannelTables& lut = point.lut()->channels[size_t(ch)];
    const double above = lut.destandardize(z.n[ch] + delta).value - (q.n[ch] + g * delta);
    const double below = lut.destandardize(z.n[ch] - delta).value - (q.n[ch] - g * delta);
    const double error = std::max(std::abs(above), std::abs(below));
    if (error > kGlintRefinementSigmas * sigma_r && error > kGlintRefinementBend * std::abs(g) * delta) return true;
  }
  return false;
}

// The R x R children of the sub-element at u (glint_technique.h): centres at u + ((b + 1/2) / R - 1/2) / K per
// axis, spatial sigma kGlintSubElementSigmaTexels / R, and weights that scale their masses to the sub-element's
// own, so that refining never changes the P-NDF's normalisation (sum m).
struct Children {
  std::array<Vec2, size_t(kGlintRefinementPerAxis* kGlintRefinementPerAxis)> centre;
  std::array<double, size_t(kGlintRefinementPerAxis* kGlintRefinementPerAxis)> mass;  // each, before scaling
  double scale = 0.0;                                                                 // parent mass / sum
};
constexpr double kChildSigma = kGlintSubElementSigmaTexels / kGlintRefinementPerAxis;

Children children_of(const Vec2& u, const GlintFootprint& footprint, double sigma_r) {
  constexpr int R = kGlintRefinementPerAxis;
  Children c;
  double sum = 0.0;
  for (int b1 = 0; b1 < R; ++b1)
    for (int b0 = 0; b0 < R; ++b0) {
      const size_t i = size_t(b1 * R + b0);
      c.centre[i] = u + Vec2((b0 + 0.5) / R - 0.5, (b1 + 0.5) / R - 0.5) / kK;
      c.mass[i] = element_footprint_mass(c.centre[i], kChildSigma, footprint, sigma_r);
      sum += c.mass[i];
    }
  const double parent = element_footprint_mass(u, kGlintSubElementSigmaTexels, footprint, sigma_r);
  c.scale = sum > 0.0 ? parent / sum : 0.0;  // both underflow together far outside the footprint
  return c;
}

// The sub-element at u as evaluation and sampling both see it: its element, and its children where G^-1 bends
// over it (histogram blending only), so that the two can never disagree on the refinement rule.
struct SubElement {
  PositionNormalElement element;
  std::optional<Children> children;
};

SubElement sub_element_at(const GlintPointQuery& point, const Vec2& u, const GlintFootprint& footprint,
                          double sigma_r) {
  const bool histogram = point.mode() == GlintBlendMode::histogram;
  NormalSample z;
  const NormalSample q = point.evaluate(u, histogram ? &z : nullptr);
  SubElement out{element_at(q, u, kGlintSubElementSigmaTexels, footprint), std::nullopt};
  if (histogram && bends_within(point, q, z, sigma_r)) out.children = children_of(u, footprint, sigma_r);
  return out;
}

// Bounds b shifted by -K (u - c) over the texels [x_lo, x_hi] x [y_lo, y_hi] grown by the element reach
// (glint_pndf.h): per component, the interval of K (u - c) over that box is subtracted.
RmqBounds shifted(const RmqBounds& b, const GlintFootprint& footprint, int64_t x_lo, int64_t x_hi, int64_t y_lo,
                  int64_t y_hi) {
  const Mat2& k = footprint.slope;
  if (k.isZero(0.0)) return b;
  const double r = kGlintElementReachTexels;
  const Vec2 lo(double(x_lo) + 0.5 - r - footprint.center.x(), double(y_lo) + 0.5 - r - footprint.center.y());
  const Vec2 hi(double(x_hi) + 0.5 + r - footprint.center.x(), double(y_hi) + 0.5 + r - footprint.center.y());
  Vec2 shift_lo, shift_hi;
  for (int i = 0; i < 2; ++i) {
    shift_lo[i] = std::min(k(i, 0) * lo.x(), k(i, 0) * hi.x()) + std::min(k(i, 1) * lo.y(), k(i, 1) * hi.y());
    shift_hi[i] = std::max(k(i, 0) * lo.x(), k(i, 0) * hi.x()) + std::max(k(i, 1) * lo.y(), k(i, 1) * hi.y());
  }
  return {b.min_x - shift_hi.x(), b.max_x - shift_lo.x(), b.min_y - shift_hi.y(), b.max_y - shift_lo.y()};
}

// Whether s lies outside the box b widened by the normal cut-off m.
bool outside(const RmqBounds& b, const Vec2& s, double m) {
  return s.x() < b.min_x - m || s.x() > b.max_x + m || s.y() < b.min_y - m || s.y() > b.max_y + m;
}

// Index i with probability w_i / sum w, from u in [0, 1) (inversion of the running sum).
size_t pick(std::span<const double> w, double u) {
  double total = 0.0;
  for (const double x : w) total += x;
  double target = u * total, run = 0.0;
  for (size_t i = 0; i < w.size(); ++i) {
    run += w[i];
    if (target < run) return i;
  }
  return w.size() - 1;
}

std::vector<double> running_sums(const std::vector<double>& w) {
  std::vector<double> out(w.size() + 1, 0.0);
  for (size_t i = 0; i < w.size(); ++i) out[i + 1] = out[i] + w[i];
  return out;
}

// The sub-element masses of a footprint's texels: common * wx_i * wy_j (separable), kept as running sums of the
// axis factors so that any rectangle's mass is two differences; total() is the P-NDF's normalizer.
struct FootprintMasses {
  std::vector<double> prefix_x, prefix_y;  // K per texel, from the footprint's first texel
  double common = 0.0;                     // element_footprint_mass at the footprint's centre

  FootprintMasses(const GlintFootprint& footprint, const TexelRange& t, double sigma_r)
      : prefix_x(running_sums(axis_weights(t.t0_lo, t.t0_hi, footprint.center.x(), footprint.sigma))),
        prefix_y(running_sums(axis_weights(t.t1_lo, t.t1_hi, footprint.center.y(), footprint.sigma))),
        common(element_footprint_mass(footprint.center, kGlintSubElementSigmaTexels, footprint, sigma_r)) {}
  double total() const { return common * prefix_x.back() * prefix_y.back(); }
};

}  // namespace

TexelRange footprint_texels(const GlintFootprint& footprint) {
  const double s = footprint.sigma;
  if (!(std::isfinite(s) && s > 0.0) || !std::isfinite(footprint.center.x()) || !std::isfinite(footprint.center.y()) ||
      !footprint.slope.allFinite())
    throw Error(ExitCode::invalid_input, "P-NDF footprint needs a finite centre, a finite sigma > 0 and a finite slope",
                "P-NDF");
  const double r = kGlintFootprintCutoffSigmas * s;
  constexpr double kLimit = 4.0e18;  // the texel indices must fit in int64 with room for patch arithmetic
  const Vec2& c = footprint.center;
  if (std::abs(c.x()) + r > kLimit || std::abs(c.y()) + r > kLimit)
    throw Error(ExitCode::invalid_input, "P-NDF footprint lies too far from the origin", "P-NDF");
  // Centre t + 0.5 in [c - r, c + r].
  return {int64_t(std::ceil(c.x() - r - 0.5)), int64_t(std::floor(c.x() + r - 0.5)),
          int64_t(std::ceil(c.y() - r - 0.5)), int64_t(std::floor(c.y() + r - 0.5))};
}

double point_ndf(const GlintPointQuery& point, const Vec2& u, double sigma_r, const Vec2& s) {
  if (!(std::isfinite(sigma_r) && sigma_r > 0.0))
    throw Error(ExitCode::invalid_input, "point NDF intrinsic roughness must be finite and > 0", "P-NDF");
  const double r2 = (s - point.evaluate(u).n).squaredNorm() / (sigma_r * sigma_r);
  return std::exp(-0.5 * r2) / (2.0 * std::numbers::pi * sigma_r * sigma_r);
}

GlintPndf::GlintPndf(const GlintRangeQuery& range, double sigma_r) : range_(&range), sigma_r_(sigma_r) {
  if (!(std::isfinite(sigma_r) && sigma_r > 0.0))
    throw Error(ExitCode::invalid_input, "P-NDF intrinsic roughness must be finite and > 0", "P-NDF");
}

RmqBounds GlintPndf::element_box(int64_t t0, int64_t t1, const GlintFootprint& footprint) const {
  return shifted(range_->element_bounds(t0, t1), footprint, t0, t0, t1, t1);
}

double GlintPndf::sub_element_sum(int64_t t0, int64_t t1, const GlintFootprint& footprint, const Vec2& s) const {
  const GlintPointQuery& point = range_->point();
  double sum = 0.0;
  for (int a1 = 0; a1 < kK; ++a1)
    for (int a0 = 0; a0 < kK; ++a0) {
      const SubElement e = sub_element_at(point, sub_element_centre(t0, t1, a0, a1), footprint, sigma_r_);
      if (!e.children) {
        sum += element_footprint_integral(e.element, footprint, sigma_r_, s);
        continue;
      }
      double children = 0.0;
      for (const Vec2& v : e.children->centre)
        children += element_footprint_integral(element_at(point.evaluate(v), v, kChildSigma, footprint), footprint,
                                               sigma_r_, s);
      sum += e.children->scale * children;
    }
  return sum;
}

double GlintPndf::element_term(int64_t t0, int64_t t1, const GlintFootprint& footprint, const Vec2& s) const {
  if (outside(element_box(t0, t1, footprint), s, kGlintNormalCutoffSigmas * sigma_r_)) return 0.0;
  return sub_element_sum(t0, t1, footprint, s);
}

double GlintPndf::evaluate_brute_force(const GlintFootprint& footprint, const Vec2& s) const {
  const TexelRange t = footprint_texels(footprint);
  if (t.empty()) return 0.0;
  double sum = 0.0;
  for (int64_t t1 = t.t1_lo; t1 <= t.t1_hi; ++t1)
    for (int64_t t0 = t.t0_lo; t0 <= t.t0_hi; ++t0) sum += element_term(t0, t1, footprint, s);
  return sum / FootprintMasses(footprint, t, sigma_r_).total();
}

struct GlintPndf::Query {
  const GlintFootprint& footprint;
  Vec2 s;
  TexelRange texels;
  bool aggregate;
  FootprintMasses masses;
};

// The closed form of an aggregated node (glint_pndf.h, "Aggregation"): the node's mass times the Gaussian around
// the centre of its box b. The node is the texels [x, x + w) x [y, y + h).
double GlintPndf::aggregated_term(const RmqBounds& b, int64_t x, int64_t y, int64_t w, int64_t h,
                                  const Query& q) const {
  const int64_t mx = (x - q.texels.t0_lo) * kK, my = (y - q.texels.t1_lo) * kK;
  const FootprintMasses& m = q.masses;
  const double mass = m.common * (m.prefix_x[size_t(mx + w * kK)] - m.prefix_x[size_t(mx)]) *
                      (m.prefix_y[size_t(my + h * kK)] - m.prefix_y[size_t(my)]);
  const Vec2 centre(0.5 * (b.min_x + b.max_x), 0.5 * (b.min_y + b.max_y));
  const double ir2 = 1.0 / (sigma_r_ * sigma_r_);
  return mass * ir2 * std::exp(-0.5 * (q.s - centre).squaredNorm() * ir2) / (2.0 * std::numbers::pi);
}

double GlintPndf::traverse(const TargetNode& node, const Query& q, PndfStatistics& stats) const {
  ++stats.nodes_visited;
  const int64_t h = range_->target_side();
  const int64_t x = node.patch_i * h + node.x0, y = node.patch_j * h + node.y0;
  const bool leaf = node.width == 1 && node.height == 1;
  uint32_t lookups = 0;
  const RmqBounds b =
      leaf ? element_box(x, y, q.footprint)
           : shifted(range_->node_bounds(node, &lookups), q.footprint, x, x + node.width - 1, y, y + node.height - 1);
  stats.rmq_lookups += lookups;
  if (outside(b, q.s, kGlintNormalCutoffSigmas * sigma_r_)) return 0.0;
  const double narrow = kGlintAggregateWidthSigmas * sigma_r_;
  if (q.aggregate && b.max_x - b.min_x <= narrow && b.max_y - b.min_y <= narrow) {
    ++stats.nodes_aggregated;
    return aggregated_term(b, x, y, node.width, node.height, q);
  }
  if (leaf) {
    const double v = sub_element_sum(x, y, q.footprint, q.s);
    if (v != 0.0) ++stats.elements_evaluated;
    return v;
  }
  const uint32_t w0 = (node.width + 1) / 2, h0 = (node.height + 1) / 2;
  double sum = 0.0;
  for (int qy = 0; qy < 2; ++qy)
    for (int qx = 0; qx < 2; ++qx) {
      TargetNode child = node;
      child.x0 = node.x0 + (qx ? w0 : 0);
      child.width = qx ? node.width - w0 : w0;
      child.y0 = node.y0 + (qy ? h0 : 0);
      child.height = qy ? node.height - h0 : h0;
      if (child.width > 0 && child.height > 0) sum += traverse(child, q, stats);
    }
  return sum;
}

double GlintPndf::evaluate(const GlintFootprint& footprint, const Vec2& s, PndfStatistics* stats,
                           bool aggregate) const {
  const TexelRange t = footprint_texels(footprint);
  if (t.empty()) return 0.0;
  const Query q{footprint, s, t, aggregate, FootprintMasses(footprint, t, sigma_r_)};
  PndfStatistics local;
  const int64_t h = range_->target_side();
  double sum = 0.0;
  // One root node per target patch the footprint covers ([Wang20] Sec. 5.2), however many.
  for (int64_t pj = floor_div(t.t1_lo, h); pj <= floor_div(t.t1_hi, h); ++pj)
    for (int64_t pi = floor_div(t.t0_lo, h); pi <= floor_div(t.t0_hi, h); ++pi) {
      const int64_t x_lo = std::max(t.t0_lo, pi * h), x_hi = std::min(t.t0_hi, pi * h + h - 1);
      const int64_t y_lo = std::max(t.t1_lo, pj * h), y_hi = std::min(t.t1_hi, pj * h + h - 1);
      const TargetNode root{pi,
                            pj,
                            uint32_t(x_lo - pi * h),
                            uint32_t(y_lo - pj * h),
                            uint32_t(x_hi - x_lo + 1),
                            uint32_t(y_hi - y_lo + 1)};
      sum += traverse(root, q, local);
    }
  if (stats) {
    stats->nodes_visited += local.nodes_visited;
    stats->elements_evaluated += local.elements_evaluated;
    stats->rmq_lookups += local.rmq_lookups;
    stats->nodes_aggregated += local.nodes_aggregated;
  }
  return sum / q.masses.total();
}

std::optional<Vec2> GlintPndf::sample(const GlintFootprint& footprint, const std::function<double()>& uniform) const {
  const TexelRange t = footprint_texels(footprint);
  if (t.empty()) return std::nullopt;
  const std::vector<double> wx = axis_weights(t.t0_lo, t.t0_hi, footprint.center.x(), footprint.sigma);
  const std::vector<double> wy = axis_weights(t.t1_lo, t.t1_hi, footprint.center.y(), footprint.sigma);
  for (int attempt = 0; attempt < 64; ++attempt)
    if (const std::optional<Vec2> s = draw(footprint, t, wx, wy, uniform)) return s;
  return std::nullopt;
}

std::optional<Vec2> GlintPndf::sample_once(const GlintFootprint& footprint,
                                           const std::function<double()>& uniform) const {
  const TexelRange t = footprint_texels(footprint);
  if (t.empty()) return std::nullopt;
  return draw(footprint, t, axis_weights(t.t0_lo, t.t0_hi, footprint.center.x(), footprint.sigma),
              axis_weights(t.t1_lo, t.t1_hi, footprint.center.y(), footprint.sigma), uniform);
}

std::optional<Vec2> GlintPndf::draw(const GlintFootprint& footprint, const TexelRange& t, const std::vector<double>& wx,
                                    const std::vector<double>& wy, const std::function<double()>& uniform) const {
  const size_t i0 = pick(wx, uniform()), i1 = pick(wy, uniform());
  const int64_t t0 = t.t0_lo + int64_t(i0 / kK), t1 = t.t1_lo + int64_t(i1 / kK);
  const GlintPointQuery& point = range_->point();
  const SubElement picked =
      sub_element_at(point, sub_element_centre(t0, t1, int(i0 % kK), int(i1 % kK)), footprint, sigma_r_);
  PositionNormalElement e = picked.element;
  if (picked.children) {  // a child, with probability its share of the mass
    const Vec2& v = picked.children->centre[pick(picked.children->mass, uniform())];
    e = element_at(point.evaluate(v), v, kChildSigma, footprint);
  }
  const Vec2 s = sample_element_normal(e, footprint, sigma_r_, {uniform(), uniform(), uniform(), uniform()});
  if (outside(shifted(range_->element_bounds(t0, t1), footprint, t0, t0, t1, t1), s,
              kGlintNormalCutoffSigmas * sigma_r_))
    return std::nullopt;
  return s;
}

}  // namespace mbk
