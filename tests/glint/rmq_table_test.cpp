// The RMQ table against brute force ([Wang20] Sec. 4.4, Alg. 1-2): for >= 10,000 random rectangles per map
// (squares up to twice the patch, squares running over the right/bottom border, and non-square rectangles up
// to the whole map), on the six generated kinds, non-square and non-power-of-two sizes, tiny maps and the real
// maps when present, at 16 and 8 bits, the stored bounds contain the truth (the min/max of the texels' leaf
// element intervals, element_normal_bounds.h) and are within one quantum of it. In fact the query is exact
// up to quantization (the strip cover reads only texels of the rectangle), so the codes are asserted EQUAL to
// the quantized brute force: there is no cover slack to document. Also: every stored entry (every level,
// every texel, border squares included) is the quantized clipped brute force, levels nest, squares need at
// most four lookups, bytes do not depend on the thread count, and the memory matches the paper's 14 MiB.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "formats/asset.h"
#include "formats/error.h"
#include "formats/validate.h"
#include "libbake/core/hash.h"
#include "libbake/core/parallel.h"
#include "libbake/gen/generator.h"
#include "libbake/glint/element_normal_bounds.h"
#include "libbake/glint/rmq_asset.h"
#include "libbake/glint/rmq_table.h"

namespace mbk {
namespace {

// The leaf intervals of every texel, read once.
struct Leaves {
  uint32_t width, height;
  std::vector<RmqBounds> b;
  const RmqBounds& at(uint32_t x, uint32_t row) const { return b[size_t(row) * width + x]; }
};

Leaves leaves_of(const NormalMap& m) {
  Leaves l{m.width, m.height, {}};
  l.b.reserve(m.texels.size());
  for (uint32_t row = 0; row < m.height; ++row)
    for (uint32_t x = 0; x < m.width; ++x) l.b.push_back(element_normal_bounds(m, x, row));
  return l;
}

struct Rect {
  uint32_t x, row, w, h;
};

// Min/max of the leaf intervals over [x, x + w) x [row, row + h) clipped to the map, texel by texel.
RmqBounds brute_force(const Leaves& l, const Rect& r) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  RmqBounds out{inf, -inf, inf, -inf};
  for (uint32_t row = r.row; row < std::min(r.row + r.h, l.height); ++row)
    for (uint32_t x = r.x; x < std::min(r.x + r.w, l.width); ++x) {
      const RmqBounds& b = l.at(x, row);
      out.min_x = std::min(out.min_x, b.min_x), out.max_x = std::max(out.max_x, b.max_x);
      out.min_y = std::min(out.min_y, b.min_y), out.max_y = std::max(out.max_y, b.max_y);
    }
  return out;
}

// Side in [1, max], log-uniform (small rectangles as often as large ones, per octave).
uint32_t log_uniform_side(uint32_t h, uint32_t max) {
  const double side = std::floor(std::exp(unit_from_hash(h) * std::log(double(max) + 1.0)));
  return std::clamp(uint32_t(side), 1u, max);
}

// Three kinds in turn: squares of side 1..2P inside the map, squares starting near the right/bottom border
// and running over it (the query clips them, like the stored squares), and non-square rectangles with
// log-uniform sides up to the whole map.
std::vector<Rect> random_rects(uint32_t W, uint32_t H, uint32_t patch, uint32_t count, uint32_t seed) {
  std::vector<Rect> rects;
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t h1 = hash3(seed, i, 1), h2 = hash3(seed, i, 2), h3 = hash3(seed, i, 3);
    Rect r{};
    if (i % 3 == 0) {
      const uint32_t side = h1 % 2 ? 1u << (h1 / 2 % (std::bit_width(patch) + 1)) : 1 + h1 / 2 % (2 * patch);
      r.w = r.h = side;
      r.x = side <= W ? h2 % (W - side + 1) : h2 % W;
      r.row = side <= H ? h3 % (H - side + 1) : h3 % H;
    } else if (i % 3 == 1) {
      const uint32_t side = 1 + h1 % (2 * patch);
      r.w = r.h = side;
      r.x = W - 1 - h2 % std::min(side, W);
      r.row = H - 1 - h3 % std::min(side, H);
    } else {
      r.w = log_uniform_side(h1, W), r.h = log_uniform_side(hash3(seed, i, 4), H);
      r.x = h2 % (W - r.w + 1), r.row = h3 % (H - r.h + 1);
    }
    rects.push_back(r);
  }
  return rects;
}

