// Pixels a silhouette crosses, for edge-adaptive sampling (`render --edge-spp`). A filtered sample shades the
// footprint of the surface its ray hits: it filters texture, not coverage, so a pixel that two shapes (or a shape
// and the background) share is as aliased at one filtered sample as at one brute-force ray (the glints report's
// bent quad: one silhouette pixel made its 8 x 8-block error 5x the reference's noise floor). The renderer gives
// such pixels more samples. Which pixels: the primary rays through the image's (W + 1) x (H + 1) pixel corners are
// cast once; a pixel whose four corners do not all see the same shape (or all the background) is an edge pixel.
// A feature thinner than a pixel that passes between all four corners is missed, as any point sampling misses it;
// corners are told apart by shape only, so where a shape hides part of itself (a bent quad folded past 180
// degrees) its own silhouette is not an edge.
#pragma once

#include <cstdint>
#include <vector>

#include "libbake/eval/camera_rays.h"
#include "libbake/scene/scene.h"

namespace mbk {

// W x H flags, row-major: 1 where the pixel's corners see different shapes (or some the background).
std::vector<uint8_t> silhouette_pixels(const Scene& scene, const PinholeCamera& camera);

}  // namespace mbk
