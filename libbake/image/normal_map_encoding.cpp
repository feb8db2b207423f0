// NormalMap -> image encodings (see normal_map_encoding.h).
#include "libbake/image/normal_map_encoding.h"

#include "formats/error.h"
#include "formats/file_extension.h"

namespace mbk {

NormalEncoding encoding_for_path(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".exr") return NormalEncoding::float_vector;
  for (const char* e : {".png", ".tif", ".tiff", ".tga", ".jpg", ".jpeg"})
    if (ext == e) return NormalEncoding::unsigned_codes;
  throw Error(ExitCode::bad_command_line,
              "cannot store a normal map in a '" + ext + "' file (use .png or .exr; .tif, .tga, .jpg also work)",
              path.string());
}

Image encode_normal_map(const NormalMap& map, NormalEncoding encoding, YConvention convention) {
  Image image;
  image.width = map.width;
  image.height = map.height;
  image.channels = 3;
  image.pixels.resize(map.texels.size() * 3);
  const float y_sign = convention == YConvention::minus_y ? -1.0f : 1.0f;
  for (size_t i = 0; i < map.texels.size(); ++i) {
    const Vec3f n(map.texels[i].x(), y_sign * map.texels[i].y(), map.texels[i].z());
    for (int c = 0; c < 3; ++c)
      image.pixels[3 * i + c] = encoding == NormalEncoding::unsigned_codes ? 0.5f * (n[c] + 1.0f) : n[c];
  }
  return image;
}

void save_normal_map(const std::filesystem::path& path, const NormalMap& map, YConvention convention,
                     const std::filesystem::path& format_path) {
  const NormalEncoding encoding = encoding_for_path(format_path.empty() ? path : format_path);
  ImageSaveOptions options;
  options.png_bits = 16;
  options.float_bits = 32;
  save_image(path, encode_normal_map(map, encoding, convention), options, format_path);
}

}  // namespace mbk
