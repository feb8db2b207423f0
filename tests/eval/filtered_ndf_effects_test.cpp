// The filtered-NDF effects at render time (libbake/eval/sh_effect.h, vmf_effect.h, toksvig_effect.h; [Han07]):
// - at the finest level (a magnified plane) sh, vmf and toksvig shade like plain normal mapping (the `mip`
//   effect), on a smooth map and on a bumpy one (vmf within 1%: it also shades the small spread of the normals a
//   magnified footprint covers, and is closer to the reference for it);
// - on a plane receding to the horizon they are closer to the brute-force reference than plain mip, because
//   the NDF under a large footprint is wide and mip's renormalised mean normal forgets it;
// - where normals cancel (a V-groove seen from afar) every effect stays finite (the kMaxFilteredAlpha cap);
// - reference mode reads no assets (the shaders return the raw-map baseline).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "libbake/eval/filtered_ndf_shading.h"
#include "libbake/eval/image_difference.h"
#include "libbake/eval/renderer.h"
#include "libbake/scene/bake_plan.h"
#include "tests/scene/scene_test_fixtures.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

using nlohmann::json;
using test::ScratchDir;

// One plane (material "m" with the given effect) seen by a camera; a point light, a directional light, a sky.
json plane_scene(const json& effect, const json& specular, const json& camera, const json& plane,
                 const json& point_light) {
  json material = {{"albedo", {0.3, 0.3, 0.3}}, {"specular", specular}, {"normal_map", {{"path", "map.exr"}}}};
  material["effects"] = json::array();
  if (!effect.is_null()) material["effects"].push_back(effect);
  json p = plane;
  p["type"] = "plane";
  p["material"] = "m";
  return {{"camera", camera},
          {"shapes", {p}},
          {"materials", {{"m", material}}},
          {"lights",
           {point_light,
            {{"type", "directional"}, {"direction", {0.2, -1.0, 0.4}}, {"irradiance", {0.4, 0.4, 0.4}}},
            {{"type", "sky"}, {"radiance", {0.05, 0.06, 0.08}}}}}};
}

Image render_with(const ScratchDir& dir, const json& scene_json, uint32_t reference = 0) {
  testing::write_json(dir / "s.json", scene_json);
  const Scene scene = load_scene(dir / "s.json");
  if (reference == 0) {
    std::filesystem::create_directories(default_asset_folder(scene));
    for (const PlannedAsset& a : plan_assets(scene))
      a.recipe.bake(Progress::silent()).write(default_asset_folder(scene) / a.file_name);
  }
  RenderSettings settings;
  settings.reference = reference;
  return render_scene(scene, load_render_inputs(scene, settings), settings, Progress::silent());
}

double mean(const Image& im) {
  double s = 0.0;
  for (const float v : im.pixels) s += v;
  return s / double(im.pixels.size());
}

// A camera close above a 2 x 2 plane carrying one 32 x 32 tile: ~5 pixels per texel (LOD 0 everywhere).
json magnified(const json& effect, const json& specular) {
  return plane_scene(
      effect, specular,
      {{"position", {0.0, 0.6, 0.6}}, {"look_at", {0.0, 0.0, 0.0}}, {"fov_y", 40}, {"width", 48}, {"height", 36}},
      {{"size", {2.0, 2.0}}, {"uv_scale", {1.0, 1.0}}},
      {{"type", "point"}, {"position", {0.3, 1.0, -0.4}}, {"intensity", {2.0, 2.0, 2.0}}});
}

// Gentle bumps, one period per tile: neighbouring normals differ by a few degrees.
void write_smooth_map(const std::filesystem::path& path) {
  testing::write_normal_map(path, 32, 32, [](uint32_t x, uint32_t row) {
    const double u = 2 * std::numbers::pi * (x + 0.5) / 32, v = 2 * std::numbers::pi * (row + 0.5) / 32;
    return Vec3(0.3 * std::cos(u), 0.25 * std::sin(v), 1.0);
  });
}

