// Real normal maps nobody here made (MICROBAKE_REAL_DATA_DIR, see SOURCES.md there; skipped when absent):
// every normal map loads as unit vectors (one, lossy, needs the repair policy), one-channel height maps are
// refused as such, the CLI bakes a valid mip asset from each, and the default convention, auto, reads each as
// SOURCES.md says (and its green-flipped copy the other way; flakes undecidable, read as +Y with one warning).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>

#include "formats/error.h"
#include "libbake/image/convention_detection.h"
#include "libbake/image/image_io.h"
#include "libbake/image/normal_map.h"
#include "libbake/image/normal_map_encoding.h"
#include "tests/image/cli_run.h"
#include "tests/image/warning_capture.h"

namespace mbk {
namespace {

const std::filesystem::path kRealDir = MICROBAKE_REAL_DATA_DIR;

std::vector<std::filesystem::path> real_images() {
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(kRealDir)) return files;
  for (const auto& e : std::filesystem::directory_iterator(kRealDir))
    if (e.path().extension() == ".png") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

bool is_height_map(const std::filesystem::path& p) { return p.stem().string().ends_with("_height"); }

// The one real map with an invalid texel (see NormalMapsLoadAsUnitVectorsAndHeightMapsAreRefused).
const std::filesystem::path kFlakes = "metallic_flakes.png";

TEST(RealMaps, NormalMapsLoadAsUnitVectorsAndHeightMapsAreRefused) {
  const auto files = real_images();
  if (files.empty()) GTEST_SKIP() << "no real maps in " << kRealDir;
  for (const auto& p : files) {
    if (is_height_map(p)) {
      try {
        load_normal_map(p, {});
        ADD_FAILURE() << p << " loaded as a normal map";
      } catch (const Error& e) {
        EXPECT_EQ(e.code(), ExitCode::invalid_input);
        EXPECT_NE(std::string(e.what()).find("height map"), std::string::npos) << e.what();
      }
      continue;
    }
    if (p.filename() == kFlakes) {
      // Lossy WebP left one texel below the horizon (blue 125 of 255, z = -0.02): refused as documented,
      // accepted with the repair policy.
      try {
        load_normal_map(p, {YConvention::minus_y, InvalidTexelPolicy::error});
        ADD_FAILURE() << p << ": the texel below the horizon was accepted";
      } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "1 invalid texel (NaN/Inf, zero length or z < 0); the first is at (x, row) = (106, 20): z < 0"),
                  std::string::npos)
            << e.what();
      }
    }
    const InvalidTexelPolicy policy = p.filename() == kFlakes ? InvalidTexelPolicy::repair : InvalidTexelPolicy::error;
    const LoadedNormalMap m = load_normal_map(p, {YConvention::minus_y, policy});
    EXPECT_EQ(m.record.repaired_texels, p.filename() == kFlakes ? 1u : 0u);
    for (const Vec3f& n : m.map.texels) ASSERT_NEAR(n.norm(), 1.0f, 1e-6f) << p;
    // The raw decoded lengths, before renormalisation (what the notes report).
    ImageFileInfo info;
    const Image raw = load_image(p, &info);
    double mean_len = 0, min_z = 1;
    for (size_t i = 0; i < raw.pixels.size(); i += raw.channels) {
      const Vec3 v(2.0 * raw.pixels[i] - 1, 2.0 * raw.pixels[i + 1] - 1, 2.0 * raw.pixels[i + 2] - 1);
      mean_len += v.norm(), min_z = std::min(min_z, v.z());
    }
    mean_len /= double(raw.pixels.size() / raw.channels);
    std::cout << "[real] " << p.filename().string() << ": " << m.map.width << "x" << m.map.height << " "
              << info.pixel_format << " x" << info.file_channels << ", mean |2v-1| " << mean_len << ", min z " << min_z
              << "\n";
    if (p.filename() == "ground_dirt_16bit.png") {
      EXPECT_EQ(m.record.pixel_format, "uint16");
    }
  }
}

// The conventions SOURCES.md gives (curl test and, where a height map comes with the file, its gradient agree):
// -Y for five maps, leather_grain only weakly (energy ratio 2.5); the flakes are not a height field.
const std::pair<const char*, const char*> kSourcesConventions[] = {
    {"scifi_panel_bevels.png", "-Y"}, {"brushed_streaks_diagonal.png", "-Y"},
    {"brick_floor.png", "-Y"},        {"ground_dirt_16bit.png", "-Y"},
    {"leather_grain.png", "-Y"},      {"metallic_flakes.png", "undecidable"}};

