// Writing normal maps back to image files: the inverse of load_normal_map's decoding (normal_map.h), so
// that generated maps load back as the same vectors (up to the file's precision).
// - Integer files (PNG, TIFF, TGA, JPEG) store (n + 1) / 2 per channel; save_normal_map writes 16-bit
//   where the format allows (PNG, TIFF).
// - EXR stores n itself as 32-bit float, uncompressed: zip shrinks the noise-like mantissas of unit normals by ~4%
//   (50.4 -> 48.2 MB at 2048 x 2048) at ~25 MB/s per core, a second for a 4-megapixel map.
// - A -Y target flips y, so that loading the file with the same convention gives the map back.
#pragma once

#include <filesystem>

#include "libbake/image/image_io.h"
#include "libbake/image/normal_map.h"

namespace mbk {

enum class NormalEncoding { unsigned_codes, float_vector };

// The encoding a file extension calls for: .exr -> float_vector; .png, .tif, .tiff, .tga, .jpg, .jpeg ->
// unsigned_codes; anything else -> Error(bad_command_line) (e.g. .hdr cannot hold negative components).
NormalEncoding encoding_for_path(const std::filesystem::path& path);

// Three channels, row 0 at the top, in the encoding given.
Image encode_normal_map(const NormalMap& map, NormalEncoding encoding, YConvention convention = YConvention::plus_y);

// Encodes for the extension of `format_path` (or `path`) and writes with save_image: PNG/TIFF 16-bit,
// EXR 32-bit float. Same errors as save_image and encoding_for_path.
void save_normal_map(const std::filesystem::path& path, const NormalMap& map,
                     YConvention convention = YConvention::plus_y, const std::filesystem::path& format_path = {});

// save_normal_map for unit normals held as a 3-channel image (x, y, z per pixel, +Y): an EXR for +Y is written
// from `normals` itself, without a copy.
void save_normal_image(const std::filesystem::path& path, const Image& normals,
                       YConvention convention = YConvention::plus_y, const std::filesystem::path& format_path = {});

}  // namespace mbk
