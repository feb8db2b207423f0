// Loading normal maps: decoding, the +Y/-Y convention, two-channel reconstruction, the invalid-texel
// policy, size limits, and the input record every asset keeps (conventions in normal_map.h).
#include "libbake/image/normal_map.h"

#include <xxhash.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "formats/container_layout.h"
#include "formats/error.h"
#include "libbake/core/parallel.h"
#include "libbake/core/warnings.h"
#include "libbake/image/convention_detection.h"
#include "libbake/image/image_io.h"

namespace mbk {
namespace {

enum class TexelFault { none, non_finite, zero_length, below_horizon };

const char* fault_name(TexelFault f) {
  switch (f) {
    case TexelFault::non_finite:
      return "NaN or Inf";
    case TexelFault::zero_length:
      return "zero length";
    case TexelFault::below_horizon:
      return "z < 0";
    case TexelFault::none:
      break;
  }
  return "valid";
}

struct Decoding {
  bool unsigned_codes;       // 2v - 1, else the value itself
  uint32_t channels;         // channels used: 2 (x, y) or 3
  double horizon_tolerance;  // how far below 0 a decoded z may be and still be the rounded horizon
};

// Decodes one texel into a unit vector, or reports why it is invalid (repairing it when asked).
TexelFault decode_texel(const float* v, const Decoding& d, bool repair, Vec3f& out) {
  double x = v[0], y = v[1], z = 0.0;
  if (d.unsigned_codes) x = 2.0 * x - 1.0, y = 2.0 * y - 1.0;
  if (d.channels == 2) {
    z = std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
  } else {
    z = d.unsigned_codes ? 2.0 * double(v[2]) - 1.0 : double(v[2]);
  }
  TexelFault fault = TexelFault::none;
  if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
    fault = TexelFault::non_finite;
  } else if (z < 0.0) {
    if (z >= -d.horizon_tolerance)
      z = 0.0;  // the horizon, rounded down by the integer encoding
    else
      fault = TexelFault::below_horizon;
  }
  if (fault == TexelFault::none && x * x + y * y + z * z == 0.0) fault = TexelFault::zero_length;
  if (fault != TexelFault::none) {
    if (!repair) return fault;
    if (fault == TexelFault::below_horizon) z = 0.0;
    if (fault == TexelFault::non_finite || x * x + y * y + z * z == 0.0) x = 0.0, y = 0.0, z = 1.0;
  }
  const double len = std::sqrt(x * x + y * y + z * z);
  out = Vec3f(float(x / len), float(y / len), float(z / len));
  return fault;
}

[[noreturn]] void refuse_one_channel(const std::string& where) {
  throw Error(ExitCode::invalid_input,
              "one-channel image: this looks like a height map, not a normal map (convert it to normals first)", where);
}

struct RowFaults {
  uint64_t count = 0;
  uint32_t first_x = 0;
  TexelFault first = TexelFault::none;
};

std::string fixed3(double v, bool sign) {
  char text[32];
  std::snprintf(text, sizeof text, sign ? "%+.3f" : "%.3f", v);
  return text;
}

// Decides the convention of `map` (decoded as +Y), records how, warns when auto cannot decide or a requested
// convention contradicts a confident statistic, and flips y when the map is -Y.
void resolve_convention(NormalMap& map, const ConventionRequest& requested, InputRecord& record) {
  const ConventionEvidence evidence = measure_convention(map);
  const std::optional<YConvention> verdict = evidence.verdict();
  const YConvention used = requested ? *requested : verdict.value_or(YConvention::plus_y);
  record.convention = convention_name(used);
  record.convention_requested = convention_request_name(requested);
  record.convention_evidence = evidence.to_json();
  record.convention_evidence["verdict"] = verdict ? convention_name(*verdict) : "undecidable";
  const std::string numbers = "curl statistic " + fixed3(evidence.statistic, true) + ", confidence " +
                              fixed3(std::abs(evidence.statistic), false);
  const std::string needed = fixed3(evidence.required_confidence(), false);
  std::string decision = "detected";
  if (!requested && !verdict) {
    decision = "undecidable, read as +Y";
    warn("cannot tell the normal map's green-channel convention (" + numbers + ", " + needed +
             " needed): read as +Y; name it (--convention +Y|-Y, or \"convention\" in a scene or graph file) to "
             "silence this",
         record.path);
  } else if (requested && verdict && *verdict != *requested) {
    decision = "as requested, against the statistic";
    warn("the normal map is read as " + convention_name(*requested) + " as requested, but its slopes say " +
             convention_name(*verdict) + " (" + numbers + ", " + needed + " needed): check its convention",
         record.path);
  } else if (requested) {
    decision = "as requested";
  }
  record.convention_evidence["decision"] = decision;
  // One serial pass: a parallel loop of one texel per iteration would spend more on scheduling than on the work.
  if (used == YConvention::minus_y)
    for (Vec3f& n : map.texels) n.y() = -n.y();
}

}  // namespace

std::string convention_name(YConvention c) { return c == YConvention::plus_y ? "+Y" : "-Y"; }

YConvention parse_convention(const std::string& name) {
  std::string n;
  for (char ch : name) n += char(std::tolower(static_cast<unsigned char>(ch)));
  if (n == "+y" || n == "opengl") return YConvention::plus_y;
  if (n == "-y" || n == "directx") return YConvention::minus_y;
  throw Error(ExitCode::bad_command_line, "unknown normal-map convention '" + name + "' (use +Y/opengl or -Y/directx)");
}

