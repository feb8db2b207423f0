// Moment pyramids of drivers (see moment_pyramid.h).
#include "libbake/colormap/moment_pyramid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "formats/asset.h"
#include "formats/error.h"
#include "formats/mip_levels.h"
#include "formats/moments_layout.h"
#include "libbake/image/box_pyramid.h"
#include "libbake/image/texture_taps.h"
#include "libbake/image/normal_map.h"

namespace mbk {

Driver load_driver(const std::filesystem::path& path, uint32_t channel) {
  const std::string where = path.string();
  const ImageHeader header = read_image_header_within(path, kMaxNormalMapSide, "driver");
  if (channel >= header.info.file_channels)
    throw Error(ExitCode::invalid_input,
                "--channel " + std::to_string(channel) + " but the image has " +
                    std::to_string(header.info.file_channels) + " channel" +
                    (header.info.file_channels == 1 ? "" : "s"),
                where);
  ImageFileInfo info;
  const Image image = load_image(path, &info);
  Driver d;
  d.width = image.width;
  d.height = image.height;
  d.values.resize(size_t(d.width) * d.height);
  for (uint32_t row = 0; row < d.height; ++row)
    for (uint32_t x = 0; x < d.width; ++x) {
      const double v = image.at(x, row, channel);
      if (!std::isfinite(v))
        throw Error(ExitCode::invalid_input, "non-finite driver value",
                    where + ", texel (" + std::to_string(x) + ", " + std::to_string(row) + ")");
      d.values[size_t(row) * d.width + x] = v;
    }
  d.record = {{"path", where},
              {"content_hash", file_content_hash(path)},
              {"bytes", std::filesystem::file_size(path)},
              {"width", d.width},
              {"height", d.height},
              {"channels", info.file_channels},
              {"pixel_format", info.pixel_format},
              {"channel", channel}};
  return d;
}

MomentPyramid build_moment_pyramid(const Driver& driver) {
  if (driver.width == 0 || driver.height == 0 || driver.values.size() != size_t(driver.width) * driver.height)
    throw Error(ExitCode::runtime_failure, "internal: empty driver or value count not matching its size");
  // The shift: the mean, summed by rows then rows in order (deterministic), rounded to float.
  double sum = 0.0;
  for (uint32_t row = 0; row < driver.height; ++row) {
    double r = 0.0;
    for (uint32_t x = 0; x < driver.width; ++x) r += driver.values[size_t(row) * driver.width + x];
    sum += r;
  }
  MomentPyramid p;
  p.shift = double(float(sum / double(driver.values.size())));
  Image finest;
  finest.width = driver.width;
  finest.height = driver.height;
  finest.channels = kMomentsChannels;
  finest.pixels.resize(driver.values.size() * 2);
  for (size_t i = 0; i < driver.values.size(); ++i) {
    const float d = float(driver.values[i] - p.shift);
    finest.pixels[2 * i] = d;
    finest.pixels[2 * i + 1] = float(double(d) * double(d));
  }
  p.levels = build_box_pyramid(std::move(finest));
  return p;
}

FootprintMoments sample_moments(const MomentPyramid& pyramid, const Vec2& uv, double lod) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  if (pyramid.levels.empty()) throw Error(ExitCode::runtime_failure, "internal: sampling an empty moment pyramid");
  if (!std::isfinite(uv.x()) || !std::isfinite(uv.y()) || std::isnan(lod)) return {nan, nan};
  const LevelBlend b = level_blend(pyramid.levels.size(), lod);
  double m[2] = {0.0, 0.0};
  for (const auto& [k, level_weight] : {std::pair{b.fine, 1.0 - b.t}, std::pair{b.coarse, b.t}}) {
    if (level_weight == 0.0) continue;
    const Image& L = pyramid.levels[k];
    for (const TextureTap& tap : bilinear_taps(L.width, L.height, uv))
      for (uint32_t c = 0; c < 2; ++c) m[c] += level_weight * tap.weight * L.at(tap.x, tap.row, c);
  }
  return {pyramid.shift + m[0], std::max(0.0, m[1] - m[0] * m[0])};
}

AssetWriter moments_asset_writer(const MomentPyramid& pyramid, const Driver& driver) {
  double lo = driver.values.front(), hi = lo, sum = 0.0;
  for (double v : driver.values) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    sum += v;
  }
  const double mean = sum / double(driver.values.size());
  double squares = 0.0;
  for (double v : driver.values) squares += (v - mean) * (v - mean);
  nlohmann::json metadata;
  metadata["inputs"] = nlohmann::json::array({driver.record});
  metadata["parameters"] = {
      {"width", driver.width}, {"height", driver.height}, {"levels", pyramid.levels.size()}, {"shift", pyramid.shift}};
  metadata["conventions"] = {
      {"uv", "u right, v up; texel (x, row) centre at ((x + 0.5) / W, 1 - (row + 0.5) / H), row 0 at the top"},
      {"channels",
       "per texel (E[d], E[d^2]) with d = f - shift: footprint mean = shift + E[d], variance = "
       "E[d^2] - E[d]^2 after interpolating both"},
      {"levels",
       "formats/mip_levels.h: level k is max(1, floor(W / 2^k)) x max(1, floor(H / 2^k)), each texel the "
       "area-weighted mean of level 0 over its rectangle"},
      {"lookup", "trilinear, wrapping at the borders (tiling)"}};
  metadata["statistics"] = {
      {"min", lo}, {"max", hi}, {"mean", mean}, {"variance", squares / double(driver.values.size())}};
  AssetWriter writer("moments", std::move(metadata));
  for (size_t k = 0; k < pyramid.levels.size(); ++k) {
    const Image& L = pyramid.levels[k];
    writer.add(moments_level_name(k), {L.height, L.width, kMomentsChannels}, L.pixels);
  }
  return writer;
}

MomentPyramid read_moment_pyramid(const Asset& asset) {
  const auto& p = asset.metadata()["parameters"];
  if (asset.metadata().value("kind", "") != "moments" || !p.is_object() || !p.contains("shift") ||
      !p["shift"].is_number() || !p.contains("width") || !p["width"].is_number_unsigned() || !p.contains("height") ||
      !p["height"].is_number_unsigned())
    throw Error(ExitCode::invalid_input, "not a moments asset (parameters width, height, shift)");
  MomentPyramid pyramid;
  pyramid.shift = p["shift"].get<double>();
  const auto sizes = mip_level_sizes(p["width"].get<uint32_t>(), p["height"].get<uint32_t>());
  for (size_t k = 0; k < sizes.size(); ++k) {
    const SectionInfo& s = asset.section(moments_level_name(k));
    if (s.shape != std::vector<uint64_t>{sizes[k].height, sizes[k].width, kMomentsChannels})
      throw Error(ExitCode::invalid_input, "moments level shape does not match its size", moments_level_name(k));
    Image L;
    L.width = sizes[k].width;
    L.height = sizes[k].height;
    L.channels = kMomentsChannels;
    L.pixels = asset.read<float>(moments_level_name(k));
    pyramid.levels.push_back(std::move(L));
  }
  if (pyramid.levels.empty()) throw Error(ExitCode::invalid_input, "moments asset has no levels");
  return pyramid;
}

}  // namespace mbk
