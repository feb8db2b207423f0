// Long footprints shaded in parts (libbake/eval/sample_parts.h): the part count and axis against the singular
// values and right singular vector of the footprint's world-space Jacobian (Eigen's SVD, an independent
// computation), the cases that leave a sample whole (round, magnified, capped, grazing, degenerate), that the parts
// tile the sample (offsets and shrunk differentials), and the property a user sees: on a plane receding to the
// horizon, shading the long footprints in parts brings plain mip and the filtered-NDF effects closer to the
// brute-force reference.
#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <cmath>
#include <iostream>
#include <random>

#include "libbake/eval/image_difference.h"
#include "libbake/eval/renderer.h"
#include "libbake/eval/sample_parts.h"
#include "tests/eval/receding_plane_fixture.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

TEST(SampleParts, CountAndAxisFollowTheFootprintsSvd) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int split = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 a(u(rng), u(rng), u(rng));
    const Vec3 b = a * u(rng) * 3.0 + Vec3(u(rng), u(rng), u(rng)) * std::pow(10.0, -3.0 * std::abs(u(rng)));
    Eigen::Matrix<double, 3, 2> m;
    m << a, b;
    const Eigen::JacobiSVD<Eigen::Matrix<double, 3, 2>> svd(m, Eigen::ComputeFullV);
    const double s1 = svd.singularValues()(0), s2 = svd.singularValues()(1);
    const int cap = 1 + trial % kMaxSampleParts;
    const SampleParts p = sample_parts(a, b, cap);
    const double expected = std::clamp(std::ceil(s1 / (kPartAnisotropy * s2)), 1.0, double(cap));
    // Ratios within 1e-9 of an integer may round either way.
    if (std::abs(s1 / (kPartAnisotropy * s2) - std::round(s1 / (kPartAnisotropy * s2))) < 1e-9) continue;
    ASSERT_EQ(p.count, int(expected)) << "s1 " << s1 << " s2 " << s2 << " cap " << cap;
    if (p.count > 1) {
      ++split;
      EXPECT_NEAR(p.axis.norm(), 1.0, 1e-12);
      EXPECT_NEAR(std::abs(p.axis.dot(svd.matrixV().col(0))), 1.0, 1e-9);
    }
  }
  EXPECT_GT(split, 500);
}

TEST(SampleParts, RoundMagnifiedCappedGrazingAndDegenerateFootprintsStayWhole) {
  const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY();
  EXPECT_EQ(sample_parts(x, y, 16).count, 1);                // a circle
  EXPECT_EQ(sample_parts(1e-6 * x, 1e-6 * y, 16).count, 1);  // any size: the ratio decides
  EXPECT_EQ(sample_parts(x, 7.99 * y, 16).count, 1);         // just under the anisotropy threshold
  EXPECT_EQ(sample_parts(x, 8.01 * y, 16).count, 2);
  EXPECT_EQ(sample_parts(x, 1000.0 * y, 16).count, 16);
  EXPECT_EQ(sample_parts(x, 1000.0 * y, 1000).count, kMaxSampleParts);  // the cap is clamped
  EXPECT_EQ(sample_parts(x, 1000.0 * y, 1).count, 1);                   // max_parts 1: whole
  EXPECT_EQ(sample_parts(x, 1000.0 * y, 0).count, 1);
  EXPECT_EQ(sample_parts(x, Vec3(INFINITY, 0, 0), 16).count, 1);  // a grazing ray
  EXPECT_EQ(sample_parts(x, Vec3(NAN, 0, 0), 16).count, 1);
  EXPECT_EQ(sample_parts(Vec3::Zero(), Vec3::Zero(), 16).count, 1);
  // A line (s2 = 0): as many parts as allowed, along the line's pixel direction.
  const SampleParts line = sample_parts(x, 2.0 * x, 4);
  EXPECT_EQ(line.count, 4);
  EXPECT_NEAR(std::abs(line.axis.dot(Vec2(1.0, 2.0).normalized())), 1.0, 1e-12);
  EXPECT_EQ(sample_parts(x, 30.0 * y, 16).axis.cwiseAbs(), Vec2(0.0, 1.0));
}

