// The colour-map effects end to end ([Heitz13]; libbake/eval/colormap_effect.h): a plane receding to the horizon
// with colour-mapped noise (and a height-mapped and a slope-mapped sphere) baked, rendered naive, filtered and as
// the supersampled --reference; the filtered image must be closer to the reference than the naive one, by a
// margin, for each case.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "formats/error.h"
#include "libbake/eval/image_difference.h"
#include "libbake/eval/renderer.h"
#include "libbake/image/image_io.h"
#include "libbake/scene/bake_plan.h"
#include "tests/eval/render_fixtures.h"
#include "tests/scene/scene_test_fixtures.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

using nlohmann::json;
using test::ScratchDir;

// Hard-edged stripes: C is far from linear, so C(mean f) is far from E[C(f)] once f varies within a pixel.
void write_stripes(const std::filesystem::path& path) {
  json stops = json::array();
  const std::vector<std::vector<double>> colors = {{0.9, 0.8, 0.2}, {0.1, 0.1, 0.12}, {0.85, 0.2, 0.1}};
  for (int k = 0; k < 5; ++k) {
    stops.push_back({{"at", 0.2 * k}, {"color", colors[k % 3]}});
    stops.push_back({{"at", 0.2 * (k + 1)}, {"color", colors[k % 3]}});
  }
  testing::write_json(path, {{"encoding", "linear"}, {"stops", stops}});
}

json scene(const std::string& mode, const json& effect_a, const json& effect_b, const json& effect_c) {
  auto material = [&](json effect) {
    effect["mode"] = mode;
    effect["colormap"] = "stripes.json";
    return json{{"specular", {{"roughness", 0.4}, {"f0", 0.04}}}, {"effects", {effect}}};
  };
  json s =
      testing::small_scene({{"a", material(effect_a)}, {"b", material(effect_b)}, {"c", material(effect_c)}}, 48, 30);
  s["camera"]["position"] = {0.0, 0.8, 4.0};  // low over the plane: it recedes to the horizon
  s["camera"]["look_at"] = {0.0, 0.5, 0.0};
  return s;
}

// RMSE over the pixels where `mask` (an image of the same scene with one material marked) is set.
double masked_rmse(const Image& a, const Image& b, const std::vector<bool>& mask) {
  double sum = 0.0;
  size_t n = 0;
  for (size_t p = 0; p < mask.size(); ++p)
    if (mask[p])
      for (uint32_t c = 0; c < 3; ++c, ++n) {
        const double d = double(a.pixels[p * a.channels + c]) - b.pixels[p * b.channels + c];
        sum += d * d;
      }
  return n ? std::sqrt(sum / double(n)) : 0.0;
}

TEST(ColormapEffect, FilteredIsCloserToTheReferenceThanNaive_RecedingNoisePlane) {
  ScratchDir dir("colormap_effect");
  write_stripes(dir / "stripes.json");
  const json noise = {{"name", "colormap"},
                      {"noise", {{"cells", {4, 4}}, {"octaves", 4}, {"seed", 7}}},
                      {"scale", 0.8},
                      {"offset", 0.5}};
  const json height = {{"name", "colormap-height"},
                       {"noise", {{"cells", {2, 2}}, {"octaves", 2}}},
                       {"scale", 0.3},
                       {"offset", 0.5},
                       {"sigma_h", 0.12},
                       {"slope_sigma", 0.5}};
  const json slope = {{"name", "colormap-slope"}, {"slope_sigma", 0.4}, {"direction_degrees", 0}, {"offset", 0.5}};
  testing::write_json(dir / "filtered.json", scene("filtered", noise, height, slope));
  testing::write_json(dir / "naive.json", scene("naive", noise, height, slope));
  const Scene filtered_scene = load_scene(dir / "filtered.json"), naive_scene = load_scene(dir / "naive.json");
  testing::bake_scene(filtered_scene);
  testing::bake_scene(naive_scene);
  const Image filtered = testing::render(filtered_scene, 1, 0), naive = testing::render(naive_scene, 1, 0);
  const Image reference = testing::render(filtered_scene, 1, 8);

  // Per material: the pixels each shape covers, where a render with that material black differs.
  for (const std::string m : {"a", "b", "c"}) {
    json marked = scene("filtered", noise, height, slope);
    marked["materials"][m] = {{"albedo", 0.0}, {"specular", {{"f0", 0.0}}}};
    testing::write_json(dir / "marked.json", marked);
    const Scene marked_scene = load_scene(dir / "marked.json");
    testing::bake_scene(marked_scene);
    const Image black = testing::render(marked_scene, 1, 0);
    std::vector<bool> mask(size_t(black.width) * black.height);
    for (size_t p = 0; p < mask.size(); ++p)
      for (uint32_t c = 0; c < 3; ++c) mask[p] = mask[p] || black.pixels[p * 3 + c] != filtered.pixels[p * 3 + c];
    const size_t covered = size_t(std::count(mask.begin(), mask.end(), true));
    ASSERT_GT(covered, 40u) << m;
    const double e_filtered = masked_rmse(filtered, reference, mask), e_naive = masked_rmse(naive, reference, mask);
    std::cout << "material " << m << ": " << covered << " pixels, RMSE to reference: naive " << e_naive << ", filtered "
              << e_filtered << "\n";
    EXPECT_LT(e_filtered, 0.7 * e_naive) << m;
  }
}

