// Reading a colour map C for `microbake colormap` ([Heitz13] Sec. 4: C maps grayscale driver values to colours):
// from a 1-D gradient image or from JSON colour stops, into the piecewise-linear ColormapCurve of
// formats/colormap_layout.h, in LINEAR RGB (filtering averages light, so sRGB-encoded inputs are decoded first).
//
// Gradient images: row 0 when the image has one row, else the middle row (row floor(H / 2), the row whose
// centre is at or just below the image centre). Texel x becomes a knot at (x + 0.5) / W with its colour, so the
// driver domain is [0, 1] (value 0 at the left edge, 1 at the right edge) and C clamps to the end texels
// beyond the outer texel centres, as a GPU's clamped linear lookup does. One channel is grey (r = g = b); two
// are grey + alpha (alpha ignored); more are RGB(A). Encoding: `automatic` decodes integer images (PNG, TGA,
// JPEG...) as sRGB and takes float images (EXR, float TIFF) as linear.
//
// JSON colour stops (a file ending in .json): {"encoding": "srgb" | "linear", "stops": [{"at": x, "color":
// [r, g, b] or grey}, ...]}: at least two stops, positions non-decreasing, the first below the last, at most
// two stops at one position (a hard edge: C jumps there). "encoding" defaults to "srgb" (colours in [0, 1]
// as a colour picker shows them); "linear" colours may be any value in [0, 65504]. The driver domain is
// [first stop, last stop]. Unknown keys are errors naming their path. At most kMaxColormapStops stops (checked
// before any is read).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "formats/colormap_layout.h"

namespace mbk {

inline constexpr size_t kMaxColormapStops = 1024;

enum class ColorEncoding { automatic, srgb, linear };
// "auto", "srgb", "linear"; Error(bad_command_line) otherwise.
ColorEncoding parse_color_encoding(const std::string& name);

struct LoadedColormap {
  ColormapCurve curve;                        // linear RGB
  double domain_min = 0.0, domain_max = 1.0;  // the driver range the table's mean axis spans
  std::string encoding;                       // what was applied: "srgb" or "linear"
  nlohmann::json record;                      // the input record for the asset's metadata "inputs"
};

// Throws Error: io_failure (missing file), invalid_input (not an image / malformed JSON, bad stops, non-finite
// pixels), with the JSON path or pixel in `where`.
LoadedColormap load_colormap_source(const std::filesystem::path& path, ColorEncoding encoding);

// The JSON colour stops of `text` (the file's bytes; `where` names it in errors), as load_colormap_source reads a
// .json file, without the file record. Same errors.
LoadedColormap parse_colormap_stops(std::string_view text, const std::string& where, ColorEncoding encoding);

}  // namespace mbk
