// The colour-map effects end to end ([Heitz13]; libbake/eval/colormap_effect.h): a plane receding to the horizon
// with colour-mapped noise (and a height-mapped and a slope-mapped sphere) baked, rendered naive, filtered and as
// the supersampled --reference; the filtered image must be closer to the reference than the naive one, by a
// margin, for each case.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "libbake/eval/image_difference.h"
#include "libbake/eval/renderer.h"
#include "libbake/image/image_io.h"
#include "libbake/scene/bake_plan.h"
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

void bake(const Scene& s) {
  std::filesystem::create_directories(default_asset_folder(s));
  for (const PlannedAsset& a : plan_assets(s))
    a.recipe.bake(Progress::silent()).write(default_asset_folder(s) / a.file_name);
}

Image render_mode(const Scene& s, uint32_t reference) {
  RenderSettings settings;
  settings.spp = 1;
  settings.reference = reference;
  return render_scene(s, load_render_inputs(s, settings), settings, Progress::silent());
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
  bake(filtered_scene);
  bake(naive_scene);
  const Image filtered = render_mode(filtered_scene, 0), naive = render_mode(naive_scene, 0);
  const Image reference = render_mode(filtered_scene, 8);

  // Per material: the pixels each shape covers, where a render with that material black differs.
  for (const std::string m : {"a", "b", "c"}) {
    json marked = scene("filtered", noise, height, slope);
    marked["materials"][m] = {{"albedo", 0.0}, {"specular", {{"f0", 0.0}}}};
    testing::write_json(dir / "marked.json", marked);
    const Scene marked_scene = load_scene(dir / "marked.json");
    bake(marked_scene);
    const Image black = render_mode(marked_scene, 0);
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
  bake(filtered_scene);
  bake(naive_scene);
  const Image reference = render_mode(filtered_scene, 8);
  const std::vector<bool> all(size_t(reference.width) * reference.height, true);
  const double e_filtered = masked_rmse(render_mode(filtered_scene, 0), reference, all),
               e_naive = masked_rmse(render_mode(naive_scene, 0), reference, all);
  std::cout << "image driver: RMSE to reference: naive " << e_naive << ", filtered " << e_filtered << "\n";
  EXPECT_LT(e_filtered, 0.7 * e_naive);
}

}  // namespace
}  // namespace mbk
