// Edge-adaptive sampling (libbake/eval/silhouette_pixels.h, `render --edge-spp`): the pixels flagged are the
// pixels a brute force over a 9 x 9 lattice of sub-pixel rays finds shared by two shapes (or a shape and the
// background), none where one shape fills the view; with edge samples a filtered render's silhouettes come to the
// reference's noise floor at one sample per pixel elsewhere, and pixels no silhouette crosses are unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

#include "libbake/eval/camera_rays.h"
#include "libbake/eval/image_difference.h"
#include "libbake/eval/shape_intersection.h"
#include "libbake/eval/silhouette_pixels.h"
#include "tests/eval/render_fixtures.h"
#include "tests/scene/scene_test_fixtures.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

using nlohmann::json;
using test::ScratchDir;

json plain_materials() {
  const auto m = [](double roughness) {
    return json{{"albedo", {0.6, 0.5, 0.4}}, {"specular", {{"roughness", roughness}, {"f0", 0.04}}}};
  };
  return {{"a", m(0.3)}, {"b", m(0.1)}, {"c", m(0.2)}};
}

Scene scene_in(const ScratchDir& dir, const json& scene_json) {
  testing::write_json(dir / "s.json", scene_json);
  return load_scene(dir / "s.json");
}

// Whether the rays through the 9 x 9 lattice of film points x + i/8, y + j/8 (i, j = 0..8: the pixel's closed
// square, corners included) see more than one shape or the background.
bool mixed_pixel(const Scene& scene, const PinholeCamera& camera, uint32_t x, uint32_t y) {
  std::set<int64_t> seen;
  for (int j = 0; j <= 8; ++j)
    for (int i = 0; i <= 8; ++i) {
      const auto hit = intersect_scene(scene.shapes, camera.ray(x + i / 8.0, y + j / 8.0).ray);
      seen.insert(hit ? int64_t(hit->shape) : -1);
    }
  return seen.size() > 1;
}

TEST(SilhouettePixels, FlagThePixelsABruteForceFindsShared) {
  ScratchDir dir("silhouette_flags");
  const Scene scene = scene_in(dir, testing::small_scene(plain_materials(), 80, 60));
  const PinholeCamera camera(scene.camera);
  const std::vector<uint8_t> flags = silhouette_pixels(scene, camera);
  ASSERT_EQ(flags.size(), size_t(80) * 60);
  size_t flagged = 0, mixed = 0, both = 0;
  for (uint32_t y = 0; y < 60; ++y)
    for (uint32_t x = 0; x < 80; ++x) {
      const bool f = flags[size_t(y) * 80 + x] != 0, m = mixed_pixel(scene, camera, x, y);
      flagged += f, mixed += m, both += f && m;
      // A flagged pixel's corners see two things, and the corners are lattice points: never a false flag.
      EXPECT_TRUE(!f || m) << "pixel " << x << ", " << y;
    }
  std::printf("[ info ] %zu pixels flagged, %zu shared by the brute force, %zu both\n", flagged, mixed, both);
  // The sphere, the bent quad and the horizon cross hundreds of pixels; a boundary can pass between the four
  // corners of a pixel only where it runs nearly along the pixel's side, which few pixels of a curve do.
  EXPECT_GT(mixed, 200u);
  EXPECT_GE(double(both), 0.95 * double(mixed));
}

TEST(SilhouettePixels, NoneWhereOneShapeFillsTheView) {
  ScratchDir dir("silhouette_none");
  json s = testing::small_scene(plain_materials(), 32, 24);
  s["shapes"] = json::array({s["shapes"][0]});
  s["camera"]["look_at"] = {0.0, 0.0, 0.0};  // straight down onto the 30 x 30 plane: no horizon in view
  s["camera"]["position"] = {0.0, 2.0, 0.01};
  const Scene scene = scene_in(dir, s);
  for (const uint8_t f : silhouette_pixels(scene, PinholeCamera(scene.camera))) ASSERT_EQ(f, 0);
}

TEST(SilhouettePixels, EdgeSamplesBringSilhouettesToTheReferenceAndLeaveOtherPixelsAlone) {
  ScratchDir dir("silhouette_render");
  const Scene scene = scene_in(dir, testing::small_scene(plain_materials(), 64, 48));
  const Image one = testing::render(scene, 1), edged = testing::render(scene, 1, 0, 0, 16);
  const Image reference = testing::render(scene, 1, 16), brute = testing::render(scene, 1, 4);
  const std::vector<uint8_t> flags = silhouette_pixels(scene, PinholeCamera(scene.camera));
  // Mean absolute error against the reference over the flagged pixels: at 1 spp, with 16 edge samples, and of brute
  // force at 4 x 4 rays (the same sample count there).
  double edge_without = 0.0, edge_with = 0.0, edge_brute = 0.0;
  size_t edges = 0, changed = 0;
  for (uint32_t y = 0; y < one.height; ++y)
    for (uint32_t x = 0; x < one.width; ++x) {
      const bool edge = flags[size_t(y) * one.width + x] != 0;
      edges += edge;
      for (uint32_t c = 0; c < 3; ++c) {
        const double r = reference.at(x, y, c);
        if (edge) {
          edge_without += std::abs(one.at(x, y, c) - r), edge_with += std::abs(edged.at(x, y, c) - r);
          edge_brute += std::abs(brute.at(x, y, c) - r);
          changed += one.at(x, y, c) != edged.at(x, y, c);
        } else {
          ASSERT_EQ(one.at(x, y, c), edged.at(x, y, c)) << "pixel " << x << ", " << y;
        }
      }
    }
  edge_without /= 3.0 * edges, edge_with /= 3.0 * edges, edge_brute /= 3.0 * edges;
  std::printf("[ info ] %zu edge pixels, mean error: 1 spp %.5f, with 16 edge samples %.5f, brute force 4 x 4 %.5f\n",
              edges, edge_without, edge_with, edge_brute);
  EXPECT_GT(changed, 0u);
  EXPECT_LE(edge_with, 0.35 * edge_without);
  EXPECT_LE(edge_with, 1.5 * edge_brute);
}

}  // namespace
}  // namespace mbk
