// The `histogram` scene effect (libbake/scene/effect_histogram.cpp, libbake/eval/histogram_effect.h; [Shah24]): it
// bakes only the map's histogram asset with canonical options (plus the baseline every material with effects has),
// refuses bad options naming them; the filtered render of binned P-NDFs under an environment map and a point light
// agrees with the Monte Carlo reference of Eq. 2 (which reads no asset) within twice the reference's own floor on
// block means, for a constant roughness and for a roughness texture; a roughness texture changes the picture without
// a rebake, and a constant roughness texture renders exactly as the same constant. A furnace, the check that does not
// share the effect's code with its reference: a flat mirror-like metal seen from above under a uniform white sky
// reflects f0 (every reflected lobe integrates the sky to 1; F = f0 at normal incidence; G2 = 1 for a base
// roughness near zero), by the effect and by the reference alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "formats/error.h"
#include "libbake/eval/image_difference.h"
#include "libbake/gen/generator.h"
#include "libbake/image/normal_map_encoding.h"
#include "libbake/scene/bake_plan.h"
#include "tests/eval/render_fixtures.h"
#include "tests/scene/scene_test_fixtures.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

using nlohmann::json;
using test::ScratchDir;
using testing::bake_scene;
using testing::render;

// A lat-long sky: a dim gradient and two soft-edged bright discs (a warm one and a cool one), float EXR.
void write_environment(const std::filesystem::path& path) {
  Image env;
  env.width = 128;
  env.height = 64;
  env.channels = 3;
  env.pixels.resize(size_t(env.width) * env.height * 3);
  const Vec3 warm_axis = Vec3(-0.45, 0.55, -0.7).normalized(), cool_axis = Vec3(0.8, 0.35, -0.45).normalized();
  for (uint32_t row = 0; row < env.height; ++row)
    for (uint32_t i = 0; i < env.width; ++i) {
      const double theta = std::numbers::pi * (row + 0.5) / env.height,
                   phi = 2 * std::numbers::pi * (i + 0.5) / env.width;
      const Vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      const auto disc = [&](const Vec3& axis) { return std::clamp((d.dot(axis) - 0.95) / 0.03, 0.0, 1.0); };
      const Vec3 l = Vec3::Constant(0.05 + 0.1 * std::max(d.y(), 0.0)) + disc(warm_axis) * Vec3(6.0, 5.5, 5.0) +
                     disc(cool_axis) * Vec3(1.5, 2.5, 4.0);
      for (uint32_t c = 0; c < 3; ++c) env.at(i, row, c) = float(l[c]);
    }
  save_image(path, env);
}

// A metal plane seen at ~30 degrees under the environment and one point light; `effect` is the histogram effect.
json plane_scene(const json& effect) {
  return {{"camera",
           {{"position", {0.0, 1.2, 2.2}},
            {"look_at", {0.0, 0.0, -0.3}},
            {"up", {0, 1, 0}},
            {"fov_y", 40},
            {"width", 48},
            {"height", 32}}},
          {"shapes",
           {{{"type", "plane"},
             {"center", {0, 0, 0}},
             {"normal", {0, 1, 0}},
             {"tangent", {1, 0, 0}},
             {"size", {4, 4}},
             {"uv_scale", {4, 4}},
             {"material", "metal"}}}},
          {"materials",
           {{"metal",
             {{"albedo", 0.02},
              {"specular", {{"distribution", "ggx"}, {"roughness", 0.1}, {"f0", {0.9, 0.88, 0.85}}}},
              {"normal_map", {{"path", "map.png"}, {"convention", "+Y"}}},
              {"effects", {effect}}}}}},
          {"lights",
           {{{"type", "environment"}, {"path", "env.exr"}},
            {{"type", "point"}, {"position", {-1, 2, -2}}, {"intensity", {10, 10, 10}}}}}};
}

void write_inputs(const std::filesystem::path& dir) {
  save_normal_map(dir / "map.png", generate_normal_map("scratches", {64, 64}, 1, Progress::silent()));
  write_environment(dir / "env.exr");
}

void write_roughness(const std::filesystem::path& path, const std::function<double(uint32_t, uint32_t)>& sigma) {
  Image im;
  im.width = im.height = 16;
  im.channels = 1;
  im.pixels.resize(256);
  for (uint32_t row = 0; row < 16; ++row)
    for (uint32_t x = 0; x < 16; ++x) im.at(x, row, 0) = float(sigma(x, row));
  save_image(path, im);
}