TEST(FilteredNdfEffects, FinestLevelEqualsPlainNormalMapping) {
  ScratchDir dir("filtered_finest");
  write_smooth_map(dir / "map.exr");
  const json specular = {{"distribution", "beckmann"}, {"roughness", 0.3}, {"f0", 0.3}};
  const Image plain = render_with(dir, magnified("mip", specular));
  for (const json& effect :
       {json{{"name", "sh"}, {"order", 24}, {"precision", "f32"}}, json{{"name", "vmf"}, {"lobes", 2}}}) {
    const Image filtered = render_with(dir, magnified(effect, specular));
    const ImageDifference d = compare_images(filtered, plain);
    EXPECT_LT(d.rmse, 0.01 * mean(plain)) << effect.dump() << ": rmse " << d.rmse << ", mean " << mean(plain);
  }
  // A low order too: its specular bands beyond 2 are completed from the mean normal's lobe (sh_lobe_tail.h), exact
  // for one normal per footprint; what is left is the order-2 diffuse (measured 1.5% of the mean; before the
  // completion the truncated specular put it over 3%).
  const double low = compare_images(render_with(dir, magnified({{"name", "sh"}, {"order", 2}}, specular)), plain).rmse;
  EXPECT_LT(low, 0.02 * mean(plain));
}

TEST(FilteredNdfEffects, MagnifiedBumpyMapMatchesPlainNormalMapping) {
  // LOD 0 on a map whose neighbouring normals differ by tens of degrees: the lookups take the renormalised
  // bilinear normal (filtered_ndf_textures.h, toksvig_effect.h), as plain normal mapping does. Before that, the
  // four taps as separate deltas (sh), a kappa lowered by the taps' spread (vmf) or Toksvig's widening from
  // the bilinear mean's length gave 3 times mip's error against the reference.
  ScratchDir dir("filtered_finest_bumpy");
  testing::write_bumpy_map(dir / "map.exr", 32, 32);
  const json specular = {{"distribution", "beckmann"}, {"roughness", 0.3}, {"f0", 0.3}};
  const Image plain = render_with(dir, magnified("mip", specular));
  const auto rmse = [&](const json& effect) {
    return compare_images(render_with(dir, magnified(effect, specular)), plain).rmse;
  };
  // Toksvig: the same normal and, with |n| = 1, no widening: the same image up to float rounding.
  EXPECT_LT(rmse("toksvig"), 1e-4 * mean(plain));
  // sh: what is left is the truncation of D at order 24. vmf reads each footprint at four points (its quarters,
  // filtered_ndf_textures.h), so it shades the small spread of the interpolated normals a 0.2-texel footprint
  // covers, which plain normal mapping does not: it must stay close to mip and be closer to the reference.
  // Measured: sh24 0.31%, vmf2 0.51% of the mean; against a 16 x 16 reference vmf2 0.00081, mip 0.00134.
  const double sh = rmse({{"name", "sh"}, {"order", 24}, {"precision", "f32"}}),
               vmf = rmse({{"name", "vmf"}, {"lobes", 2}});
  std::cout << "magnified bumpy map, rmse vs mip: sh24 " << sh << ", vmf2 " << vmf << " (mean " << mean(plain) << ")\n";
  EXPECT_LT(sh, 0.005 * mean(plain));
  EXPECT_LT(vmf, 0.01 * mean(plain));
  const Image reference = render_with(dir, magnified("mip", specular), 16);
  const double vmf_to_reference =
      compare_images(render_with(dir, magnified({{"name", "vmf"}, {"lobes", 2}}, specular)), reference).rmse;
  const double mip_to_reference = compare_images(plain, reference).rmse;
  std::cout << "against the reference: vmf2 " << vmf_to_reference << ", mip " << mip_to_reference << "\n";
  EXPECT_LT(vmf_to_reference, 0.8 * mip_to_reference);
}

TEST(FilteredNdfEffects, FinestLevelEqualsPlainNormalMapping_EnvironmentLight) {
  // Distant lighting alone, with bands 1 and 2: the sh shader's rotated irradiance integral and the vmf
  // shader's per-lobe Eq. (7.23) must give the baseline's irradiance at the finest level.
  ScratchDir dir("filtered_finest_env");
  write_smooth_map(dir / "map.exr");
  Image env;
  env.width = 32;
  env.height = 16;
  env.channels = 3;
  env.pixels.resize(size_t(32) * 16 * 3);
  for (uint32_t row = 0; row < 16; ++row)
    for (uint32_t x = 0; x < 32; ++x) {
      const double phi = 2 * std::numbers::pi * (x + 0.5) / 32, theta = std::numbers::pi * (row + 0.5) / 16;
      const double dx = std::sin(theta) * std::cos(phi), dz = std::sin(theta) * std::sin(phi);
      for (uint32_t c = 0; c < 3; ++c) env.at(x, row, c) = float(0.2 + 1.5 * std::max(0.0, -dx + 0.5 * dz));
    }
  save_image(dir / "env.exr", env);
  const json specular = {{"distribution", "beckmann"}, {"roughness", 0.3}, {"f0", 0.3}};
  const auto scene = [&](const json& effect) {
    json j = magnified(effect, specular);
    j["lights"] = {{{"type", "environment"}, {"path", "env.exr"}}};
    return j;
  };
  const Image plain = render_with(dir, scene("mip"));
  for (const json& effect :
       {json{{"name", "sh"}, {"order", 24}, {"precision", "f32"}}, json{{"name", "vmf"}, {"lobes", 2}}}) {
    const ImageDifference d = compare_images(render_with(dir, scene(effect)), plain);
    EXPECT_LT(d.rmse, 0.01 * mean(plain)) << effect.dump() << ": rmse " << d.rmse << ", mean " << mean(plain);
  }
}

