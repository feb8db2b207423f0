// Every image microbake reads or writes goes through OpenImageIO, behind these functions: in the module
// libmicrobake_image_io.so that image_io.cpp loads on the first call (libbake/image/image_io_module.h), so that
// commands that touch no image never load OpenImageIO. Pixels in memory are float, interleaved, row-major with
// row 0 at the top.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace mbk {

struct Image {
  uint32_t width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // width * height * channels
  float& at(uint32_t x, uint32_t row, uint32_t c) { return pixels[(size_t(row) * width + x) * channels + c]; }
  float at(uint32_t x, uint32_t row, uint32_t c) const { return pixels[(size_t(row) * width + x) * channels + c]; }
};

struct ImageFileInfo {
  std::string pixel_format;  // OpenImageIO's name of the stored type: uint8, uint16, half, float...
  bool is_float = false;     // true when the stored type is a float type (values taken as they are)
  bool is_signed = false;    // signed integer types (int8, int16...), which load_image maps to [-1, 1]
  int integer_bits = 0;      // bits per stored integer sample (8, 16, 32...), 0 for float types
  uint32_t file_channels = 0;
};

// Reads any image OpenImageIO can (subimage 0, MIP level 0); unsigned integer types become [0, 1] floats,
// signed integer types [-1, 1] (OpenImageIO's normalisation), float types are kept. Colour channels are
// never multiplied by alpha (OpenImageIO's "oiio:UnassociatedAlpha"), and no colour transform is applied.
// Throws Error: io_failure when the file is missing or unreadable, invalid_input when it is not an image.
Image load_image(const std::filesystem::path& path, ImageFileInfo* info = nullptr);

// The size and stored type of an image without reading its pixels, so that callers can enforce size
// limits before allocating. Same errors as load_image.
struct ImageHeader {
  uint32_t width = 0, height = 0;
  ImageFileInfo info;
};
ImageHeader read_image_header(const std::filesystem::path& path);
// read_image_header, then Error(invalid_input) "<what> is WxH texels; each side may be at most <max_side>" when a
// side is larger, so that callers enforce their size limit before allocating.
ImageHeader read_image_header_within(const std::filesystem::path& path, uint32_t max_side, const std::string& what);

// How save_image stores pixels. PNG: 8 or 16 bits (values clamped to [0, 1], rounded to the nearest code,
// NaN stored as 0); EXR: half or float (linear, unclamped). Other extensions OpenImageIO supports (TIFF,
// TGA, JPEG...) get the same integer codes as PNG, reduced by OpenImageIO to what the format can hold
// (8 bits for TGA and JPEG). `png_bits` is ignored for EXR ("half" vs "float" chosen by `float_bits`).
// Every channel is stored as given (a fourth or second channel is never treated as alpha to divide by).
struct ImageSaveOptions {
  int png_bits = 16;    // 8 or 16
  int float_bits = 32;  // 16 or 32 for EXR
  bool exr_zip = true;  // EXR compression: zip, or none (save_normal_map: zip saves ~4% on 32-bit float normals)
};

// Starts loading the image library (~0.4 s: OpenImageIO and its dependencies) on a background thread and returns at
// once, for a command that writes an image after a long computation, which the load then overlaps; the next image
// call waits for it to finish. A load that fails is reported by that call, as without this.
void start_loading_image_io();

// Writes to `path` (callers make it atomic with cli's OutputOption / formats' AtomicFile), reporting a full disk or
// a file-size limit as io_failure: the file is complete when save_image returns, never silently short.
// The format comes from the extension of `format_path` when given (for temporary files), else of `path`.
// Throws Error: io_failure when it cannot write, bad_command_line for an unknown extension.
void save_image(const std::filesystem::path& path, const Image& image, const ImageSaveOptions& options = {},
                const std::filesystem::path& format_path = {});

}  // namespace mbk