Scene scene_in(const std::filesystem::path& dir, const json& effect) {
  testing::write_json(dir / "s.json", plane_scene(effect));
  return load_scene(dir / "s.json");
}

// The effect (1 sample per pixel) and a second reference (another seed) against a reference of 8 x 8 rays, on
// 8 x 8 blocks.
struct BlockErrors {
  double effect, floor;
};
BlockErrors block_errors(const Scene& scene, const char* label) {
  const Image effect = render(scene, 1), reference = render(scene, 1, 8), other = render(scene, 1, 8, 1);
  const BlockErrors e{compare_images(effect, reference, 8).block_relative_l1,
                      compare_images(other, reference, 8).block_relative_l1};
  std::printf("[ info ] %s: effect %.4f, reference floor %.4f (8 x 8 blocks)\n", label, e.effect, e.floor);
  return e;
}

TEST(HistogramEffect, BakesOnlyTheHistogramWithCanonicalOptions) {
  ScratchDir dir("histogram_effect_plan");
  write_inputs(dir.path());
  const Scene scene = scene_in(dir.path(), {{"name", "histogram"}, {"phi_bins", 16}});
  std::vector<std::string> kinds;
  for (const PlannedAsset& a : plan_assets(scene)) kinds.push_back(a.recipe.kind);
  EXPECT_EQ(kinds, (std::vector<std::string>{"histogram", "mip"}));  // mip: the material's baseline
  EXPECT_EQ(scene.materials.at("metal").effects.at(0).options, (json{{"method", "exact"},
                                                                     {"theta_bins", 9},
                                                                     {"phi_bins", 16},
                                                                     {"theta_binning", "adaptive"},
                                                                     {"features", 16},
                                                                     {"iterations", 20000},
                                                                     {"batch", 512},
                                                                     {"seed", 1},
                                                                     {"roughness", 0.05},
                                                                     {"sh_order", 20}}));
  for (const json& bad :
       {json{{"name", "histogram"}, {"roughness", 0}}, json{{"name", "histogram"}, {"sh_order", 0}},
        json{{"name", "histogram"}, {"method", "lossy"}}, json{{"name", "histogram"}, {"sigma", 1}},
        json{{"name", "histogram"}, {"theta_binning", "kmeans"}}, json{{"name", "histogram"}, {"roughness_map", 3}}})
    EXPECT_THROW(scene_in(dir.path(), bad), Error) << bad.dump();
}

TEST(HistogramEffect, FlatMirrorUnderAUniformSkyReflectsF0ByEffectAndReference) {
  ScratchDir dir("histogram_effect_furnace");
  NormalMap flat;
  flat.width = flat.height = 8;
  flat.texels.assign(64, Vec3f(0, 0, 1));
  save_normal_map(dir / "map.exr", flat);
  Image sky;
  sky.width = 32;
  sky.height = 16;
  sky.channels = 3;
  sky.pixels.assign(size_t(32) * 16 * 3, 1.0f);
  save_image(dir / "env.exr", sky);
  for (const double f0 : {1.0, 0.5})
    for (const double sigma : {0.01, 0.05}) {
      SCOPED_TRACE("f0 " + std::to_string(f0) + ", sigma " + std::to_string(sigma));
      json s = plane_scene({{"name", "histogram"}, {"roughness", sigma}, {"sh_order", 40}});
      s["camera"] = {{"position", {0.0, 3.0, 0.0}},
                     {"look_at", {0.0, 0.0, 0.0}},
                     {"up", {0, 0, -1}},
                     {"fov_y", 20},
                     {"width", 16},
                     {"height", 16}};
      s["lights"] = json::array({{{"type", "environment"}, {"path", "env.exr"}}});
      json& metal = s["materials"]["metal"];
      metal["albedo"] = 0.0;
      metal["specular"] = {{"distribution", "ggx"}, {"roughness", 0.001}, {"f0", {f0, f0, f0}}};
      metal["normal_map"]["path"] = "map.exr";
      testing::write_json(dir / "s.json", s);
      const Scene scene = load_scene(dir / "s.json");
      bake_scene(scene);
      // Views within 6 degrees of the normal: (1 - cos)^5 < 1e-11, the lobe's mass below the horizon e^-(1/sigma^2).
      for (const Image& im : {render(scene, 1), render(scene, 1, 4)})
        for (size_t i = 0; i < im.pixels.size(); ++i) EXPECT_NEAR(im.pixels[i], f0, 0.01 * f0) << "value " << i;
    }
}

