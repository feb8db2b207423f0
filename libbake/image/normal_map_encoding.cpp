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

namespace {

// (n + 1) / 2 for integer files, y flipped for -Y, on 3-channel pixels in place.
void encode_in_place(Image& image, NormalEncoding encoding, YConvention convention) {
  const float y_sign = convention == YConvention::minus_y ? -1.0f : 1.0f;
  for (size_t i = 0; i < image.pixels.size(); i += 3) {
    image.pixels[i + 1] *= y_sign;
    if (encoding == NormalEncoding::unsigned_codes)
      for (int c = 0; c < 3; ++c) image.pixels[i + c] = 0.5f * (image.pixels[i + c] + 1.0f);
  }
}

ImageSaveOptions normal_map_save_options() {
  ImageSaveOptions options;
  options.png_bits = 16;
  options.float_bits = 32;
  options.exr_zip = false;
  return options;
}

}  // namespace

Image encode_normal_map(const NormalMap& map, NormalEncoding encoding, YConvention convention) {
  Image image;
  image.width = map.width;
  image.height = map.height;
  image.channels = 3;
  image.pixels.resize(map.texels.size() * 3);
  for (size_t i = 0; i < map.texels.size(); ++i)
    for (int c = 0; c < 3; ++c) image.pixels[3 * i + c] = map.texels[i][c];
  encode_in_place(image, encoding, convention);
  return image;
}

void save_normal_map(const std::filesystem::path& path, const NormalMap& map, YConvention convention,
                     const std::filesystem::path& format_path) {
  const NormalEncoding encoding = encoding_for_path(format_path.empty() ? path : format_path);
  save_image(path, encode_normal_map(map, encoding, convention), normal_map_save_options(), format_path);
}

void save_normal_image(const std::filesystem::path& path, const Image& normals, YConvention convention,
                       const std::filesystem::path& format_path) {
  if (normals.channels != 3)
    throw Error(ExitCode::runtime_failure, "internal: a normal image has 3 channels", path.string());
  const NormalEncoding encoding = encoding_for_path(format_path.empty() ? path : format_path);
  if (encoding == NormalEncoding::float_vector && convention == YConvention::plus_y)
    return save_image(path, normals, normal_map_save_options(), format_path);
  Image encoded = normals;
  encode_in_place(encoded, encoding, convention);
  save_image(path, encoded, normal_map_save_options(), format_path);
}

}  // namespace mbk
