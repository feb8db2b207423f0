// Linear EXR and tone-mapped PNG output of renders (see render_output.h).
#include "libbake/eval/render_output.h"

#include <algorithm>
#include <cmath>

#include "formats/error.h"
#include "formats/file_extension.h"

namespace mbk {
double srgb_oetf(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; }

Image tone_map_for_display(const Image& linear) {
  Image out = linear;
  for (float& v : out.pixels)
    v = float(srgb_oetf(std::clamp(double(v), 0.0, 1.0)));  // NaN would pass clamp: none are produced
  return out;
}

bool is_render_extension(const std::filesystem::path& path) {
  const std::string e = lower_extension(path);
  return e == ".exr" || e == ".png";
}

void save_render(const std::filesystem::path& path, const Image& linear, const std::filesystem::path& format_path) {
  const std::string e = lower_extension(format_path);
  if (e == ".exr") {
    save_image(path, linear, ImageSaveOptions{16, 32}, format_path);
  } else if (e == ".png") {
    save_image(path, tone_map_for_display(linear), ImageSaveOptions{8, 32}, format_path);
  } else {
    throw Error(ExitCode::bad_command_line, "render output must end in .exr (linear) or .png (tone-mapped)",
                format_path.string());
  }
}

}  // namespace mbk
