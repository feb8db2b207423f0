// Reading the standardization tables of a `lut` asset (see standardization_lut.h).
#include "formats/standardization_lut.h"

#include "formats/lut_layout.h"

namespace mbk {

StandardizationChannelTables::StandardizationChannelTables(std::vector<float> x, std::vector<float> z)
    : forward_(x, z), inverse_(z, x) {}

StandardizationLut read_standardization_lut(const Asset& asset) {
  if (asset.kind().id != kLutKindId)
    throw Error(ExitCode::invalid_input, "expected a lut asset, found kind '" + std::string(asset.kind().name) + "'",
                asset.where());
  const std::optional<uint32_t> size = lut_size_parameter(asset.metadata());
  if (!size) throw Error(ExitCode::invalid_input, "lut parameters.size must be an integer in 2..65536", asset.where());
  StandardizationLut lut;
  lut.size = *size;
  for (uint32_t c = 0; c < kLutChannels; ++c) {
    const std::string name(kLutKnotSections[c]);
    const SectionInfo& s = asset.section(name);
    if (!lut_knot_shape_ok(s.shape, lut.size))
      throw Error(ExitCode::invalid_input,
                  "lut section '" + name + "' should have shape [M, 2] with 1 <= M <= 3 x size", asset.where());
    const std::vector<float> rows = asset.read<float>(name);
    std::vector<float> x(s.shape[0]), z(s.shape[0]);
    for (size_t i = 0; i < x.size(); ++i) x[i] = rows[2 * i], z[i] = rows[2 * i + 1];
    lut.channels[c] = StandardizationChannelTables(std::move(x), std::move(z));
  }
  return lut;
}

}  // namespace mbk
