// The `crease` effect end to end ([Parilov05]; libbake/scene/effect_crease.cpp, libbake/eval/crease_effect.h) and
// its ground truth (libbake/eval/exact_crease_normals.h): the plan bakes exactly one crease asset; bad options are
// refused; the exact normals never take a value from across a curve; and on a magnified plane with a diagonal
// crease the reconstruction renders closer to the reference than plain (bilinear, MIP-mapped) normal mapping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "formats/error.h"
#include "libbake/eval/exact_crease_normals.h"
#include "libbake/eval/image_difference.h"
#include "libbake/scene/asset_freshness.h"
#include "tests/eval/render_fixtures.h"
#include "tests/scene/scene_test_fixtures.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

using nlohmann::json;
using test::ScratchDir;

// A 16 x 16 map split by the directed line (3.3, 0) -> (12.7, 16): texels whose centre lies right of it (as seen
// on screen, y down) tilt one way, the others the other way, so interpolating across it is far off.
constexpr uint32_t kSide = 16;
const Vec2 kLineA(3.3, 0.0), kLineB(12.7, 16.0);
const Vec3 kRight = Vec3(-0.6, 0.25, 1.0).normalized(), kLeft = Vec3(0.55, -0.2, 1.0).normalized();

double signed_distance(const Vec2& p) {  // > 0 right of the line
  const Vec2 d = (kLineB - kLineA).normalized();
  return d.x() * (p - kLineA).y() - d.y() * (p - kLineA).x();
}

double segment_distance(const Vec2& p) {
  const Vec2 ab = kLineB - kLineA;
  const double t = std::clamp((p - kLineA).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (kLineA + t * ab)).norm();
}

Vec3 side_normal(const Vec2& p) { return signed_distance(p) >= 0 ? kRight : kLeft; }

NormalMap split_map() {
  NormalMap m;
  m.width = m.height = kSide;
  for (uint32_t row = 0; row < kSide; ++row)
    for (uint32_t x = 0; x < kSide; ++x) m.texels.push_back(side_normal(Vec2(x + 0.5, row + 0.5)).cast<float>());
  return m;
}

void write_inputs(const ScratchDir& dir) {
  testing::write_normal_map(dir / "split.exr", kSide, kSide,
                            [](uint32_t x, uint32_t row) { return side_normal(Vec2(x + 0.5, row + 0.5)); });
  testing::write_json(dir / "line.json",
                      {{"curves", {{{"points", {{kLineA.x(), kLineA.y()}, {kLineB.x(), kLineB.y()}}}}}}});
}

// A camera close above a 2 x 2 plane carrying the map once: about 6 pixels per texel, the crease across the view.
json magnified_scene(const json& effect) {  // null: no effect
  const json effects = effect.is_null() ? json::array() : json::array({effect});
  return {{"camera",
           {{"position", {0.0, 1.6, 0.9}}, {"look_at", {0.0, 0.0, 0.0}}, {"fov_y", 50}, {"width", 96}, {"height", 72}}},
          {"shapes", {{{"type", "plane"}, {"size", {2.0, 2.0}}, {"uv_scale", {1.0, 1.0}}, {"material", "a"}}}},
          {"materials",
           {{"a",
             {{"albedo", {0.5, 0.5, 0.5}},
              {"specular", {{"roughness", 0.25}, {"f0", 0.04}}},
              {"normal_map", {{"path", "split.exr"}}},
              {"effects", effects}}}}},
          {"lights",
           {{{"type", "point"}, {"position", {1.5, 2.0, 1.0}}, {"intensity", {6.0, 6.0, 6.0}}},
            {{"type", "sky"}, {"radiance", {0.05, 0.05, 0.06}}}}}};
}

