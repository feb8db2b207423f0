// Telling +Y from -Y by the curl of the slope field (libbake/image/convention_detection.h): every generated kind is
// detected as it is written (+Y) and its green-flipped copy as -Y, through files and the loader's auto; flakes are
// undecidable both ways; the hard cases (flat, 1 x 1, 1 x N, tiny, non-integrable, horizon texels, non-tileable
// crops); the statistic's invariances; and what the loader records and warns. Real maps: real_maps_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/gen/generator.h"
#include "libbake/image/convention_detection.h"
#include "libbake/image/normal_map.h"
#include "libbake/image/normal_map_encoding.h"
#include "tests/image/cli_run.h"
#include "tests/image/warning_capture.h"

namespace mbk {
namespace {

NormalMap gen(std::string_view kind, uint32_t w, uint32_t h, uint32_t seed = 1) {
  return find_generator(kind)->generate({w, h}, seed, Progress::silent());
}

NormalMap flip_green(NormalMap m) {
  for (Vec3f& n : m.texels) n.y() = -n.y();
  return m;
}

std::string verdict_name(const ConventionEvidence& e) {
  const auto v = e.verdict();
  return v ? convention_name(*v) : "undecidable";
}

NormalMap constant_map(uint32_t w, uint32_t h, const Vec3f& n) {
  NormalMap m{w, h, {}};
  m.texels.assign(size_t(w) * h, n);
  return m;
}

// Deterministic pseudo-random unit normals with z >= 0.5: a field with no height behind it.
NormalMap noise_map(uint32_t w, uint32_t h) {
  NormalMap m{w, h, {}};
  uint64_t state = 0x9E3779B97F4A7C15ull;
  auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) / double(1ull << 53) * 2.0 - 1.0;
  };
  for (size_t i = 0; i < size_t(w) * h; ++i) {
    const double x = 0.5 * next(), y = 0.5 * next();
    m.texels.push_back(Vec3(x, y, 1.0).normalized().cast<float>());
  }
  return m;
}

class ConventionOfGeneratedKinds : public ::testing::TestWithParam<GeneratorKind> {};

std::string kind_name(const ::testing::TestParamInfo<GeneratorKind>& info) { return std::string(info.param.name); }

