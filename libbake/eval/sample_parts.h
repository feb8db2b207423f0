// Long footprints shaded in parts. A filtered sample shades its whole footprint at one point: one position, one
// view and light direction, the footprint's NDF. Where the footprint is long (a surface seen at a grazing angle:
// hundreds of texels along the view, a few across), what the shading depends on besides the normal - the view
// and light directions, the point lights' distances - changes along it, and the NDF of the whole footprint no
// longer says which of its normals sits where: the bevel at its near end and the one at its far end are lit and
// seen differently (measured on examples/scenes/filtering_plane.json with scifi_panel_bevels, sh16 at 4 samples per
// pixel: far-field RMSE 0.136; the footprints' probes were not the cause - 64 probes 0.136, probes placed through
// the pixel's exact perspective within 0.01 per row - while shading 4 parts of each long footprint gives 0.101).
//
// So a sample whose world-space footprint, the ellipse of its ray differentials' dp/dx, dp/dy (uv_footprint.h), is
// more than kPartAnisotropy times longer than wide is shaded in
//     P = min(max_parts, ceil(s1 / (kPartAnisotropy s2)))
// parts along its major axis: part k is the ray through the sample's film point offset by ((k + 1/2) / P - 1/2) e
// (e the unit pixel-step direction the footprint's major axis comes from), traced to its own hit, with ray
// differentials shrunk along e by 1 / P (so its footprint is its 1 / P of the sample's), and the parts' radiances
// are averaged: the parts tile the sample's cell, so together they still filter exactly the pixel. A circle, a
// magnified footprint or max_parts = 1 leaves the sample whole; a part whose ray misses the surface (the horizon
// inside the cell) sees what the ray sees.
#pragma once

#include "libbake/eval/camera_rays.h"

namespace mbk {

inline constexpr double kPartAnisotropy = 8.0;
inline constexpr int kMaxSampleParts = 16;

struct SampleParts {
  int count = 1;
  Vec2 axis = Vec2(0.0, 1.0);  // e: unit, in the sample's pixel steps (the units of its ray differentials)
};

// The parts of a sample whose footprint has world-space steps dp_dx, dp_dy (max_parts clamped to [1,
// kMaxSampleParts]); non-finite steps (a grazing ray) leave it whole.
SampleParts sample_parts(const Vec3& dp_dx, const Vec3& dp_dy, int max_parts);

// Part k's film offset from the sample's film point, in pixel steps, and its ray differentials (the sample's
// shrunk along the axis by 1 / count).
Vec2 part_offset(const SampleParts& parts, int k);
void shrink_to_part(const SampleParts& parts, Vec3& ddx, Vec3& ddy);

}  // namespace mbk
