// The table of asset kinds (see asset_kind.h).
#include "formats/asset_kind.h"

#include "formats/lut_layout.h"

namespace mbk {

std::span<const AssetKind> asset_kinds() {
  static const std::vector<AssetKind> kKinds = {mip_kind(),
                                                lut_kind(),
                                                rmq_kind(),
                                                sh_kind(),
                                                vmf_kind(),
                                                crease_kind(),
                                                colormap_kind(),
                                                moments_kind(),
                                                graph_kind(),
                                                histogram_kind(),
                                                neural_histogram_kind()};
  return kKinds;
}

const AssetKind* find_kind(uint32_t id) {
  for (const auto& k : asset_kinds())
    if (k.id == id) return &k;
  return nullptr;
}

const AssetKind* find_kind(std::string_view name) {
  for (const auto& k : asset_kinds())
    if (k.name == name) return &k;
  return nullptr;
}

std::string_view retired_kind_note(uint32_t id) {
  if (id == kRetiredLutKindId)
    return " (uniform lut tables of microbake 0.1, retired because they misread repeated values: rebake with "
           "'microbake lut')";
  return "";
}

}  // namespace mbk