std::string text(const Rect& r) {
  return "[" + std::to_string(r.x) + ", +" + std::to_string(r.w) + ") x [" + std::to_string(r.row) + ", +" +
         std::to_string(r.h) + ")";
}

// Asserts containment, one-quantum tightness and exactness of the codes; `mean_slack` receives the mean
// slack in quanta.
void check_rects(const RmqTable& t, const Leaves& l, const std::vector<Rect>& rects, const std::string& label,
                 double* mean_slack = nullptr) {
  const RmqTableView view = t.view();
  const uint32_t bits = t.layout.bits;
  const double quantum[2] = {t.range[0].quantum(bits), t.range[1].quantum(bits)};
  double slack_sum = 0;
  for (const Rect& r : rects) {
    const RmqBounds truth = brute_force(l, r);
    const RmqCodes codes = view.query_codes(r.x, r.row, r.w, r.h);
    const RmqBounds got = view.dequantize(codes);
    const double truth_v[4] = {truth.min_x, truth.max_x, truth.min_y, truth.max_y};
    const double got_v[4] = {got.min_x, got.max_x, got.min_y, got.max_y};
    const uint32_t got_c[4] = {codes.min_x, codes.max_x, codes.min_y, codes.max_y};
    for (int c = 0; c < 4; ++c) {
      const bool is_min = c % 2 == 0;
      const RmqRange& range = t.range[c / 2];
      const double slack = is_min ? truth_v[c] - got_v[c] : got_v[c] - truth_v[c];
      ASSERT_GE(slack, 0.0) << label << " " << text(r) << " component " << c << ": bound excludes the truth";
      const double rounding = 1e-15 * std::max(std::abs(range.lo), std::abs(range.hi));
      ASSERT_LE(slack, quantum[c / 2] + rounding) << label << " " << text(r) << " component " << c;
      const uint32_t exact =
          is_min ? rmq_quantize_down(truth_v[c], range, bits) : rmq_quantize_up(truth_v[c], range, bits);
      ASSERT_EQ(got_c[c], exact) << label << " " << text(r) << " component " << c;
      slack_sum += quantum[c / 2] > 0 ? slack / quantum[c / 2] : 0.0;
    }
  }
  if (mean_slack) *mean_slack = slack_sum / (4.0 * rects.size());
}

constexpr uint32_t kRectsPerMap = 10000;

TEST(RmqTable, ContainsBruteForceMinMax_GeneratedKinds) {
  for (const GeneratorKind& kind : generator_kinds()) {
    const NormalMap map = generate_normal_map(kind.name, {256, 256}, 3, Progress::silent());
    const Leaves l = leaves_of(map);
    const auto rects = random_rects(256, 256, kRmqDefaultPatch, kRectsPerMap, 11);
    for (uint32_t bits : {16u, 8u}) {
      const RmqTable t = build_rmq_table(map, kRmqDefaultPatch, bits, Progress::silent());
      double slack = 0;
      check_rects(t, l, rects, std::string(kind.name) + " " + std::to_string(bits) + " bits", &slack);
      if (HasFatalFailure()) return;
      RecordProperty(std::string(kind.name) + "_" + std::to_string(bits) + "_mean_slack_quanta", std::to_string(slack));
    }
  }
}

TEST(RmqTable, ContainsBruteForceMinMax_NonSquareRectangles) {
  // Non-square, non-power-of-two maps; every rectangle of the third kind is non-square and read by a strip.
  struct Case {
    const char* kind;
    uint32_t w, h, patch;
  };
  for (const Case& c : {Case{"bumps", 300, 77, 64}, Case{"leather", 77, 300, 32}, Case{"panels", 129, 65, 64},
                        Case{"scratches", 1000, 9, 8}, Case{"flakes", 13, 211, 2}}) {
    const NormalMap map = generate_normal_map(c.kind, {c.w, c.h}, 5, Progress::silent());
    const Leaves l = leaves_of(map);
    const auto rects = random_rects(c.w, c.h, c.patch, kRectsPerMap, 12);
    for (uint32_t bits : {16u, 8u}) {
      const RmqTable t = build_rmq_table(map, c.patch, bits, Progress::silent());
      check_rects(t, l, rects,
                  std::string(c.kind) + " " + std::to_string(c.w) + "x" + std::to_string(c.h) + " " +
                      std::to_string(bits) + " bits");
      if (HasFatalFailure()) return;
    }
  }
}

