// Normal maps in microbake, and the conventions every technique shares.
//
// Conventions (stated once here; functions document only their exceptions):
// - Tangent space: x along +u, y along +v, z out of the surface. Texture coordinates have u to the right and
//   v up; texel (x, row) of a W x H image has its centre at u = (x + 0.5) / W, v = 1 - (row + 0.5) / H, and
//   row 0 is the top row of the image as stored in the file.
// - +Y ("OpenGL"): green grows with tangent y (up in the image). -Y ("DirectX"): green grows downward; loading
//   a -Y map flips y so that every NormalMap in memory is +Y. The default, auto, tells the two apart by the curl
//   of the slope field (convention_detection.h) and reads a map it cannot decide as +Y, with a warning.
// - Encodings: unsigned integer images (PNG 8/16-bit, TGA, JPEG, TIFF) map [0, 1] -> [-1, 1] by 2v - 1;
//   float images (EXR half/float, float TIFF) are taken as the vector itself, and so are the rare signed
//   integer images (already in [-1, 1]). Two-channel maps are (x, y) with z = sqrt(max(0, 1 - x^2 - y^2));
//   extra channels beyond the third (alpha) are ignored and never multiply the colour. One-channel images
//   are refused: they are height maps, not normal maps.
// - Every texel is renormalised to unit length on load. Invalid texels (zero length, NaN/Inf, z < 0) are
//   an error naming their count and the first position, unless the caller asks to repair them:
//   non-finite or zero-length texels become (0, 0, 1) and z < 0 becomes z = 0 (the horizon), renormalised.
//   One exception keeps integer maps honest: an unsigned integer map cannot store z = 0 (2v - 1 is never 0),
//   so the code just below the middle (z = -1/255 in 8 bits, -1/65535 in 16) is the horizon rounded down
//   and becomes z = 0 without counting as invalid; anything lower is invalid.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "libbake/core/eigen.h"
#include "libbake/image/image_io.h"

namespace mbk {

enum class YConvention { plus_y, minus_y };
std::string convention_name(YConvention c);             // "+Y" or "-Y"
YConvention parse_convention(const std::string& name);  // accepts +Y/-Y, opengl/directx; Error(bad_command_line)

// A requested convention: one of the two, or nullopt for auto (detect; +Y when undecidable).
using ConventionRequest = std::optional<YConvention>;
std::string convention_request_name(const ConventionRequest& c);  // "auto", "+Y" or "-Y"
// Accepts auto and what parse_convention accepts, any case; Error(bad_command_line) naming all of them.
ConventionRequest parse_convention_request(const std::string& name);

enum class InvalidTexelPolicy { error, repair };

// Size limits, enforced on load with a clear error: each side at most kMaxNormalMapSide texels.
inline constexpr uint32_t kMaxNormalMapSide = 16384;

struct NormalMap {
  uint32_t width = 0, height = 0;
  std::vector<Vec3f> texels;  // row-major, row 0 at the top

  const Vec3f& at(uint32_t x, uint32_t row) const { return texels[size_t(row) * width + x]; }
  Vec3f& at(uint32_t x, uint32_t row) { return texels[size_t(row) * width + x]; }
};

struct NormalMapLoadOptions {
  ConventionRequest convention;  // auto
  InvalidTexelPolicy invalid = InvalidTexelPolicy::error;
  // How the user asks for repair, named in the error about invalid texels (a scene: its "repair" key).
  std::string repair_hint = "--repair-invalid";
};

// What an asset records about each input (metadata "inputs"): enough to detect that it changed.
struct InputRecord {
  std::string path;          // as given
  std::string content_hash;  // "xxh3:" + 16 hex digits of the file's bytes
  uint64_t bytes = 0;
  uint32_t width = 0, height = 0, channels = 0;
  std::string pixel_format;          // OpenImageIO's name: uint8, uint16, half, float...
  std::string convention;            // the one the map was read as: "+Y" or "-Y"
  std::string convention_requested;  // "auto", "+Y" or "-Y"
  // The curl statistic of the file's green channel and how it was used (ConventionEvidence::to_json() plus
  // "verdict": "+Y", "-Y" or "undecidable", and "decision": "detected", "undecidable, read as +Y", "as requested"
  // or "as requested, against the statistic").
  nlohmann::json convention_evidence = nlohmann::json::object();
  std::string invalid_policy;  // "error" or "repair"
  uint64_t repaired_texels = 0;
  nlohmann::json to_json() const;
};

struct LoadedNormalMap {
  NormalMap map;
  InputRecord record;
};

// Throws Error: io_failure (missing/unreadable file), invalid_input (not an image, one channel, invalid
// texels under the error policy, too large). Raises one warning (libbake/core/warnings.h) when auto cannot decide
// the convention (the map is read as +Y) or when a requested convention contradicts a confident statistic.
LoadedNormalMap load_normal_map(const std::filesystem::path& path, const NormalMapLoadOptions& options);

// The decoding step of load_normal_map, after the image library: `image` (pixels as load_image gives them, stored
// as `info` says) becomes unit texels in +Y, with the same errors and warnings (`where` names the map). The record
// gets everything but the file's content hash and byte count. Any size and any values (NaN/Inf included) are
// refused cleanly or decoded; Error(runtime_failure) when the buffer's length is not width x height x channels.
LoadedNormalMap decode_normal_map(const Image& image, const ImageFileInfo& info, const NormalMapLoadOptions& options,
                                  const std::string& where);

// The content hash recorded for inputs ("xxh3:<16 hex>"). Throws Error(io_failure).
std::string file_content_hash(const std::filesystem::path& path);

// The "conventions" metadata of assets baked from normal maps: tangent space, uv and texel centres, and
// the in-memory +Y convention (each input's own convention is in its InputRecord).
nlohmann::json normal_map_conventions();

}  // namespace mbk