TEST(SampleParts, PartsTileTheSample) {
  // Offsets: centred, a part apart along the axis, so that [offset - 1/(2P), offset + 1/(2P)] along the axis tile
  // [-1/2, 1/2]; differentials: the component along the axis shrinks by 1/P, the one across it is kept.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double angle = 3.2 * u(rng);
    SampleParts p;
    p.count = 2 + trial % 15;
    p.axis = Vec2(std::cos(angle), std::sin(angle));
    Vec2 sum = Vec2::Zero();
    for (int k = 0; k < p.count; ++k) {
      const Vec2 o = part_offset(p, k);
      sum += o;
      EXPECT_NEAR(o.dot(Vec2(-p.axis.y(), p.axis.x())), 0.0, 1e-15);
      EXPECT_NEAR(o.dot(p.axis), -0.5 + (k + 0.5) / p.count, 1e-15);
    }
    EXPECT_NEAR(sum.norm(), 0.0, 1e-12);
    const Vec3 ddx(u(rng), u(rng), u(rng)), ddy(u(rng), u(rng), u(rng));
    Vec3 px = ddx, py = ddy;
    shrink_to_part(p, px, py);
    const auto along = [&](const Vec3& dx, const Vec3& dy, const Vec2& e) { return Vec3(e.x() * dx + e.y() * dy); };
    const Vec2 across(-p.axis.y(), p.axis.x());
    EXPECT_LT((along(px, py, p.axis) - along(ddx, ddy, p.axis) / p.count).norm(), 1e-14);
    EXPECT_LT((along(px, py, across) - along(ddx, ddy, across)).norm(), 1e-14);
  }
}

// The plane receding to the horizon over a 64 x 64 bumpy map (uv scale 60) and its 16 x 16-ray reference, made once
// for the render tests below; render() bakes and renders an effect on it.
struct RecedingBumpyPlane {
  test::ScratchDir dir{"sample_parts_receding"};
  Image reference;
  RecedingBumpyPlane() {
    testing::write_bumpy_map(dir / "map.exr", 64, 64);
    reference = render("mip", 16, 1);
  }
  Image render(const nlohmann::json& effect, uint32_t reference_rays, int max_parts) const {
    return test::render_in(dir.path(), test::receding_plane_scene(effect, 60.0), reference_rays, max_parts);
  }
};

const RecedingBumpyPlane& receding_bumpy_plane() {
  static const RecedingBumpyPlane plane;
  return plane;
}

TEST(SampleParts, LongFootprintsInPartsAreCloserToTheReference) {
  const RecedingBumpyPlane& plane = receding_bumpy_plane();
  const auto render = [&](const nlohmann::json& effect, int max_parts) { return plane.render(effect, 0, max_parts); };
  const Image& reference = plane.reference;
  for (const nlohmann::json& effect :
       {nlohmann::json("mip"), nlohmann::json("toksvig"), nlohmann::json{{"name", "vmf"}, {"lobes", 2}}}) {
    const double whole = compare_images(render(effect, 1), reference).rmse;
    const double parts = compare_images(render(effect, 4), reference).rmse;
    std::cout << effect.dump() << ": rmse vs reference, footprints whole " << whole << ", in up to 4 parts " << parts
              << "\n";
    EXPECT_LT(parts, 0.8 * whole) << effect.dump();
  }
}

TEST(SampleParts, ShKeepsTheHighlightOfTheFinestLevelNormalsAPartReads) {
  // A part of a long footprint near the camera reads a few finest-level normals (deltas). The sh shader once shaded
  // them as one lobe widened by their spread, whose masking at the grazing view halved the point light's highlight
  // on the rows where the footprints are split (measured on the filtering plane: sh8 at 16 spp 0.19 RMSE on those
  // rows, 0.008 whole); the deltas now shade as the reference shades a normal (sh_effect.cpp). Property: in parts,
  // sh is as close to the reference as toksvig (which shades the same bilinear normals at the finest level), and
  // splitting no longer makes it worse.
  const RecedingBumpyPlane& plane = receding_bumpy_plane();
  const nlohmann::json sh = {{"name", "sh"}, {"order", 8}};
  const double toksvig = compare_images(plane.render("toksvig", 0, 4), plane.reference).rmse;
  const double sh_whole = compare_images(plane.render(sh, 0, 1), plane.reference).rmse;
  const double sh_parts = compare_images(plane.render(sh, 0, 4), plane.reference).rmse;
  std::cout << "receding plane, rmse vs reference: toksvig in parts " << toksvig << ", sh8 whole " << sh_whole
            << ", sh8 in parts " << sh_parts << "\n";
  EXPECT_LT(sh_parts, 1.1 * toksvig);
  EXPECT_LT(sh_parts, sh_whole);
}

}  // namespace
}  // namespace mbk