// The first row whose pixels all differ from the sky row 0 shows, after the row the horizon crosses.
uint32_t first_row_below_the_horizon(const Image& im) {
  const auto sky = [&](uint32_t row) {
    for (uint32_t x = 0; x < im.width; ++x)
      if (im.at(x, row, 0) != im.at(0, 0, 0)) return false;
    return true;
  };
  uint32_t row = 0;
  while (row < im.height && sky(row)) ++row;
  return row + 1;
}

// The rows from `first` down.
Image crop_rows(const Image& im, uint32_t first) {
  Image out = im;
  out.height = im.height - first;
  out.pixels.assign(im.pixels.begin() + ptrdiff_t(size_t(first) * im.width * im.channels), im.pixels.end());
  return out;
}

// A plane receding to the horizon under a glossy highlight: footprints from ~4 texels to the whole map.
json receding(const json& effect) {
  return plane_scene(
      effect, {{"distribution", "ggx"}, {"roughness", 0.25}, {"f0", 0.5}},
      {{"position", {0.0, 0.4, 0.0}}, {"look_at", {0.0, 0.3, -8.0}}, {"fov_y", 20}, {"width", 48}, {"height", 32}},
      {{"center", {0.0, 0.0, -50.0}}, {"size", {100.0, 100.0}}, {"uv_scale", {100.0, 100.0}}},
      {{"type", "point"}, {"position", {0.0, 2.0, -25.0}}, {"intensity", {300.0, 300.0, 300.0}}});
}

TEST(FilteredNdfEffects, RecedingPlaneIsCloserToTheReferenceThanPlainMip) {
  ScratchDir dir("filtered_receding");
  testing::write_bumpy_map(dir / "map.exr", 32, 32);
  const Image reference = render_with(dir, receding("mip"), 12);
  // Below the horizon: the row the horizon crosses is part sky in the reference and all plane or all sky at one
  // sample per pixel, whatever the method (coverage, not filtering); it is left out with the sky above it.
  const uint32_t sky_rows = first_row_below_the_horizon(reference);
  ASSERT_LT(sky_rows + 8, reference.height);
  // From `first` down: the whole far field, and without its first row (the horizon's glare, where every method
  // overshoots the reference's mean 2.1 with 3.5-3.8).
  const auto error = [&](const json& effect, uint32_t first) {
    return compare_images(crop_rows(render_with(dir, receding(effect)), first), crop_rows(reference, first)).rmse;
  };
  const json sh16 = {{"name", "sh"}, {"order", 16}}, vmf4 = {{"name", "vmf"}, {"lobes", 4}};
  const double mip = error("mip", sky_rows), toksvig = error("toksvig", sky_rows), sh = error(sh16, sky_rows),
               vmf = error(vmf4, sky_rows);
  const double mip_below = error("mip", sky_rows + 1), toksvig_below = error("toksvig", sky_rows + 1),
               sh_below = error(sh16, sky_rows + 1), vmf_below = error(vmf4, sky_rows + 1);
  std::cout << "rmse vs reference: mip " << mip << ", toksvig " << toksvig << ", sh16 " << sh << ", vmf4 " << vmf
            << "; below the glare row: mip " << mip_below << ", toksvig " << toksvig_below << ", sh16 " << sh_below
            << ", vmf4 " << vmf_below << " (mean " << mean(reference) << ")\n";
  // Measured with the long footprints shaded in parts (sample_parts.h, the default): mip 0.71, toksvig 0.19, sh16
  // 0.25, vmf4 0.19 (mean 0.38); below the glare row mip 0.61, toksvig 0.17, sh16 0.22, vmf4 0.17. One shading
  // point per sample: mip 1.19, toksvig 0.65, sh16 0.82, vmf4 0.69; below the glare row mip 0.68, toksvig 0.19, vmf4
  // 0.19, sh16 0.27. Before lobe_specular.h (every factor at the lobe's mean) toksvig and vmf4 were 0.40 and
  // 0.39 there, and sh16 0.57 before its lobe correction (lobe_corrected_specular).
  EXPECT_LT(sh, 0.75 * mip);
  EXPECT_LT(vmf, 0.65 * mip);
  EXPECT_LT(toksvig, 0.65 * mip);
  EXPECT_LT(sh_below, 0.45 * mip_below);
  EXPECT_LT(vmf_below, 0.35 * mip_below);
  EXPECT_LT(toksvig_below, 0.35 * mip_below);
}

