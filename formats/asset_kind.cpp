// The table of asset kinds (see asset_kind.h).
#include "formats/asset_kind.h"

namespace mbk {

std::span<const AssetKind> asset_kinds() {
  static const std::vector<AssetKind> kKinds = {mip_kind(),    lut_kind(),      rmq_kind(),     sh_kind(),   vmf_kind(),
                                                crease_kind(), colormap_kind(), moments_kind(), graph_kind()};
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

}  // namespace mbk