TEST(HistogramEffect, MatchesItsReferenceUnderAnEnvironmentAndAPointLight) {
  ScratchDir dir("histogram_effect_reference");
  write_inputs(dir.path());
  const Scene scene = scene_in(dir.path(), {{"name", "histogram"}, {"roughness", 0.05}, {"sh_order", 40}});
  bake_scene(scene);
  const BlockErrors e = block_errors(scene, "scratches, roughness 0.05, order 40");
  EXPECT_LT(e.effect, 2.0 * e.floor + 0.005);
}

// The plane scene with the map tiled 24 times across it (written to dir/file), so that most footprints span 8 texels
// or more and read a compressed source's prediction (smaller ones are counted exactly).
Scene tiled_plane(const ScratchDir& dir, const std::string& file, const json& effect) {
  json s = plane_scene(effect);
  s["shapes"][0]["uv_scale"] = {24, 24};
  testing::write_json(dir / file, s);
  return load_scene(dir / file);
}

// Block L1 of the exact table's render and of another source's against the exact scene's 8 x 8-ray reference, and
// between the two renders.
struct AgainstExact {
  double exact = 0, other = 0, apart = 0;
};
AgainstExact block_l1_against_exact(const Scene& exact, const Scene& other, const char* what) {
  bake_scene(exact);
  bake_scene(other);
  const Image reference = render(exact, 1, 8), exact_image = render(exact, 1), other_image = render(other, 1);
  const AgainstExact e{compare_images(exact_image, reference, 8).block_relative_l1,
                       compare_images(other_image, reference, 8).block_relative_l1,
                       compare_images(other_image, exact_image, 8).block_relative_l1};
  std::printf("[ info ] block L1 against the reference: exact %.4f, %s %.4f; %s vs exact %.4f\n", e.exact, what,
              e.other, what, e.apart);
  return e;
}

// The neural histogram behind the same shader: a short training on the 64^2 scratches map bakes only the
// neural_histogram asset, and its render stays near the reference, no further from it than a stated margin beyond
// the exact table's render (what a few hundred Adam steps cost).
TEST(HistogramEffect, NeuralHistogramRendersNearTheExactTable) {
  ScratchDir dir("histogram_effect_neural");
  write_inputs(dir.path());
  const Scene exact = tiled_plane(dir, "exact.json", {{"name", "histogram"}, {"sh_order", 40}});
  const Scene neural =
      tiled_plane(dir, "neural.json",
                  {{"name", "histogram"}, {"sh_order", 40}, {"method", "neural"}, {"iterations", 400}, {"batch", 256}});
  std::vector<std::string> kinds;
  for (const PlannedAsset& a : plan_assets(neural)) kinds.push_back(a.recipe.kind);
  EXPECT_EQ(kinds, (std::vector<std::string>{"neural_histogram", "mip"}));
  const AgainstExact e = block_l1_against_exact(exact, neural, "neural (400 steps)");
  EXPECT_GT(e.apart, 0.0);  // the network was read
  EXPECT_LT(e.other, e.exact + 0.02);
}

// The non-neural baseline behind the same shader: `method pyramid` bakes the exact asset (the very file of `method
// exact`), compresses it at load to a MIP pyramid of histograms of the neural predictor's bytes, and renders near
// the reference, no further from it than the same margin as the neural histogram beyond the exact table.
TEST(HistogramEffect, PyramidBaselineReadsTheExactAssetAndRendersNearIt) {
  ScratchDir dir("histogram_effect_pyramid");
  write_inputs(dir.path());
  const Scene exact = tiled_plane(dir, "exact.json", {{"name", "histogram"}, {"sh_order", 40}});
  const Scene pyramid =
      tiled_plane(dir, "pyramid.json", {{"name", "histogram"}, {"sh_order", 40}, {"method", "pyramid"}});
  std::vector<std::string> files;
  for (const PlannedAsset& a : plan_assets(exact)) files.push_back(a.file_name);
  for (size_t i = 0; const PlannedAsset& a : plan_assets(pyramid)) EXPECT_EQ(a.file_name, files.at(i++));
  const AgainstExact e = block_l1_against_exact(exact, pyramid, "pyramid");
  EXPECT_GT(e.apart, 0.0);  // the pyramid was read
  EXPECT_LT(e.other, e.exact + 0.02);
}

