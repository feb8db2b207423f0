// Element type codes, names and sizes (formats/SPEC.md, "Element types").
#include "formats/element_type.h"

#include <array>

namespace mbk {
namespace {
struct ElementInfo {
  ElementType type;
  std::string_view name;
  size_t size;
};
constexpr std::array<ElementInfo, 11> kElements = {{
    {ElementType::u8, "u8", 1},
    {ElementType::i8, "i8", 1},
    {ElementType::u16, "u16", 2},
    {ElementType::i16, "i16", 2},
    {ElementType::u32, "u32", 4},
    {ElementType::i32, "i32", 4},
    {ElementType::u64, "u64", 8},
    {ElementType::i64, "i64", 8},
    {ElementType::f16, "f16", 2},
    {ElementType::f32, "f32", 4},
    {ElementType::f64, "f64", 8},
}};
}  // namespace

size_t element_size(uint32_t code) {
  for (const auto& e : kElements)
    if (static_cast<uint32_t>(e.type) == code) return e.size;
  return 0;
}

std::string_view element_name(ElementType type) {
  for (const auto& e : kElements)
    if (e.type == type) return e.name;
  return "?";
}

}  // namespace mbk