TEST(FilteredNdfEffects, ShNearSurfaceDoesNotRing) {
  // About 2 texels per pixel under a narrow GGX lobe: the footprint's NDF is nearly one normal, far sharper than
  // orders 2-8 can hold, and the truncated expansion smeared and rang the highlight, worse with every order
  // (measured here: sh2 0.064, sh4 0.11, sh8 0.21 against toksvig 0.026; the filtering report's near sphere: sh8
  // 0.35 against mip 0.044). With the bands beyond the order completed (sh_lobe_tail.h) the error must not grow
  // with the order and stay near the single-lobe (Toksvig) one: measured 0.040 for every order.
  ScratchDir dir("filtered_near_sh");
  testing::write_bumpy_map(dir / "map.exr", 256, 256);
  const json specular = {{"distribution", "ggx"}, {"roughness", 0.1}, {"f0", 0.5}};
  const Image reference = render_with(dir, magnified("mip", specular), 8);
  const auto error = [&](const json& effect) {
    return compare_images(render_with(dir, magnified(effect, specular)), reference).rmse;
  };
  const double toksvig = error("toksvig"), sh2 = error({{"name", "sh"}, {"order", 2}});
  for (const int order : {2, 4, 8}) {
    const double sh = order == 2 ? sh2 : error({{"name", "sh"}, {"order", order}});
    std::cout << "near surface, rmse vs reference: toksvig " << toksvig << ", sh" << order << " " << sh << "\n";
    EXPECT_LT(sh, 1.75 * toksvig) << "order " << order;
    EXPECT_LT(sh, 1.1 * sh2) << "order " << order;
  }
}

TEST(FilteredNdfEffects, CancellingNormalsStayFinite) {
  ScratchDir dir("filtered_vgroove");
  // A V-groove: alternate columns lean +x and -x almost to the horizon; two columns average to |n| ~ 0.1.
  testing::write_normal_map(dir / "map.exr", 8, 8,
                            [](uint32_t x, uint32_t) { return Vec3(x % 2 ? 0.995 : -0.995, 0.0, 0.1); });
  for (const json& effect : {json("toksvig"), json{{"name", "sh"}, {"order", 0}}, json{{"name", "sh"}, {"order", 4}},
                             json{{"name", "vmf"}, {"lobes", 1}}, json{{"name", "vmf"}, {"lobes", 2}}}) {
    const Image im = render_with(dir, receding(effect));
    for (const float v : im.pixels) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << effect.dump();
  }
}

TEST(FilteredNdfEffects, ReferenceReadsNoAssetsAndIsTheRawMap) {
  ScratchDir dir("filtered_reference");
  write_smooth_map(dir / "map.exr");
  const json specular = {{"roughness", 0.3}};
  const Image plain = render_with(dir, magnified(nullptr, specular), 2);
  for (const json& effect : {json("sh"), json("vmf"), json("toksvig")}) {
    const Image im = render_with(dir, magnified(effect, specular), 2);  // no bake: assets are never read
    EXPECT_EQ(im.pixels, plain.pixels) << effect.dump();
  }
}

TEST(FilteredNdfShading, MicrofacetRhatIsNormalised) {
  // rhat_1 = 2 pi integral D(t) t dt = 1 for a projected-area-normalised D, even for sharp lobes.
  for (const Distribution d : {Distribution::beckmann, Distribution::ggx})
    for (const double alpha : {0.01, 0.05, 0.2, 0.6, 1.0}) {
      const std::vector<double> rhat = microfacet_rhat({d, alpha}, 4);
      EXPECT_NEAR(rhat[1], 1.0, 1e-6) << "alpha " << alpha;
    }
}

}  // namespace
}  // namespace mbk