TEST(HistogramEffect, RoughnessTextureNeedsNoRebakeAndMatchesItsReference) {
  ScratchDir dir("histogram_effect_roughness");
  write_inputs(dir.path());
  write_roughness(dir / "gradient.exr", [](uint32_t x, uint32_t) { return 0.02 + 0.1 * x / 15.0; });
  write_roughness(dir / "constant.exr", [](uint32_t, uint32_t) { return 0.125; });
  const Scene plain = scene_in(dir.path(), {{"name", "histogram"}, {"roughness", 0.125}, {"sh_order", 40}});
  bake_scene(plain);
  const std::vector<PlannedAsset> baked = plan_assets(plain);
  const Image constant_value = render(plain, 1);

  // A roughness texture is the shader's: the same assets (same names, so `bake` finds them up to date).
  const Scene textured =
      scene_in(dir.path(), {{"name", "histogram"}, {"roughness_map", "gradient.exr"}, {"sh_order", 40}});
  const std::vector<PlannedAsset> planned = plan_assets(textured);
  ASSERT_EQ(planned.size(), baked.size());
  for (size_t i = 0; i < planned.size(); ++i) EXPECT_EQ(planned[i].file_name, baked[i].file_name);
  const BlockErrors e = block_errors(textured, "scratches, roughness 0.02..0.12 across u, order 40");
  EXPECT_LT(e.effect, 2.0 * e.floor + 0.005);
  EXPECT_GT(compare_images(render(textured, 1), constant_value).rmse, 0.05);

  // A texture of one value renders bit for bit as that value (0.125 is exact in float).
  const Scene constant_map =
      scene_in(dir.path(), {{"name", "histogram"}, {"roughness_map", "constant.exr"}, {"sh_order", 40}});
  EXPECT_EQ(compare_images(render(constant_map, 1), constant_value).max_abs, 0.0);
}

TEST(HistogramEffect, FlatMapReflectsTheEnvironmentLikeItsReference) {
  // One bin holds every normal: what is left is the environment's SH order and the mirror-image lobes.
  ScratchDir dir("histogram_effect_flat");
  write_inputs(dir.path());
  NormalMap flat;
  flat.width = flat.height = 32;
  flat.texels.assign(32 * 32, Vec3f(0, 0, 1));
  save_normal_map(dir / "map.png", flat);
  const Scene scene = scene_in(dir.path(), {{"name", "histogram"}, {"roughness", 0.05}, {"sh_order", 60}});
  bake_scene(scene);
  const BlockErrors e = block_errors(scene, "flat, roughness 0.05, order 60");
  EXPECT_LT(e.effect, 2.0 * e.floor + 0.005);
}

TEST(HistogramEffect, ReflectionsTooSharpForTheOrderBlurInsteadOfRinging) {
  // Roughness 0.003 at order 8: the mirrored lobes are far narrower than band 8 resolves. Truncated as they are,
  // they ring around the bright discs (negative radiance, black after clamping); widened to the narrowest resolved
  // lobe they blur. Every effect pixel stays at least half the darkest reference pixel (the dim sky's reflection).
  ScratchDir dir("histogram_effect_sharp");
  write_inputs(dir.path());
  NormalMap flat;
  flat.width = flat.height = 16;
  flat.texels.assign(16 * 16, Vec3f(0, 0, 1));
  save_normal_map(dir / "map.png", flat);
  json scene_json = plane_scene({{"name", "histogram"}, {"roughness", 0.003}, {"sh_order", 8}});
  scene_json["lights"] = json::array({scene_json["lights"][0]});  // the environment alone
  testing::write_json(dir / "s.json", scene_json);
  const Scene scene = load_scene(dir / "s.json");
  bake_scene(scene);
  const Image effect = render(scene, 1), reference = render(scene, 1, 4);
  const auto darkest = [](const Image& im) { return *std::min_element(im.pixels.begin(), im.pixels.end()); };
  std::printf("[ info ] darkest channel value: effect %.4f, reference %.4f\n", darkest(effect), darkest(reference));
  EXPECT_GT(darkest(reference), 0.0f);
  EXPECT_GE(darkest(effect), 0.5f * darkest(reference));
}

}  // namespace
}  // namespace mbk
