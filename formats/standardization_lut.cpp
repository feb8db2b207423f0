// Reading the standardization tables of a `lut` asset (see standardization_lut.h).
#include "formats/standardization_lut.h"

#include "formats/lut_layout.h"

namespace mbk {

StandardizationLut read_standardization_lut(const Asset& asset) {
  if (asset.kind().id != kLutKindId)
    throw Error(ExitCode::invalid_input, "expected a lut asset, found kind '" + std::string(asset.kind().name) + "'",
                asset.where());
  const SectionInfo& forward = asset.section(std::string(kLutForwardSection));
  const uint64_t size = forward.shape.size() == 2 ? forward.shape[1] : 0;
  auto expect_shape = [&](std::string_view name, uint64_t length) {
    const SectionInfo& s = asset.section(std::string(name));
    if (s.shape != std::vector<uint64_t>{kLutChannels, length})
      throw Error(ExitCode::invalid_input,
                  "lut section '" + std::string(name) + "' should have shape [2, " + std::to_string(length) + "]",
                  asset.where());
  };
  if (size < kLutMinSize || size > kLutMaxSize)
    throw Error(ExitCode::invalid_input, "lut tables must have 2..65536 samples", asset.where());
  expect_shape(kLutForwardSection, size);
  expect_shape(kLutInverseSection, size);
  expect_shape(kLutForwardSlopeSection, size - 1);
  expect_shape(kLutInverseSlopeSection, size - 1);
  expect_shape(kLutDomainsSection, kLutDomainValues);

  const std::vector<float> domains = asset.read<float>(std::string(kLutDomainsSection));
  const std::vector<float> fwd = asset.read<float>(std::string(kLutForwardSection));
  const std::vector<float> fwd_slope = asset.read<float>(std::string(kLutForwardSlopeSection));
  const std::vector<float> inv = asset.read<float>(std::string(kLutInverseSection));
  const std::vector<float> inv_slope = asset.read<float>(std::string(kLutInverseSlopeSection));
  StandardizationLut lut;
  lut.size = uint32_t(size);
  for (uint32_t c = 0; c < kLutChannels; ++c) {
    StandardizationChannelTables& t = lut.channels[c];
    const float* d = &domains[size_t(c) * kLutDomainValues];
    t.x_lo = d[0], t.x_hi = d[1], t.z_lo = d[2], t.z_hi = d[3];
    auto row = [c](const std::vector<float>& all, uint64_t length) {
      return std::vector<float>(all.begin() + ptrdiff_t(c * length), all.begin() + ptrdiff_t((c + 1) * length));
    };
    t.forward = row(fwd, size);
    t.inverse = row(inv, size);
    t.forward_slope = row(fwd_slope, size - 1);
    t.inverse_slope = row(inv_slope, size - 1);
  }
  return lut;
}

}  // namespace mbk