TEST(RmqTable, ContainsBruteForceMinMax_TinyMaps) {
  for (auto [w, h] : {std::pair{1u, 1u}, {1u, 9u}, {9u, 1u}, {2u, 2u}, {2u, 3u}, {5u, 5u}, {3u, 8u}}) {
    const NormalMap map = generate_normal_map("bumps", {w, h}, 2, Progress::silent());
    const Leaves l = leaves_of(map);
    const uint32_t patch = rmq_default_patch(w, h);
    const auto rects = random_rects(w, h, patch, kRectsPerMap, 13);
    for (uint32_t bits : {16u, 8u}) {
      const RmqTable t = build_rmq_table(map, patch, bits, Progress::silent());
      check_rects(t, l, rects, std::to_string(w) + "x" + std::to_string(h) + " " + std::to_string(bits) + " bits");
      if (HasFatalFailure()) return;
    }
  }
}

TEST(RmqTable, ContainsBruteForceMinMax_RealMaps) {
  const std::filesystem::path dir = MICROBAKE_REAL_DATA_DIR;
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(dir))
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".png" && !e.path().stem().string().ends_with("_height")) files.push_back(e.path());
  if (files.empty()) GTEST_SKIP() << "no real maps in " << dir;
  std::sort(files.begin(), files.end());
  for (const auto& p : files) {
    // All the real maps are -Y (README, "What the loader found"); one lossy map needs the repair policy.
    const LoadedNormalMap in = load_normal_map(p, {YConvention::minus_y, InvalidTexelPolicy::repair});
    const Leaves l = leaves_of(in.map);
    const uint32_t patch = rmq_default_patch(in.map.width, in.map.height);
    const auto rects = random_rects(in.map.width, in.map.height, patch, kRectsPerMap, 14);
    for (uint32_t bits : {16u, 8u}) {
      const RmqTable t = build_rmq_table(in.map, patch, bits, Progress::silent());
      check_rects(t, l, rects, p.filename().string() + " " + std::to_string(bits) + " bits");
      if (HasFatalFailure()) return;
    }
  }
}

TEST(RmqTable, EveryStoredSquareIsTheQuantizedClippedBruteForce) {
  // Exhaustive: every level, every texel, so every square touching the right or bottom border is included.
  for (auto [w, h] : {std::pair{1u, 1u}, {1u, 9u}, {9u, 1u}, {2u, 3u}, {5u, 5u}, {37u, 23u}, {23u, 37u}, {64u, 17u}}) {
    const NormalMap map = generate_normal_map("leather", {w, h}, 4, Progress::silent());
    const Leaves l = leaves_of(map);
    const uint32_t patch = std::bit_floor(std::min(w, h));
    for (uint32_t bits : {16u, 8u}) {
      const RmqTable t = build_rmq_table(map, patch, bits, Progress::silent());
      const RmqTableView view = t.view();
      for (uint32_t k = 0; k < t.layout.levels; ++k)
        for (uint32_t row = 0; row < h; ++row)
          for (uint32_t x = 0; x < w; ++x) {
            const RmqBounds truth = brute_force(l, {x, row, 1u << k, 1u << k});
            const RmqCodes e = view.entry(k, x, row);
            const std::string at = std::to_string(w) + "x" + std::to_string(h) + " level " + std::to_string(k) + " (" +
                                   std::to_string(x) + ", " + std::to_string(row) + ")";
            ASSERT_EQ(e.min_x, rmq_quantize_down(truth.min_x, t.range[0], bits)) << at;
            ASSERT_EQ(e.max_x, rmq_quantize_up(truth.max_x, t.range[0], bits)) << at;
            ASSERT_EQ(e.min_y, rmq_quantize_down(truth.min_y, t.range[1], bits)) << at;
            ASSERT_EQ(e.max_y, rmq_quantize_up(truth.max_y, t.range[1], bits)) << at;
          }
    }
  }
}