TEST(ColormapEffect, ImageDriverFilteredIsCloserToTheReferenceThanNaive_MomentPyramid) {
  // The driver as an image (baked to a moment pyramid): a fine sine pattern of f over 256 x 64 texels, tiled 12
  // times across the plane (the same map drives all three materials).
  ScratchDir dir("colormap_image_driver");
  write_stripes(dir / "stripes.json");
  Image driver{256, 64, 1, {}};
  for (uint32_t row = 0; row < driver.height; ++row)
    for (uint32_t x = 0; x < driver.width; ++x)
      driver.pixels.push_back(float(0.5 + 0.45 * std::sin(0.37 * x) * std::cos(0.21 * row)));
  save_image(dir / "driver.exr", driver);
  const json effect = {{"name", "colormap"}, {"driver", "driver.exr"}};
  testing::write_json(dir / "filtered.json", scene("filtered", effect, effect, effect));
  testing::write_json(dir / "naive.json", scene("naive", effect, effect, effect));
  const Scene filtered_scene = load_scene(dir / "filtered.json"), naive_scene = load_scene(dir / "naive.json");
  testing::bake_scene(filtered_scene);
  testing::bake_scene(naive_scene);
  const Image reference = testing::render(filtered_scene, 1, 8);
  const std::vector<bool> all(size_t(reference.width) * reference.height, true);
  const double e_filtered = masked_rmse(testing::render(filtered_scene, 1, 0), reference, all),
               e_naive = masked_rmse(testing::render(naive_scene, 1, 0), reference, all);
  std::cout << "image driver: RMSE to reference: naive " << e_naive << ", filtered " << e_filtered << "\n";
  EXPECT_LT(e_filtered, 0.7 * e_naive);
}

// Sec. 6 combinations: material "a" (the receding plane) names `effects` (each given its mode and the stripes);
// "b" and "c" are plain.
json combination_scene(const std::string& mode, json effects) {
  for (json& e : effects) {
    e["mode"] = mode;
    e["colormap"] = "stripes.json";
  }
  const json plain = {{"albedo", 0.3}, {"specular", {{"roughness", 0.4}, {"f0", 0.04}}}};
  json a = plain;
  a["effects"] = effects;
  json s = testing::small_scene({{"a", a}, {"b", plain}, {"c", plain}}, 48, 30);
  s["camera"]["position"] = {0.0, 0.8, 4.0};
  s["camera"]["look_at"] = {0.0, 0.5, 0.0};
  return s;
}

const json kNoise = {
    {"name", "colormap"}, {"noise", {{"cells", {4, 4}}, {"octaves", 4}, {"seed", 7}}}, {"scale", 0.8}, {"offset", 0.5}};
const json kSlope = {{"name", "colormap-slope"}, {"slope_sigma", 0.4}, {"offset", 0.5}};

json weighted(json effect, double weight, const std::string& combine = "linear") {
  effect["weight"] = weight;
  effect["combine"] = combine;
  return effect;
}

Image render_combination(const ScratchDir& dir, const std::string& mode, const json& effects, uint32_t reference) {
  testing::write_json(dir / "combination.json", combination_scene(mode, effects));
  const Scene s = load_scene(dir / "combination.json");
  testing::bake_scene(s);
  return testing::render(s, 1, reference);
}

// Radiance is affine in the albedo (Lambert plus an albedo-free specular), so the linear combination's image is
// k0 (I_0 - S) + k2 (I_s - S) + S with S the image at albedo 0 (both weights 0): an exact check of the plumbing,
// filtered and in the reference.
TEST(ColormapEffect, LinearCombinationIsTheWeightedSumOfItsTerms_FilteredAndReference) {
  ScratchDir dir("colormap_linear");
  write_stripes(dir / "stripes.json");
  const double k0 = 0.7, k2 = 0.45;
  for (const uint32_t reference : {0u, 2u}) {
    const Image combined = render_combination(dir, "filtered", {weighted(kNoise, k0), weighted(kSlope, k2)}, reference);
    const Image noise = render_combination(dir, "filtered", json::array({kNoise}), reference);
    const Image slope = render_combination(dir, "filtered", json::array({kSlope}), reference);
    const Image none = render_combination(dir, "filtered", {weighted(kNoise, 0), weighted(kSlope, 0)}, reference);
    double worst = 0.0, largest = 0.0;
    for (size_t i = 0; i < combined.pixels.size(); ++i) {
      const double s = none.pixels[i];
      const double expected = k0 * (noise.pixels[i] - s) + k2 * (slope.pixels[i] - s) + s;
      worst = std::max(worst, std::abs(combined.pixels[i] - expected));
      largest = std::max(largest, std::abs(expected));
    }
    EXPECT_LT(worst, 1e-5 * std::max(1.0, largest)) << "reference " << reference;
    EXPECT_GT(compare_images(combined, noise).rmse, 1e-3);  // the slope term changed the picture
  }
}