TEST(CreaseEffect, BakesOneCreaseAssetWithCanonicalOptions) {
  ScratchDir dir("crease_plan");
  write_inputs(dir);
  testing::write_json(dir / "s.json",
                      magnified_scene({{"name", "crease"}, {"curves", "line.json"}, {"profile", {{"kind", "v"}}}}));
  const Scene scene = load_scene(dir / "s.json");
  const std::vector<PlannedAsset> plan = plan_assets(scene);
  ASSERT_EQ(plan.size(), 2u);  // and the baseline's mip
  EXPECT_EQ(plan[1].recipe.kind, "mip");
  EXPECT_EQ(plan[0].recipe.kind, "crease");
  EXPECT_EQ(plan[0].recipe.parameters, (json{{"smooth_iterations", 10}, {"band", 4.0}}));
  ASSERT_EQ(plan[0].recipe.inputs.size(), 2u);
  EXPECT_EQ(plan[0].recipe.inputs[1].path, dir / "line.json");
  const json& options = scene.materials.at("a").effects.at(0).options;
  EXPECT_EQ(options.at("profile"),
            (json{{"kind", "v"}, {"depth", 1.0}, {"width", 2.0}, {"blend_start", 0.0}, {"blend_end", 2.0}}));
  testing::bake_scene(scene);  // and the baked file is what the plan asked for: up to date
  EXPECT_EQ(check_asset_freshness(plan[0], default_asset_folder(scene) / plan[0].file_name).state,
            AssetState::up_to_date);
}

TEST(CreaseEffect, BadOptionsAreRefusedAtTheirPath) {
  ScratchDir dir("crease_bad");
  write_inputs(dir);
  const std::vector<std::pair<json, std::string>> cases = {
      {{{"name", "crease"}}, "curves"},
      {{{"name", "crease"}, {"curves", ""}}, "curves"},
      {{{"name", "crease"}, {"curves", "line.json"}, {"band", 0}}, "band"},
      {{{"name", "crease"}, {"curves", "line.json"}, {"smooth_iterations", -1}}, "smooth_iterations"},
      {{{"name", "crease"}, {"curves", "line.json"}, {"profile", {{"kind", "zigzag"}}}}, "profile.kind"},
      {{{"name", "crease"}, {"curves", "line.json"}, {"profile", {{"width", 0}}}}, "profile.width"},
      {{{"name", "crease"}, {"curves", "line.json"}, {"curve", "line.json"}}, "curve"}};
  for (const auto& [effect, key] : cases) {
    testing::write_json(dir / "s.json", magnified_scene(effect));
    try {
      load_scene(dir / "s.json");
      ADD_FAILURE() << "accepted " << effect.dump();
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::invalid_input) << effect.dump();
      EXPECT_NE(e.message().find(key), std::string::npos) << e.message();
    }
  }
}

TEST(ExactCreaseNormals, NeverReadAcrossTheCurveAndMeasureTheExactDistance) {
  ExactCreaseNormals exact(split_map(), {{kLineA, kLineB}}, std::nullopt);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coord(0.0, double(kSide));
  int near_curve = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec2 p(coord(rng), coord(rng));
    const double s = signed_distance(p);
    if (std::abs(s) < 1e-9) continue;
    const Vec3 n = exact.normal(p);
    // The two sides' normals, and so every mix of one side's texels, are this far apart: a texel from across
    // the curve would pull n towards the other side.
    EXPECT_NEAR(n.dot(s > 0 ? kRight : kLeft), 1.0, 1e-12) << p.transpose();
    const CreaseSample cs = exact.sample(p);
    const double d = segment_distance(p);
    if (d <= exact.reach() - 1e-6) {
      ++near_curve;
      EXPECT_NEAR(cs.distance, d, 1e-12);
      EXPECT_EQ(cs.side, s > 0 ? 1 : -1);
      const Vec2 g(cs.gradient[0], cs.gradient[1]);
      EXPECT_NEAR(g.norm(), 1.0, 1e-12);
      EXPECT_GT(g.dot(Vec2(-(kLineB - kLineA).y(), (kLineB - kLineA).x())) * s, 0.0);  // away from the curve
    }
  }
  EXPECT_GT(near_curve, 1000);
}

