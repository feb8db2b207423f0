// The `vmf` asset kind (formats/kind_vmf.cpp, formats/SPEC.md "Kind 5: vmf"): vMF mixture MIP maps
// (vmf_pyramid.h, [Han07] Sec. 7.6).
#pragma once

#include "formats/asset_writer.h"
#include "libbake/filter/vmf_pyramid.h"

namespace mbk {

// Sections `level_k` f32 [h_k, w_k, J, 4] (alpha, alpha r) for k = 0..K-1, and with a material image
// `features_k` f32 [h_k, w_k, J, F] (alpha y). Metadata parameters {width, height, levels, lobes, align,
// tolerance, max_iterations, kappa_max, feature_channels}; inputs the normal map and the material image;
// statistics per level: mean EM iterations (all runs: both starts and the guard), converged fraction, the mean
// log-likelihood per finest normal of the stored lobes, empty-lobe fraction, and re-seeds kept by the collapse guard
// per texel.
AssetWriter vmf_asset_writer(const LoadedNormalMap& input, const nlohmann::json* material_record, VmfPyramid pyramid,
                             const VmfBakeOptions& options);

}  // namespace mbk
