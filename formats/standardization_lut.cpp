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
  const nlohmann::json& parameters = asset.metadata().contains("parameters") ? asset.metadata()["parameters"] : nullptr;
  const nlohmann::json size = parameters.is_object() ? parameters.value("size", nlohmann::json()) : nullptr;
  if (!size.is_number_unsigned() || size.get<uint64_t>() < kLutMinSize || size.get<uint64_t>() > kLutMaxSize)
    throw Error(ExitCode::invalid_input, "lut parameters.size must be an integer in 2..65536", asset.where());
  StandardizationLut lut;
  lut.size = size.get<uint32_t>();
  for (uint32_t c = 0; c < kLutChannels; ++c) {
    const std::string name(kLutKnotSections[c]);
    const SectionInfo& s = asset.section(name);
    if (s.shape.size() != 2 || s.shape[1] != kLutKnotColumns || s.shape[0] < 1 || s.shape[0] > lut_max_knots(lut.size))
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