// Through 16-bit PNG files, as `microbake gen` writes them, at three sizes and seeds: auto reads the map as +Y and its
// green-flipped copy as -Y (the same vectors), or, for flakes, finds both undecidable and reads them as +Y.
TEST_P(ConventionOfGeneratedKinds, AutoTellsTheMapFromItsGreenFlippedCopy) {
  const GeneratorKind& kind = GetParam();
  test::ScratchDir dir;
  const struct { uint32_t w, h, seed; } cases[] = {{512, 512, 1}, {128, 80, 2}, {64, 64, 3}};
  for (const auto& c : cases) {
    const NormalMap m = gen(kind.name, c.w, c.h, c.seed);
    save_normal_map(dir / "plus.png", m);
    save_normal_map(dir / "minus.png", m, YConvention::minus_y);  // green flipped
    test::WarningCapture warnings;
    const LoadedNormalMap plus = load_normal_map(dir / "plus.png", {});
    const LoadedNormalMap minus = load_normal_map(dir / "minus.png", {});
    const double s_plus = plus.record.convention_evidence["statistic"],
                 s_minus = minus.record.convention_evidence["statistic"];
    std::cout << "[convention] " << kind.name << " " << c.w << "x" << c.h << " seed " << c.seed << ": statistic "
              << s_plus << ", green-flipped " << s_minus << ", n_eff "
              << plus.record.convention_evidence["effective_stencils"] << ", needed "
              << plus.record.convention_evidence["required_confidence"] << "\n";
    EXPECT_EQ(plus.record.convention_requested, "auto");
    if (kind.from_height) {
      EXPECT_EQ(plus.record.convention, "+Y") << c.w;
      EXPECT_EQ(minus.record.convention, "-Y") << c.w;
      EXPECT_EQ(plus.record.convention_evidence["decision"], "detected");
      EXPECT_EQ(minus.record.convention_evidence["decision"], "detected");
      EXPECT_GT(s_plus, 0.9);
      EXPECT_LT(s_minus, -0.9);
      EXPECT_TRUE(warnings.lines().empty()) << warnings.lines().front();
      for (size_t i = 0; i < m.texels.size(); ++i)
        ASSERT_LT((plus.map.texels[i] - minus.map.texels[i]).norm(), 1e-4f) << "texel " << i;
    } else {
      EXPECT_EQ(plus.record.convention, "+Y");
      EXPECT_EQ(minus.record.convention, "+Y");
      EXPECT_EQ(plus.record.convention_evidence["verdict"], "undecidable");
      EXPECT_EQ(minus.record.convention_evidence["verdict"], "undecidable");
      EXPECT_EQ(plus.record.convention_evidence["decision"], "undecidable, read as +Y");
      ASSERT_EQ(warnings.lines().size(), 2u);
      EXPECT_NE(warnings.lines()[0].find("cannot tell the normal map's green-channel convention"), std::string::npos)
          << warnings.lines()[0];
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllKinds, ConventionOfGeneratedKinds,
                         ::testing::ValuesIn(generator_kinds().begin(), generator_kinds().end()), kind_name);

TEST(ConventionDetection, FlippingGreenNegatesTheStatisticExactly) {
  const NormalMap m = gen("leather", 96, 64);
  const ConventionEvidence e = measure_convention(m), f = measure_convention(flip_green(m));
  EXPECT_EQ(f.statistic, -e.statistic);
  EXPECT_EQ(f.effective_stencils, e.effective_stencils);
  EXPECT_EQ(verdict_name(e), "+Y");
  EXPECT_EQ(verdict_name(f), "-Y");
}

TEST(ConventionDetection, StatisticIsScaleFreeAndIgnoresNormalLengths) {
  const NormalMap m = gen("bumps", 128, 128);
  const ConventionEvidence e = measure_convention(m);
  NormalMap steeper = m, shorter = m;
  for (size_t i = 0; i < m.texels.size(); ++i) {
    const Vec3f& n = m.texels[i];
    steeper.texels[i] = Vec3f(3 * n.x(), 3 * n.y(), n.z()).normalized();  // every slope times 3
    shorter.texels[i] = n * (0.5f + 0.5f * float(i % 7) / 6.0f);          // lengths 0.5 .. 1
  }
  EXPECT_NEAR(measure_convention(steeper).statistic, e.statistic, 1e-5);
  EXPECT_NEAR(measure_convention(shorter).statistic, e.statistic, 1e-6);
}

TEST(ConventionDetection, SameBitsWhateverTheThreadCount) {
  const NormalMap m = gen("panels", 300, 200);
  const int before = thread_count();
  set_thread_count(1);
  const ConventionEvidence one = measure_convention(m);
  set_thread_count(2);
  const ConventionEvidence two = measure_convention(m);
  set_thread_count(before);
  EXPECT_EQ(one.statistic, two.statistic);
  EXPECT_EQ(one.effective_stencils, two.effective_stencils);
}

TEST(ConventionDetection, FlatMapsHaveNoEvidence) {
  for (const Vec3f& n : {Vec3f(0, 0, 1), Vec3f(0.3f, -0.4f, 0.866f)}) {
    const ConventionEvidence e = measure_convention(constant_map(64, 64, n));
    EXPECT_EQ(e.stencils, 62u * 62u);
    EXPECT_EQ(e.statistic, 0.0);
    EXPECT_EQ(e.effective_stencils, 0.0);
    EXPECT_EQ(verdict_name(e), "undecidable");
  }
}

TEST(ConventionDetection, MapsWithoutInteriorTexelsAreUndecidable) {
  // A stencil needs a neighbour on each side; borders are clamped, never wrapped.
  for (const auto& [w, h] : {std::pair{1u, 1u}, {1u, 64u}, {64u, 1u}, {2u, 64u}, {64u, 2u}}) {
    const ConventionEvidence e = measure_convention(gen("bumps", w, h));
    EXPECT_EQ(e.stencils, 0u) << w << "x" << h;
    EXPECT_EQ(verdict_name(e), "undecidable") << w << "x" << h;
  }
}

TEST(ConventionDetection, TinyMapsNeedEnoughEvidence) {
  // An 8 x 8 height field is exactly integrable (s = 1) but 36 stencils cannot rule out chance: n_eff is below
  // kConventionNullSigmas^2 = 36. From 24 x 24 on, bumps are decided.
  const ConventionEvidence tiny = measure_convention(gen("bumps", 8, 8));
  EXPECT_GT(tiny.statistic, 0.99);
  EXPECT_LT(tiny.effective_stencils, 36.0);
  EXPECT_EQ(verdict_name(tiny), "undecidable");
  for (uint32_t side : {24u, 32u, 64u}) {
    const ConventionEvidence e = measure_convention(gen("bumps", side, side));
    EXPECT_EQ(verdict_name(e), "+Y") << side << ": s " << e.statistic << ", n_eff " << e.effective_stencils;
    EXPECT_EQ(verdict_name(measure_convention(flip_green(gen("bumps", side, side)))), "-Y") << side;
  }
}

TEST(ConventionDetection, FieldsWithoutAHeightAreUndecidable) {
  for (uint32_t side : {16u, 64u, 256u, 1024u}) {
    const ConventionEvidence e = measure_convention(noise_map(side, side));
    std::cout << "[convention] noise " << side << "x" << side << ": statistic " << e.statistic << ", n_eff "
              << e.effective_stencils << ", needed " << e.required_confidence() << "\n";
    EXPECT_EQ(verdict_name(e), "undecidable") << side;
  }
  for (uint32_t seed = 1; seed <= 8; ++seed)
    for (uint32_t side : {32u, 128u, 512u}) {
      const ConventionEvidence e = measure_convention(gen("flakes", side, side, seed));
      std::cout << "[convention] flakes " << side << "x" << side << " seed " << seed << ": statistic " << e.statistic
                << ", n_eff " << e.effective_stencils << ", needed " << e.required_confidence() << "\n";
      EXPECT_EQ(verdict_name(e), "undecidable") << side << " seed " << seed;
    }
}

TEST(ConventionDetection, HorizonTexelsAreLeftOut) {
  // Texels at the horizon (z = 0, e.g. repaired z < 0) have unbounded slopes: the stencils touching them are
  // skipped, and the rest still decides.
  NormalMap m = gen("bumps", 128, 128);
  const uint64_t all = measure_convention(m).stencils;
  m.at(40, 40) = Vec3f(1, 0, 0);
  m.at(90, 17) = Vec3f(0, -1, 0);
  const ConventionEvidence e = measure_convention(m);
  EXPECT_EQ(e.stencils, all - 8u);  // each is a neighbour of 4 stencils
  EXPECT_TRUE(std::isfinite(e.statistic));
  EXPECT_EQ(verdict_name(e), "+Y");
  EXPECT_EQ(verdict_name(measure_convention(flip_green(m))), "-Y");
}

TEST(ConventionDetection, CropsThatDoNotTileAreDecidedAsWell) {
  // A window of a periodic map does not tile: wrapping round would add a seam of curl. Clamped, the window is as
  // integrable as the map.
  const NormalMap full = gen("leather", 256, 256);
  NormalMap crop{101, 77, {}};
  for (uint32_t row = 0; row < crop.height; ++row)
    for (uint32_t x = 0; x < crop.width; ++x) crop.texels.push_back(full.at(x + 37, row + 100));
  const ConventionEvidence e = measure_convention(crop);
  EXPECT_GT(e.statistic, 0.999);
  EXPECT_EQ(verdict_name(e), "+Y");
}

// ---- The loader: auto, explicit conventions, records and warnings ----

TEST(ConventionLoad, AutoReadsAMinusYFileAsMinusYWithoutWarning) {
  test::ScratchDir dir;
  const NormalMap m = gen("panels", 96, 96);
  save_normal_map(dir / "dx.png", m, YConvention::minus_y);
  test::WarningCapture warnings;
  const LoadedNormalMap a = load_normal_map(dir / "dx.png", {});
  const LoadedNormalMap e = load_normal_map(dir / "dx.png", {YConvention::minus_y, InvalidTexelPolicy::error});
  EXPECT_EQ(a.map.texels, e.map.texels);
  EXPECT_EQ(a.record.convention, "-Y");
  EXPECT_EQ(a.record.convention_requested, "auto");
  EXPECT_EQ(a.record.convention_evidence["verdict"], "-Y");
  EXPECT_EQ(a.record.convention_evidence["decision"], "detected");
  EXPECT_EQ(e.record.convention_requested, "-Y");
  EXPECT_EQ(e.record.convention_evidence["decision"], "as requested");
  // The statistic is the file's, whatever it is read as.
  EXPECT_EQ(a.record.convention_evidence["statistic"], e.record.convention_evidence["statistic"]);
  EXPECT_TRUE(warnings.lines().empty());
  const nlohmann::json j = a.record.to_json();
  for (const char* key : {"convention", "convention_requested", "convention_evidence"}) EXPECT_TRUE(j.contains(key));
  for (const char* key :
       {"statistic", "confidence", "required_confidence", "effective_stencils", "stencils", "verdict", "decision"})
    EXPECT_TRUE(j["convention_evidence"].contains(key)) << key;
}

TEST(ConventionLoad, UndecidableAutoWarnsOnceAndReadsPlusY) {
  test::ScratchDir dir;
  save_normal_map(dir / "flakes.png", gen("flakes", 64, 64));
  test::WarningCapture warnings;
  const LoadedNormalMap a = load_normal_map(dir / "flakes.png", {});
  EXPECT_EQ(a.record.convention, "+Y");
  ASSERT_EQ(warnings.lines().size(), 1u);
  const std::string& w = warnings.lines()[0];
  for (const char* part : {"cannot tell the normal map's green-channel convention (curl statistic ",
                           "needed): read as +Y", "--convention +Y|-Y", "flakes.png)"})
    EXPECT_NE(w.find(part), std::string::npos) << part << " not in: " << w;
  // Named explicitly, it is not warned about.
  warnings.clear();
  load_normal_map(dir / "flakes.png", {YConvention::plus_y, InvalidTexelPolicy::error});
  load_normal_map(dir / "flakes.png", {YConvention::minus_y, InvalidTexelPolicy::error});
  EXPECT_TRUE(warnings.lines().empty());
}

TEST(ConventionLoad, ExplicitConventionAgainstAConfidentStatisticWarns) {
  test::ScratchDir dir;
  save_normal_map(dir / "gl.png", gen("bumps", 64, 64));
  test::WarningCapture warnings;
  const LoadedNormalMap m = load_normal_map(dir / "gl.png", {YConvention::minus_y, InvalidTexelPolicy::error});
  EXPECT_EQ(m.record.convention, "-Y");  // as asked
  EXPECT_EQ(m.record.convention_evidence["decision"], "as requested, against the statistic");
  ASSERT_EQ(warnings.lines().size(), 1u);
  EXPECT_NE(
      warnings.lines()[0].find("the normal map is read as -Y as requested, but its slopes say +Y (curl statistic +"),
      std::string::npos)
      << warnings.lines()[0];
  warnings.clear();
  load_normal_map(dir / "gl.png", {YConvention::plus_y, InvalidTexelPolicy::error});
  EXPECT_TRUE(warnings.lines().empty());
}

TEST(ConventionLoad, RequestNames) {
  EXPECT_EQ(parse_convention_request("auto"), std::nullopt);
  EXPECT_EQ(parse_convention_request("AUTO"), std::nullopt);
  EXPECT_EQ(parse_convention_request("+y"), YConvention::plus_y);
  EXPECT_EQ(parse_convention_request("DirectX"), YConvention::minus_y);
  EXPECT_EQ(convention_request_name(std::nullopt), "auto");
  EXPECT_EQ(convention_request_name(YConvention::minus_y), "-Y");
  try {
    parse_convention_request("sideways");
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::bad_command_line);
    EXPECT_NE(std::string(e.what()).find("use auto, +Y/opengl or -Y/directx"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mbk
