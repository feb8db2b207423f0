// Reading colour maps from gradient images and JSON stops (see colormap_source.h).
#include "libbake/colormap/colormap_source.h"

#include <algorithm>
#include <cmath>

#include "formats/atomic_file.h"
#include "formats/error.h"
#include "formats/file_extension.h"
#include "libbake/image/image_io.h"
#include "libbake/image/normal_map.h"
#include "libbake/image/srgb_transfer.h"
#include "libbake/scene/json_fields.h"

namespace mbk {
namespace {

// Largest linear colour accepted in stops: the largest finite half float, so tables survive a half export.
constexpr double kMaxLinearColor = 65504.0;

bool is_json_path(const std::filesystem::path& path) { return lower_extension(path) == ".json"; }

nlohmann::json file_record(const std::filesystem::path& path) {
  return {
      {"path", path.string()}, {"content_hash", file_content_hash(path)}, {"bytes", std::filesystem::file_size(path)}};
}

LoadedColormap load_gradient_image(const std::filesystem::path& path, ColorEncoding encoding) {
  const std::string where = path.string();
  const ImageHeader header = read_image_header(path);
  if (header.width > kColormapMaxKnots || header.height > kMaxNormalMapSide)
    throw Error(ExitCode::invalid_input,
                "gradient image is " + std::to_string(header.width) + "x" + std::to_string(header.height) +
                    " texels; at most " + std::to_string(kColormapMaxKnots) + " wide and " +
                    std::to_string(kMaxNormalMapSide) + " high",
                where);
  ImageFileInfo info;
  const Image image = load_image(path, &info);
  const bool srgb = encoding == ColorEncoding::srgb || (encoding == ColorEncoding::automatic && !info.is_float);
  const uint32_t row = image.height / 2;
  LoadedColormap out;
  out.encoding = srgb ? "srgb" : "linear";
  for (uint32_t x = 0; x < image.width; ++x) {
    std::array<double, 3> c;
    for (uint32_t k = 0; k < 3; ++k) {
      const double v = image.at(x, row, image.channels >= 3 ? k : 0);
      if (!std::isfinite(v))
        throw Error(ExitCode::invalid_input, "non-finite value in the gradient",
                    where + ", texel (" + std::to_string(x) + ", " + std::to_string(row) + ")");
      c[k] = srgb ? srgb_to_linear(v) : v;
    }
    out.curve.knots.push_back((x + 0.5) / image.width);
    out.curve.colors.push_back(c);
  }
  out.domain_min = 0.0;
  out.domain_max = 1.0;
  out.record = file_record(path);
  out.record["width"] = image.width;
  out.record["height"] = image.height;
  out.record["channels"] = info.file_channels;
  out.record["pixel_format"] = info.pixel_format;
  out.record["row"] = row;
  out.record["encoding"] = out.encoding;
  return out;
}

LoadedColormap load_stops(const std::filesystem::path& path, ColorEncoding encoding) {
  const std::vector<uint8_t> bytes = read_file_bytes(path);
  LoadedColormap out = parse_colormap_stops(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                                            path.string(), encoding);
  out.record = file_record(path);
  out.record["stops"] = out.curve.knots.size();
  out.record["encoding"] = out.encoding;
  return out;
}

}  // namespace

ColorEncoding parse_color_encoding(const std::string& name) {
  if (name == "auto") return ColorEncoding::automatic;
  if (name == "srgb") return ColorEncoding::srgb;
  if (name == "linear") return ColorEncoding::linear;
  throw Error(ExitCode::bad_command_line, "unknown --encoding '" + name + "' (use auto, srgb or linear)");
}

LoadedColormap parse_colormap_stops(std::string_view text, const std::string& where, ColorEncoding encoding) {
  const nlohmann::json doc = parse_json_strict(text, where);
  LoadedColormap out;
  try {
    JsonObjectReader root(doc, "");
    std::string encoding_name = "srgb";
    if (const auto* e = root.optional("encoding")) encoding_name = json_choice(*e, "encoding", {"srgb", "linear"});
    // --encoding overrides the file's own statement only when given explicitly.
    if (encoding != ColorEncoding::automatic) encoding_name = encoding == ColorEncoding::srgb ? "srgb" : "linear";
    const bool srgb = encoding_name == "srgb";
    const nlohmann::json& stops = root.required("stops");
    if (!stops.is_array() || stops.size() < 2)
      throw Error(ExitCode::invalid_input, "'stops' must be an array of at least two stops", "stops");
    if (stops.size() > kMaxColormapStops)
      throw Error(ExitCode::invalid_input,
                  std::to_string(stops.size()) + " stops; at most " + std::to_string(kMaxColormapStops) +
                      " (baking costs time in proportion to them: use a gradient image for finer maps)",
                  "stops");
    for (size_t k = 0; k < stops.size(); ++k) {
      const std::string at = json_index_path("stops", k);
      JsonObjectReader stop(stops[k], at);
      const double x = json_number(stop.required("at"), stop.child("at"), -1e30, 1e30);
      const Vec3 color = json_rgb(stop.required("color"), stop.child("color"), 0.0, srgb ? 1.0 : kMaxLinearColor);
      stop.reject_unknown_keys();
      out.curve.knots.push_back(x);
      out.curve.colors.push_back(
          srgb ? std::array<double, 3>{srgb_to_linear(color.x()), srgb_to_linear(color.y()), srgb_to_linear(color.z())}
               : std::array<double, 3>{color.x(), color.y(), color.z()});
    }
    root.reject_unknown_keys();
    if (const std::string problem = colormap_curve_problem(out.curve); !problem.empty())
      throw Error(ExitCode::invalid_input, "bad stops: " + problem, "stops");
    out.domain_min = out.curve.knots.front();
    out.domain_max = out.curve.knots.back();
    if (!(out.domain_max > out.domain_min))
      throw Error(ExitCode::invalid_input, "the first and last stops must be at different positions", "stops");
    out.encoding = encoding_name;
  } catch (const Error& e) {
    throw Error(e.code(), e.what(), where + (e.where().empty() ? "" : ": " + e.where()));
  }
  return out;
}

LoadedColormap load_colormap_source(const std::filesystem::path& path, ColorEncoding encoding) {
  if (!std::filesystem::exists(path)) throw Error(ExitCode::io_failure, "file not found", path.string());
  return is_json_path(path) ? load_stops(path, encoding) : load_gradient_image(path, encoding);
}

}  // namespace mbk