std::string convention_request_name(const ConventionRequest& c) { return c ? convention_name(*c) : "auto"; }

ConventionRequest parse_convention_request(const std::string& name) {
  std::string n;
  for (char ch : name) n += char(std::tolower(static_cast<unsigned char>(ch)));
  if (n == "auto") return std::nullopt;
  try {
    return parse_convention(name);
  } catch (const Error&) {
    throw Error(ExitCode::bad_command_line,
                "unknown normal-map convention '" + name + "' (use auto, +Y/opengl or -Y/directx)");
  }
}

nlohmann::json InputRecord::to_json() const {
  return {{"path", path},
          {"content_hash", content_hash},
          {"bytes", bytes},
          {"width", width},
          {"height", height},
          {"channels", channels},
          {"pixel_format", pixel_format},
          {"convention", convention},
          {"convention_requested", convention_requested},
          {"convention_evidence", convention_evidence},
          {"invalid_policy", invalid_policy},
          {"repaired_texels", repaired_texels}};
}

std::string file_content_hash(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ExitCode::io_failure, "cannot open file for reading", path.string());
  XXH3_state_t* state = XXH3_createState();
  if (!state) throw std::bad_alloc();
  XXH3_64bits_reset(state);
  std::vector<char> buffer(1 << 20);
  while (in) {
    in.read(buffer.data(), std::streamsize(buffer.size()));
    XXH3_64bits_update(state, buffer.data(), size_t(in.gcount()));
  }
  const bool failed = in.bad();
  const uint64_t digest = XXH3_64bits_digest(state);
  XXH3_freeState(state);
  if (failed) throw Error(ExitCode::io_failure, "read error", path.string());
  return "xxh3:" + checksum_hex(digest);
}

nlohmann::json normal_map_conventions() {
  return {{"tangent_space", "x=+u, y=+v, z=out"},
          {"normal_convention", "+Y"},
          {"uv", "u right, v up; texel (x, row) centre at ((x + 0.5) / W, 1 - (row + 0.5) / H), row 0 at the top"}};
}

LoadedNormalMap decode_normal_map(const Image& image, const ImageFileInfo& info, const NormalMapLoadOptions& options,
                                  const std::string& where) {
  if (image.channels < 2) refuse_one_channel(where);
  if (image.pixels.size() != size_t(image.width) * image.height * image.channels)
    throw Error(ExitCode::runtime_failure, "decoded pixel buffer does not match its size", where);
  Decoding d;
  d.unsigned_codes = !info.is_float && !info.is_signed;
  d.channels = std::min<uint32_t>(image.channels, 3);
  d.horizon_tolerance = d.unsigned_codes ? 1.0 / (std::ldexp(1.0, info.integer_bits) - 1.0) * (1.0 + 1e-6) : 0.0;
  const bool repair = options.invalid == InvalidTexelPolicy::repair;

  LoadedNormalMap out;
  NormalMap& map = out.map;
  map.width = image.width;
  map.height = image.height;
  map.texels.assign(size_t(map.width) * map.height, Vec3f(0, 0, 1));
  std::vector<RowFaults> faults(map.height);
  parallel_for(0, map.height, [&](int64_t row) {
    RowFaults& f = faults[row];
    for (uint32_t x = 0; x < map.width; ++x) {
      const float* v = &image.pixels[(size_t(row) * map.width + x) * image.channels];
      const TexelFault fault = decode_texel(v, d, repair, map.at(x, uint32_t(row)));
      if (fault == TexelFault::none) continue;
      if (f.count++ == 0) f.first_x = x, f.first = fault;
    }
  });
  uint64_t invalid = 0;
  for (const RowFaults& f : faults) invalid += f.count;
  if (invalid && !repair) {
    uint32_t row = 0;
    while (faults[row].count == 0) ++row;
    throw Error(ExitCode::invalid_input,
                std::to_string(invalid) + " invalid texel" + (invalid == 1 ? "" : "s") +
                    " (NaN/Inf, zero length or z < 0); the first is at (x, row) = (" +
                    std::to_string(faults[row].first_x) + ", " + std::to_string(row) +
                    "): " + fault_name(faults[row].first) + "; repair them with " + options.repair_hint,
                where);
  }

  InputRecord& r = out.record;
  r.path = where;
  r.width = map.width;
  r.height = map.height;
  r.channels = info.file_channels;
  r.pixel_format = info.pixel_format;
  resolve_convention(map, options.convention, r);
  r.invalid_policy = repair ? "repair" : "error";
  r.repaired_texels = invalid;
  return out;
}

LoadedNormalMap load_normal_map(const std::filesystem::path& path, const NormalMapLoadOptions& options) {
  const std::string where = path.string();
  const ImageHeader header = read_image_header_within(path, kMaxNormalMapSide, "normal map");
  if (header.info.file_channels == 1) refuse_one_channel(where);

  ImageFileInfo info;
  const Image image = load_image(path, &info);
  LoadedNormalMap out = decode_normal_map(image, info, options, where);
  out.record.content_hash = file_content_hash(path);
  out.record.bytes = std::filesystem::file_size(path);
  return out;
}

}  // namespace mbk
