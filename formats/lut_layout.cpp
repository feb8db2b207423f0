// The size parameter, knot section shapes and grid positions of the `lut` kind (see lut_layout.h).
#include "formats/lut_layout.h"

namespace mbk {

std::optional<uint32_t> lut_size_parameter(const nlohmann::json& metadata) {
  const auto parameters = metadata.find("parameters");
  if (parameters == metadata.end() || !parameters->is_object()) return std::nullopt;
  const auto size = parameters->find("size");
  if (size == parameters->end() || !size->is_number_unsigned()) return std::nullopt;
  const uint64_t v = size->get<uint64_t>();
  if (v < kLutMinSize || v > kLutMaxSize) return std::nullopt;
  return uint32_t(v);
}

bool lut_knot_shape_ok(const std::vector<uint64_t>& shape, uint32_t size) {
  return shape.size() == 2 && shape[1] == kLutKnotColumns && shape[0] >= 1 && shape[0] <= lut_max_knots(size);
}

double lut_sample_position(double lo, double hi, uint32_t size, uint32_t j) {
  if (j + 1 >= size) return hi;
  return lo + (hi - lo) * (double(j) / double(size - 1));
}

}  // namespace mbk