// With a height effect the linear form weighs C0 and Cs by its visibility V_bar. A white colour map makes the height
// term C_h_bar = V_bar itself, so from the images of each effect alone (and of albedo 0 and 1) the per-pixel
// albedos C0, V and Cs are known, and the combination's image must be (k0 V C0 + k1 V + k2 V Cs) D + S, where D is
// the image at albedo 1 minus S. One ray per pixel, so every image samples the same points.
TEST(ColormapEffect, LinearCombinationWeighsC0AndCsByTheHeightVisibility) {
  ScratchDir dir("colormap_visibility");
  write_stripes(dir / "stripes.json");
  testing::write_json(
      dir / "white.json",
      {{"encoding", "linear"}, {"stops", {{{"at", 0}, {"color", {1, 1, 1}}}, {{"at", 1}, {"color", {1, 1, 1}}}}}});
  const json height = {
      {"name", "colormap-height"}, {"noise", {{"cells", {2, 2}}}}, {"sigma_h", 0.1}, {"slope_sigma", 0.4}};
  const double k0 = 0.6, k1 = 0.3, k2 = 0.5;
  // The effects on the stripes, except those whose name is `white`, which read the white map.
  const auto render_with = [&](json effects, const std::string& white) {
    json scene = combination_scene("filtered", effects);
    for (json& e : scene["materials"]["a"]["effects"])
      if (e["name"] == white) e["colormap"] = "white.json";
    testing::write_json(dir / "v.json", scene);
    const Scene loaded = load_scene(dir / "v.json");
    testing::bake_scene(loaded);
    return testing::render(loaded, 1);
  };
  const Image combined =
      render_with({weighted(kNoise, k0), weighted(height, k1), weighted(kSlope, k2)}, "colormap-height");
  const Image c0 = render_with(json::array({kNoise}), ""), v = render_with(json::array({height}), "colormap-height"),
              cs = render_with(json::array({kSlope}), "");
  const Image zero = render_with(json::array({weighted(kNoise, 0)}), ""),
              one = render_with(json::array({kNoise}), "colormap");
  size_t checked = 0;
  double worst = 0.0;
  for (size_t i = 0; i < combined.pixels.size(); ++i) {
    const double S = zero.pixels[i], D = one.pixels[i] - S;
    if (!(D > 1e-3)) continue;
    ++checked;
    const double a0 = (c0.pixels[i] - S) / D, av = (v.pixels[i] - S) / D, as = (cs.pixels[i] - S) / D;
    const double expected = (k0 * av * a0 + k1 * av + k2 * av * as) * D + S;
    worst = std::max(worst, std::abs(combined.pixels[i] - expected) / std::max(1e-2, std::abs(expected)));
  }
  EXPECT_GT(checked, combined.pixels.size() / 4);
  EXPECT_LT(worst, 1e-4);
}

TEST(ColormapEffect, HeightAndSlopeOfOneMaterialShareTheirSlopesAndProductsTakeNoWeights) {
  ScratchDir dir("colormap_one_surface");
  write_stripes(dir / "stripes.json");
  json height = {{"name", "colormap-height"}, {"slope_sigma", 0.2}};
  try {
    render_combination(dir, "filtered", {height, kSlope}, 0);
    ADD_FAILURE() << "accepted two microsurfaces";
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("same slope_sigma"), std::string::npos) << e.message();
  }
  try {
    render_combination(dir, "filtered", json::array({weighted(kNoise, 0.5, "product")}), 0);
    ADD_FAILURE() << "accepted a weight in a product";
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("product combination takes no weights"), std::string::npos) << e.message();
  }
}

TEST(ColormapEffect, CombinationsFilteredAreCloserToTheReferenceThanNaive_LinearAndProduct) {
  ScratchDir dir("colormap_combinations");
  write_stripes(dir / "stripes.json");
  for (const std::string combine : {"linear", "product"}) {
    json effects = {weighted(kNoise, 0.6, combine), weighted(kSlope, 0.4, combine)};
    if (combine == "product")
      for (json& e : effects) e.erase("weight");
    const Image reference = render_combination(dir, "filtered", effects, 8);
    const double e_filtered = compare_images(render_combination(dir, "filtered", effects, 0), reference).rmse;
    const double e_naive = compare_images(render_combination(dir, "naive", effects, 0), reference).rmse;
    std::cout << combine << " combination: RMSE to reference: naive " << e_naive << ", filtered " << e_filtered << "\n";
    EXPECT_LT(e_filtered, 0.7 * e_naive) << combine;
  }
}

TEST(ColormapEffect, EffectsOfOneMaterialMustCombineTheSameWay) {
  ScratchDir dir("colormap_combine_mismatch");
  write_stripes(dir / "stripes.json");
  try {
    json product = kSlope;
    product["combine"] = "product";
    render_combination(dir, "filtered", {weighted(kNoise, 1, "linear"), product}, 0);
    ADD_FAILURE() << "accepted linear + product";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input);
    EXPECT_NE(e.message().find("colormap-slope.combine"), std::string::npos) << e.message();
  }
}

}  // namespace
}  // namespace mbk