// Curves through texel centres (along the row of centres y = 8.5, and at 45 degrees through (i + 0.5, i + 0.5)): a
// centre on the curve belongs to side +1 alone (the side map's rule, orient >= 0), so no point reads a normal from
// the other side, even next to the curve.
TEST(ExactCreaseNormals, CentresOnACurveBelongToOneSide) {
  for (const auto& [a, b] : {std::pair{Vec2(0.0, 8.5), Vec2(16.0, 8.5)}, std::pair{Vec2(0.5, 0.5), Vec2(15.5, 15.5)}}) {
    const auto side = [&](const Vec2& p) {
      return (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x()) >= 0.0;
    };
    NormalMap m;
    m.width = m.height = kSide;
    for (uint32_t row = 0; row < kSide; ++row)
      for (uint32_t x = 0; x < kSide; ++x)
        m.texels.push_back((side(Vec2(x + 0.5, row + 0.5)) ? kRight : kLeft).cast<float>());
    const ExactCreaseNormals exact(m, {{a, b}}, std::nullopt);
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> coord(1.0, double(kSide) - 1.0), offset(-0.6, 0.6);
    const Vec2 along = (b - a).normalized(), across(-along.y(), along.x());
    for (int k = 0; k < 5000; ++k) {
      // Points near the curve (the hard case) and anywhere.
      const Vec2 p =
          k % 2 ? Vec2(coord(rng), coord(rng))
                : a + (b - a).norm() * std::clamp(coord(rng) / kSide, 0.05, 0.95) * along + offset(rng) * across;
      EXPECT_NEAR(exact.normal(p).dot(side(p) ? kRight : kLeft), 1.0, 1e-12) << p.transpose();
    }
  }
}

TEST(ExactCreaseNormals, AProfileShapesTheNormalsNearTheCurveOnly) {
  CreaseProfile v;  // a groove 1 deep over 2 texels, blended into the map from 1 to 2 texels away
  v.kind = CreaseProfileKind::v;
  v.depth = 1.0;
  v.width = 2.0;
  v.blend_start = 1.0;
  v.blend_end = 2.0;
  const ExactCreaseNormals exact(split_map(), {{kLineA, kLineB}}, v);
  const Vec2 dir = (kLineB - kLineA).normalized(), right(-dir.y(), dir.x());
  const Vec2 mid = 0.5 * (kLineA + kLineB);
  // Within blend_start the normal is the profile's alone: (-p' g, 1) normalised, g pointing away from the curve
  // (texel y runs down, tangent y up).
  for (const double d : {0.2, 0.5, 0.9}) {
    const Vec3 n = exact.normal(mid + d * right);
    const Vec3 expected = Vec3(-0.5 * right.x(), 0.5 * right.y(), 1.0).normalized();
    EXPECT_NEAR(n.dot(expected), 1.0, 1e-12) << d;
  }
  // Beyond blend_end the map's normal of the point's side.
  EXPECT_NEAR(exact.normal(mid + 3.0 * right).dot(kRight), 1.0, 1e-12);
  EXPECT_NEAR(exact.normal(mid - 3.0 * right).dot(kLeft), 1.0, 1e-12);
}

TEST(CreaseEffect, MustComeBeforeTheColourMapEffects) {
  ScratchDir dir("crease_order");
  write_inputs(dir);
  json s = magnified_scene(json());
  s["materials"]["a"]["effects"] = {{{"name", "colormap"}, {"colormap", "c.json"}},
                                    {{"name", "crease"}, {"curves", "line.json"}}};
  testing::write_json(dir / "s.json", s);
  try {
    load_scene(dir / "s.json");
    ADD_FAILURE() << "accepted crease after colormap";
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("must be listed before the colour-map effects"), std::string::npos) << e.message();
    EXPECT_NE(e.message().find("effects[1]"), std::string::npos) << e.message();
  }
}

TEST(CreaseEffect, MagnifiedCreaseIsCloserToTheReferenceThanBilinearNormals) {
  ScratchDir dir("crease_render");
  write_inputs(dir);
  for (const json& profile : {json(), json{{"kind", "v"}, {"depth", 0.8}, {"width", 1.0}}}) {
    json effect = {{"name", "crease"}, {"curves", "line.json"}};
    if (!profile.is_null()) effect["profile"] = profile;
    testing::write_json(dir / "crease.json", magnified_scene(effect));
    testing::write_json(dir / "plain.json", magnified_scene(json()));
    const Scene crease = load_scene(dir / "crease.json"), plain = load_scene(dir / "plain.json");
    testing::bake_scene(crease);
    const Image reference = testing::render(crease, 1, 6);
    const double e_crease = compare_images(testing::render(crease, 4), reference).rmse;
    const double e_plain = compare_images(testing::render(plain, 4), reference).rmse;
    std::cout << "profile " << profile.dump() << ": RMSE to the reference: bilinear " << e_plain << ", crease "
              << e_crease << "\n";
    EXPECT_LT(e_crease, 0.5 * e_plain) << profile.dump();
  }
}

}  // namespace
}  // namespace mbk
