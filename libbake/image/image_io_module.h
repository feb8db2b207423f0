// The boundary between libbake and the image I/O module: OpenImageIO and the ~260 shared libraries it needs are
// not linked into microbake but into libmicrobake_image_io.so (imageio/oiio_image_io.cpp), which
// libbake/image/image_io.cpp loads with dlopen the first time an image is read or written. Commands that read no
// image (info, validate, plan) then start like a small program (docs/BENCHMARKS.md, "Start-up"). The module
// exports one C function returning this table; both sides are built from this header in one build.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "libbake/image/image_io.h"

namespace mbk {

// Changes when the table or the types it passes change, so that a module of another build is refused.
inline constexpr uint32_t kImageIoModuleAbi = 2;
inline constexpr const char* kImageIoModuleFile = "libmicrobake_image_io.so";
inline constexpr const char* kImageIoModuleEntry = "microbake_image_io_module";

// The module's implementations of image_io.h (same contracts, same errors).
struct ImageIoModule {
  uint32_t abi;
  ImageHeader (*read_header)(const std::filesystem::path& path);
  Image (*load)(const std::filesystem::path& path, ImageFileInfo* info);
  void (*save)(const std::filesystem::path& path, const Image& image, const ImageSaveOptions& options,
               const std::filesystem::path& format_path);
};

// Loads the module from the first of `folders` that holds one of this build (the ABI number matches). Throws
// Error(io_failure) about `image` (the file that needed it), naming every path tried and why it failed.
const ImageIoModule& load_image_io_module(const std::vector<std::filesystem::path>& folders,
                                          const std::filesystem::path& image);

}  // namespace mbk
