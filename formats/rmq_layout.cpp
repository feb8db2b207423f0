// The `rmq` table layout and its parameters (see rmq_layout.h).
#include "formats/rmq_layout.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "formats/asset.h"
#include "formats/number_text.h"

namespace mbk {

nlohmann::json RmqLayout::to_parameters() const {
  return {{"width", width}, {"height", height}, {"patch", patch}, {"levels", levels}, {"bits", bits}};
}

uint32_t rmq_levels_for_patch(uint32_t patch) { return uint32_t(std::countr_zero(patch)) + 1; }

std::string parse_rmq_layout(const nlohmann::json& parameters, RmqLayout& layout) {
  if (!parameters.is_object()) return "parameters is not an object";
  uint32_t* fields[] = {&layout.width, &layout.height, &layout.patch, &layout.levels, &layout.bits};
  const char* names[] = {"width", "height", "patch", "levels", "bits"};
  for (size_t i = 0; i < 5; ++i) {
    const auto it = parameters.find(names[i]);
    if (it == parameters.end() || !it->is_number_unsigned() || it->get<uint64_t>() > UINT32_MAX)
      return std::string("parameters.") + names[i] + " missing or not an unsigned 32-bit integer";
    *fields[i] = it->get<uint32_t>();
  }
  if (layout.width == 0 || layout.height == 0) return "zero width or height";
  if (!std::has_single_bit(layout.patch) || layout.patch > kRmqMaxPatch)
    return "patch " + std::to_string(layout.patch) + " is not a power of two in [1, 4096]";
  if (layout.patch > std::min(layout.width, layout.height))
    return "patch " + std::to_string(layout.patch) + " is larger than the " + std::to_string(layout.width) + "x" +
           std::to_string(layout.height) + " example";
  if (layout.levels != rmq_levels_for_patch(layout.patch))
    return "levels " + std::to_string(layout.levels) + " should be " +
           std::to_string(rmq_levels_for_patch(layout.patch)) + " for patch " + std::to_string(layout.patch);
  if (layout.bits != 8 && layout.bits != 16) return "bits " + std::to_string(layout.bits) + " is neither 8 nor 16";
  return {};
}

std::string check_rmq_section_shapes(const Asset& asset, const RmqLayout& layout) {
  auto shape_text = [](const std::vector<uint64_t>& shape) {
    std::string t = "[";
    for (size_t i = 0; i < shape.size(); ++i) t += (i ? ", " : "") + std::to_string(shape[i]);
    return t + "]";
  };
  const SectionInfo& table = asset.section("table");
  if (table.type != layout.code_type() || table.shape != layout.table_shape())
    return "'table' is " + std::string(element_name(table.type)) + " " + shape_text(table.shape) +
           ", parameters ask for " + std::string(element_name(layout.code_type())) + " " +
           shape_text(layout.table_shape());
  const SectionInfo& range = asset.section("range");
  if (range.type != ElementType::f64 || range.shape != std::vector<uint64_t>{2, 2})
    return "'range' is " + std::string(element_name(range.type)) + " " + shape_text(range.shape) +
           ", should be f64 [2, 2]";
  return {};
}

std::string read_rmq_range(const Asset& asset, std::array<RmqRange, 2>& range) {
  const std::vector<double> values = asset.read<double>("range");
  for (size_t c = 0; c < 2; ++c) {
    range[c] = {values[2 * c], values[2 * c + 1]};
    const char* name = c == 0 ? "n_x" : "n_y";
    if (!std::isfinite(range[c].lo) || !std::isfinite(range[c].hi)) return std::string(name) + " range is not finite";
    if (range[c].lo > range[c].hi)
      return std::string(name) + " range has lo " + number_text(range[c].lo) + " > hi " + number_text(range[c].hi);
    if (!std::isfinite(range[c].hi - range[c].lo)) return std::string(name) + " range is too wide for a double";
  }
  return {};
}

}  // namespace mbk
