// The point query of the blended microstructure and its analytic Jacobian ([Wang20] Sec. 4.2, Eqs. 4-6,
// appendix A.2): see blended_normal.h.
#include "libbake/glint/blended_normal.h"

#include <array>
#include <cmath>

#include "formats/error.h"

namespace mbk {

GlintPointQuery::GlintPointQuery(const NormalMap& example, uint32_t patch_side, uint32_t seed, GlintBlendMode mode,
                                 const StandardizationLut* lut)
    : example_(&example), grid_(example.width, example.height, patch_side, seed), mode_(mode), lut_(lut) {
  if (example.texels.empty() || example.texels.size() != size_t(example.width) * example.height)
    throw Error(ExitCode::invalid_input, "point query needs a non-empty example", "point query");
  if (mode == GlintBlendMode::histogram && lut == nullptr)
    throw Error(ExitCode::invalid_input, "histogram blending needs the example's standardization LUT", "point query");
  channels_ = normal_components(example);
  Vec2 sum = Vec2::Zero();  // serial, in texel order: deterministic
  for (const Vec2& t : channels_.texels) sum += t;
  mean_ = sum / double(channels_.texels.size());
  if (mode == GlintBlendMode::histogram)
    for (Vec2& t : channels_.texels)
      for (int ch = 0; ch < 2; ++ch) t[ch] = lut->channels[ch].standardize(t[ch]).value;
}

NormalSample GlintPointQuery::evaluate(const Vec2& u, NormalSample* gaussian) const {
  const TargetPatchLocation loc = grid_.locate(u);
  if (mode_ == GlintBlendMode::none) {
    const int k = (loc.local.x() >= 0.5 ? 1 : 0) + (loc.local.y() >= 0.5 ? 2 : 0);
    return sample_example_bilinear(channels_, loc.corners[k].example_point);
  }
  std::array<NormalSample, 4> s;
  for (int k = 0; k < 4; ++k) s[k] = sample_example_bilinear(channels_, loc.corners[k].example_point);

  double w_norm2 = 0.0;
  Vec2 w_norm2_half_gradient = Vec2::Zero();  // sum w_k dw_k = d(W^2)/2
  for (const TargetPatchCorner& c : loc.corners) {
    w_norm2 += c.weight * c.weight;
    w_norm2_half_gradient += c.weight * c.weight_gradient;
  }
  const double W = std::sqrt(w_norm2);
  const Vec2 dW = w_norm2_half_gradient / W;

  NormalSample out;
  for (int ch = 0; ch < 2; ++ch) {
    // The blended channel before any final transform: values v_k (I_k, or Z_k) with gradients dv_k.
    double L = 0.0;
    Vec2 dL = Vec2::Zero();
    for (int k = 0; k < 4; ++k) {
      const TargetPatchCorner& c = loc.corners[k];
      const double v = s[k].n[ch];
      const Vec2 dv = s[k].jacobian.row(ch).transpose();
      L += c.weight * v;
      dL += c.weight_gradient * v + c.weight * dv;
    }
    double n = L;
    Vec2 dn = dL;
    if (mode_ != GlintBlendMode::linear) {
      const double m = mode_ == GlintBlendMode::variance ? mean_[ch] : 0.0;
      n = (L - m) / W + m;
      dn = dL / W - (L - m) * dW / w_norm2;
    }
    if (mode_ == GlintBlendMode::histogram) {
      if (gaussian) {
        gaussian->n[ch] = n;
        gaussian->jacobian.row(ch) = dn.transpose();
      }
      const LutSample inv = lut_->channels[ch].destandardize(n);
      n = inv.value;
      dn *= inv.derivative;
    }
    out.n[ch] = n;
    out.jacobian.row(ch) = dn.transpose();
  }
  return out;
}

}  // namespace mbk
