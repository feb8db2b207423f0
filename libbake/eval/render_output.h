// Writing rendered images. EXR holds the linear radiance as 32-bit float RGB, unclamped: compare EXRs.
// PNG is for looking at: each channel is clamped to [0, 1] (linear radiance 1 is display white; no
// exposure, no highlight roll-off) and encoded with the sRGB OETF (IEC 61966-2-1):
//     c <= 0.0031308 ? 12.92 c : 1.055 c^(1/2.4) - 0.055,
// stored as 8 bits per channel.
#pragma once

#include <filesystem>

#include "libbake/image/image_io.h"

namespace mbk {

double srgb_oetf(double linear);
// The display-referred image a PNG stores, values in [0, 1].
Image tone_map_for_display(const Image& linear);

// By the extension of `format_path` (.exr or .png, any case); Error(bad_command_line) for others.
void save_render(const std::filesystem::path& path, const Image& linear, const std::filesystem::path& format_path);
// Whether save_render accepts this extension.
bool is_render_extension(const std::filesystem::path& path);

}  // namespace mbk
