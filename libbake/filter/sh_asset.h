// The `sh` asset kind (formats/kind_sh.cpp, formats/SPEC.md "Kind 4: sh"): an SH NDF pyramid
// (sh_pyramid.h, [Han07] Sec. 7.4) with its finest level stored as the unit normals.
#pragma once

#include <string>

#include "formats/asset_writer.h"
#include "libbake/filter/sh_pyramid.h"
#include "libbake/filter/sh_window.h"

namespace mbk {

enum class ShPrecision { f16, f32 };
std::string precision_name(ShPrecision p);
ShPrecision parse_precision(const std::string& name);  // "f16" / "f32", else Error(bad_command_line)

inline constexpr int kShDefaultOrder = 8;

struct ShBakeOptions {
  int order = kShDefaultOrder;
  ShPrecision precision = ShPrecision::f16;
  ShWindow window = ShWindow::none;
};

// Bakes the asset: sections `normals` f32 [H, W, 3] (level 0: g_lm = Y_lm(n)); `level_k` for k = 1..K-1, f16 or
// f32 [h_k, w_k, (order+1)^2]; `window` f32 [order + 1]. Metadata parameters {width, height, levels, order,
// coefficients, precision, window}; statistics per level: mean length of the mean normal and the largest
// rounding error of the stored coefficients. The pyramid's rows are converted to the stored precision as they
// are computed (stream_sh_pyramid), in parallel, each straight into its section's buffer, which the writer
// then takes over: no level is held in f32 beside its f16 copy, and no buffer is copied (the input's normals
// become section `normals`: pass the map by std::move when it is not needed afterwards).
AssetWriter bake_sh_asset(LoadedNormalMap input, const ShBakeOptions& options, Progress& progress);

}  // namespace mbk
