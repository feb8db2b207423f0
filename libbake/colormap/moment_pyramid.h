// The moment pyramid of a tabulated driver f ([Heitz13] Sec. 4.2): the MIP pyramid of (f, f^2), so that the mean
// and variance of f over a footprint come from one trilinear lookup of both moments, sigma^2 = E[f^2] - E[f]^2
// (the variance after interpolating the moments, as the paper does). Box pyramid, sizes and coverage as every
// microbake pyramid (libbake/image/box_pyramid.h, formats/mip_levels.h); the moments are taken about a shift (the
// driver's mean) so that the difference stays well conditioned in float (formats/moments_layout.h). Asset kind 8,
// `moments` (formats/SPEC.md "Kind 8: moments").
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "formats/asset_writer.h"
#include "libbake/core/eigen.h"
#include "libbake/image/image_io.h"

namespace mbk {

class Asset;

struct MomentPyramid {
  double shift = 0.0;         // s, float-representable
  std::vector<Image> levels;  // 2 channels: E[f - s], E[(f - s)^2]
};

// The driver f: one channel of an image, as loaded (integer images in [0, 1], float images as stored).
struct Driver {
  uint32_t width = 0, height = 0;
  std::vector<double> values;  // row-major, row 0 at the top
  nlohmann::json record;       // the input record for metadata "inputs"
};

// Loads channel `channel` of an image as the driver. Error: io_failure (missing), invalid_input (not an image,
// channel out of range, non-finite values, a side above 16384).
Driver load_driver(const std::filesystem::path& path, uint32_t channel);

// Error(runtime_failure) for an empty driver or a value count that does not match the size.
MomentPyramid build_moment_pyramid(const Driver& driver);

struct FootprintMoments {
  double mean = 0.0, variance = 0.0;
};
// Trilinear lookup of both moments at uv and lod (wrapping, lod clamped; box_pyramid.h), then the variance, clamped
// at 0 (interpolation is a convex combination of texels with E[d^2] >= E[d]^2, so only float rounding can push it
// below). NaN uv or lod give NaN.
FootprintMoments sample_moments(const MomentPyramid& pyramid, const Vec2& uv, double lod);

// The asset (formats/SPEC.md "Kind 8: moments") and reading it back. read_moment_pyramid throws
// Error(invalid_input) when the asset is not a valid moments asset.
AssetWriter moments_asset_writer(const MomentPyramid& pyramid, const Driver& driver);
MomentPyramid read_moment_pyramid(const Asset& asset);

}  // namespace mbk