TEST(RealMaps, AutoFindsTheConventionSourcesMdGivesAndTheOppositeWhenGreenIsFlipped) {
  test::ScratchDir dir;
  bool any = false;
  for (const auto& [name, expected] : kSourcesConventions) {
    const auto p = kRealDir / name;
    if (!std::filesystem::exists(p)) continue;
    any = true;
    const InvalidTexelPolicy policy = p.filename() == kFlakes ? InvalidTexelPolicy::repair : InvalidTexelPolicy::error;
    test::WarningCapture warnings;
    const auto t0 = std::chrono::steady_clock::now();
    const LoadedNormalMap m = load_normal_map(p, {std::nullopt, policy});
    const auto t1 = std::chrono::steady_clock::now();
    const ConventionEvidence again = measure_convention(m.map);  // the map as read: -Y maps give -s
    const auto t2 = std::chrono::steady_clock::now();
    const nlohmann::json& e = m.record.convention_evidence;
    EXPECT_EQ(std::abs(again.statistic), std::abs(double(e["statistic"]))) << name;
    EXPECT_EQ(e["verdict"], expected) << name;
    EXPECT_EQ(m.record.convention, std::string(expected) == "undecidable" ? "+Y" : expected) << name;
    EXPECT_EQ(warnings.lines().size(), std::string(expected) == "undecidable" ? 1u : 0u) << name;
    // The green-flipped copy of the file, written as a 16-bit PNG and read back with auto: the other convention
    // (and the same vectors), or undecidable again.
    NormalMap flipped = load_normal_map(p, {YConvention::plus_y, policy}).map;  // green as stored
    for (Vec3f& n : flipped.texels) n.y() = -n.y();
    save_normal_map(dir / "flipped.png", flipped);
    const LoadedNormalMap f = load_normal_map(dir / "flipped.png", {});
    const nlohmann::json& fe = f.record.convention_evidence;
    const std::string opposite = std::string(expected) == "-Y" ? "+Y" : expected;
    EXPECT_EQ(fe["verdict"], opposite) << name;
    if (opposite != "undecidable") {
      for (size_t i = 0; i < m.map.texels.size(); ++i)
        ASSERT_LT((f.map.texels[i] - m.map.texels[i]).norm(), 1e-4f) << name << " texel " << i;
    }
    std::cout << "[real] " << name << ": curl statistic " << double(e["statistic"]) << " (energy ratio "
              << (1 + std::abs(double(e["statistic"]))) / (1 - std::abs(double(e["statistic"]))) << "), n_eff "
              << double(e["effective_stencils"]) << ", needed " << double(e["required_confidence"]) << " -> "
              << std::string(e["verdict"]) << "; green-flipped " << double(fe["statistic"]) << " -> "
              << std::string(fe["verdict"]) << "; load " << std::chrono::duration<double>(t1 - t0).count()
              << " s, statistic " << std::chrono::duration<double>(t2 - t1).count() << " s\n";
  }
  if (!any) GTEST_SKIP() << "no real maps in " << kRealDir;
}

TEST(RealMaps, CliBakesAValidMipAssetFromEachMap) {
  const auto files = real_images();
  if (files.empty()) GTEST_SKIP() << "no real maps in " << kRealDir;
  test::ScratchDir dir;
  for (const auto& p : files) {
    const auto asset = dir / (p.stem().string() + ".mbk");
    // No --convention: auto reads each as SOURCES.md says, silently, and warns once about the flakes.
    const auto r = test::run_cli("mip '" + p.string() + "' -o '" + asset.string() + "'", dir);
    if (is_height_map(p)) {
      EXPECT_EQ(r.exit_code, 3) << p;
      EXPECT_FALSE(std::filesystem::exists(asset));
      continue;
    }
    if (p.filename() == kFlakes) {
      EXPECT_EQ(r.exit_code, 3) << p;
      EXPECT_NE(r.err.find("--repair-invalid"), std::string::npos) << r.err;
      EXPECT_FALSE(std::filesystem::exists(asset));
      const auto repaired = test::run_cli("mip '" + p.string() + "' --repair-invalid -o '" + asset.string() + "'", dir);
      ASSERT_EQ(repaired.exit_code, 0) << repaired.err;
      EXPECT_EQ(repaired.err, "microbake: warning: cannot tell the normal map's green-channel convention (" +
                                  repaired.err.substr(repaired.err.find("curl statistic")));
      EXPECT_EQ(std::count(repaired.err.begin(), repaired.err.end(), '\n'), 1) << repaired.err;
      EXPECT_NE(repaired.err.find("read as +Y"), std::string::npos) << repaired.err;
    } else {
      ASSERT_EQ(r.exit_code, 0) << p << ": " << r.err;
      EXPECT_EQ(r.err, "") << p;
    }
    EXPECT_EQ(test::run_cli("validate '" + asset.string() + "'", dir).exit_code, 0) << p;
    const auto info = test::run_cli("info '" + asset.string() + "'", dir);
    EXPECT_NE(info.out.find(p.filename() == kFlakes ? "convention: +Y, undecidable, read as +Y (requested auto"
                                                    : "convention: -Y, detected (requested auto"),
              std::string::npos)
        << info.out;
  }
}

}  // namespace
}  // namespace mbk