TEST(RmqTable, RangeIsTheLeafIntervalsExtremesWithoutFlatGround) {
  // No texel of `bumps` has a degenerate leaf: the range is the data's. With flat ground (scratches) it holds
  // the data and is widened so that the flat ground is a code (rmq_atom_range_test.cpp).
  for (const bool flat_ground : {false, true}) {
    const NormalMap map = generate_normal_map(flat_ground ? "scratches" : "bumps", {90, 70}, 1, Progress::silent());
    const RmqBounds data = brute_force(leaves_of(map), {0, 0, 90, 70});
    const RmqTable t = build_rmq_table(map, 64, 16, Progress::silent());
    const double lo[2] = {data.min_x, data.min_y}, hi[2] = {data.max_x, data.max_y};
    for (int c = 0; c < 2; ++c) {
      EXPECT_LE(t.range[size_t(c)].lo, lo[c]);
      EXPECT_GE(t.range[size_t(c)].hi, hi[c]);
      if (flat_ground) continue;
      EXPECT_EQ(t.range[size_t(c)].lo, lo[c]);
      EXPECT_EQ(t.range[size_t(c)].hi, hi[c]);
    }
  }
}

TEST(RmqTable, LevelsNest) {
  const NormalMap map = generate_normal_map("panels", {100, 61}, 6, Progress::silent());
  for (uint32_t bits : {16u, 8u}) {
    const RmqTable t = build_rmq_table(map, 32, bits, Progress::silent());
    const RmqTableView v = t.view();
    for (uint32_t k = 1; k < t.layout.levels; ++k) {
      const uint32_t half = 1u << (k - 1);
      for (uint32_t row = 0; row < 61; ++row)
        for (uint32_t x = 0; x < 100; ++x) {
          const RmqCodes p = v.entry(k, x, row);
          for (uint32_t dy : {0u, half})
            for (uint32_t dx : {0u, half}) {
              if (x + dx >= 100 || row + dy >= 61) continue;
              const RmqCodes c = v.entry(k - 1, x + dx, row + dy);
              ASSERT_TRUE(p.min_x <= c.min_x && p.max_x >= c.max_x && p.min_y <= c.min_y && p.max_y >= c.max_y)
                  << "level " << k << " (" << x << ", " << row << ")";
            }
          ASSERT_LE(p.min_x, p.max_x);
          ASSERT_LE(p.min_y, p.max_y);
        }
    }
  }
}

TEST(RmqTable, SquaresInsideAPatchNeedAtMostFourLookups) {
  const NormalMap map = generate_normal_map("bumps", {200, 150}, 1, Progress::silent());
  const RmqTable t = build_rmq_table(map, 32, 16, Progress::silent());
  const RmqTableView v = t.view();
  for (uint32_t side = 1; side <= 64; ++side) {
    uint32_t lookups = 0;
    v.query_codes(200 - side, 150 - side, side, side, &lookups);
    EXPECT_EQ(lookups, std::has_single_bit(side) && side <= 32 ? 1u : 4u) << side;
  }
  // A 64 x 3 strip reads ceil(64 / 2) x ceil(3 / 2) squares of side 2.
  uint32_t lookups = 0;
  v.query_codes(10, 10, 64, 3, &lookups);
  EXPECT_EQ(lookups, 64u);
}

TEST(RmqTable, ConstantMapStoresItsValueExactly) {
  NormalMap map;
  map.width = 20, map.height = 12;
  map.texels.assign(240, Vec3f(0.28f, -0.96f, 0.0f));
  for (uint32_t bits : {16u, 8u}) {
    const RmqTable t = build_rmq_table(map, 8, bits, Progress::silent());
    EXPECT_EQ(t.range[0].lo, t.range[0].hi);
    const RmqBounds b = t.view().query(3, 2, 17, 10);
    EXPECT_EQ(b.min_x, double(0.28f));
    EXPECT_EQ(b.max_x, double(0.28f));
    EXPECT_EQ(b.min_y, double(-0.96f));
    EXPECT_EQ(b.max_y, double(-0.96f));
    EXPECT_EQ(t.leaf.mean_slack_quanta, 0.0);
  }
}

TEST(RmqTable, BadPatchOrBitsAreCommandLineErrors) {
  const NormalMap map = generate_normal_map("bumps", {40, 20}, 1, Progress::silent());
  for (auto [patch, bits] : {std::pair{3u, 16u}, {32u, 16u}, {8192u, 16u}, {0u, 16u}, {8u, 12u}}) {
    try {
      build_rmq_table(map, patch, bits, Progress::silent());
      ADD_FAILURE() << "patch " << patch << ", bits " << bits << " accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ExitCode::bad_command_line) << e.what();
    }
  }
}

TEST(RmqTable, DefaultPatchIs64OrTheLargestThatFits) {
  EXPECT_EQ(rmq_default_patch(512, 512), 64u);
  EXPECT_EQ(rmq_default_patch(2048, 100), 64u);
  EXPECT_EQ(rmq_default_patch(16, 300), 16u);
  EXPECT_EQ(rmq_default_patch(100, 37), 32u);
  EXPECT_EQ(rmq_default_patch(1, 1), 1u);
}

TEST(RmqTable, Default512TableIsThePapers14MiB) {
  // [Wang20] Sec. 5.1: about 14 MB for a 512^2 example, 64 bits per entry: 7 levels of 512^2 entries.
  const NormalMap map = generate_normal_map("flakes", {512, 512}, 1, Progress::silent());
  const RmqTable t16 = build_rmq_table(map, rmq_default_patch(512, 512), 16, Progress::silent());
  EXPECT_EQ(t16.layout.levels, 7u);
  EXPECT_EQ(t16.table.size(), 14u * 1024 * 1024);
  EXPECT_EQ(t16.table.size(), 7u * 512 * 512 * 8);
  const RmqTable t8 = build_rmq_table(map, rmq_default_patch(512, 512), 8, Progress::silent());
  EXPECT_EQ(t8.table.size(), 7u * 1024 * 1024);
}

TEST(RmqTable, BytesIdenticalWhateverTheThreadCount) {
  const NormalMap map = generate_normal_map("brushed", {173, 96}, 8, Progress::silent());
  LoadedNormalMap in{map, {}};
  in.record.path = "brushed.png";
  const int threads = thread_count();
  std::vector<std::vector<uint8_t>> files;
  for (int n : {1, 2, 3}) {
    set_thread_count(n);
    files.push_back(bake_rmq_asset(in, 32, 16, Progress::silent()).serialize());
  }
  set_thread_count(threads);
  EXPECT_EQ(files[0], files[1]);
  EXPECT_EQ(files[0], files[2]);
}

TEST(RmqAsset, PassesValidateAndReadsBackAsTheBakedTable) {
  for (auto [kind, w, h, patch, bits] :
       {std::tuple{"bumps", 64u, 64u, 64u, 16u}, {"flakes", 45u, 70u, 32u, 8u}, {"panels", 1u, 1u, 1u, 16u}}) {
    LoadedNormalMap in{generate_normal_map(kind, {w, h}, 1, Progress::silent()), {}};
    const std::vector<uint8_t> bytes = bake_rmq_asset(in, patch, bits, Progress::silent()).serialize();
    const auto findings = validate_asset(bytes);
    EXPECT_TRUE(findings.empty()) << kind << ": " << findings.front().message;
    const Asset asset = Asset::parse(bytes, kind);
    const RmqTableView stored = RmqTableView::of(asset);
    const RmqTable baked = build_rmq_table(in.map, patch, bits, Progress::silent());
    EXPECT_EQ(stored.range()[0].lo, baked.range[0].lo);
    EXPECT_EQ(stored.range()[1].hi, baked.range[1].hi);
    EXPECT_EQ(asset.metadata()["statistics"]["table_bytes"].get<uint64_t>(), baked.table.size());
    for (const Rect& r : random_rects(w, h, patch, 500, 15)) {
      const RmqCodes a = stored.query_codes(r.x, r.row, r.w, r.h), b = baked.view().query_codes(r.x, r.row, r.w, r.h);
      ASSERT_TRUE(a.min_x == b.min_x && a.max_x == b.max_x && a.min_y == b.min_y && a.max_y == b.max_y) << text(r);
    }
  }
}

TEST(RmqQuery, EmptyOrOutsideRectanglesAreErrors) {
  const NormalMap map = generate_normal_map("bumps", {16, 8}, 1, Progress::silent());
  const RmqTable t = build_rmq_table(map, 8, 16, Progress::silent());
  const RmqTableView v = t.view();
  EXPECT_THROW(v.query_codes(16, 0, 1, 1), Error);
  EXPECT_THROW(v.query_codes(0, 8, 1, 1), Error);
  EXPECT_THROW(v.query_codes(0, 0, 0, 1), Error);
  EXPECT_NO_THROW(v.query_codes(15, 7, 100, 100));  // clipped to the last texel
}

}  // namespace
}  // namespace mbk
