// Element types of .mbk sections (formats/SPEC.md, "Element types"): their on-disk codes, names and sizes.
#pragma once

#include <cstdint>
#include <string_view>

#include <Imath/half.h>

namespace mbk {

enum class ElementType : uint32_t {
  u8 = 1,
  i8 = 2,
  u16 = 3,
  i16 = 4,
  u32 = 5,
  i32 = 6,
  u64 = 7,
  i64 = 8,
  f16 = 9,
  f32 = 10,
  f64 = 11,
};

// Size in bytes of one element, or 0 for a code that is not an element type.
size_t element_size(uint32_t code);
std::string_view element_name(ElementType type);

// Maps a C++ type to its ElementType, for the typed accessors of writer and reader.
template <typename T>
struct ElementOf;
template <>
struct ElementOf<uint8_t> {
  static constexpr ElementType value = ElementType::u8;
};
template <>
struct ElementOf<int8_t> {
  static constexpr ElementType value = ElementType::i8;
};
template <>
struct ElementOf<uint16_t> {
  static constexpr ElementType value = ElementType::u16;
};
template <>
struct ElementOf<int16_t> {
  static constexpr ElementType value = ElementType::i16;
};
template <>
struct ElementOf<uint32_t> {
  static constexpr ElementType value = ElementType::u32;
};
template <>
struct ElementOf<int32_t> {
  static constexpr ElementType value = ElementType::i32;
};
template <>
struct ElementOf<uint64_t> {
  static constexpr ElementType value = ElementType::u64;
};
template <>
struct ElementOf<int64_t> {
  static constexpr ElementType value = ElementType::i64;
};
template <>
struct ElementOf<Imath::half> {
  static constexpr ElementType value = ElementType::f16;
};
template <>
struct ElementOf<float> {
  static constexpr ElementType value = ElementType::f32;
};
template <>
struct ElementOf<double> {
  static constexpr ElementType value = ElementType::f64;
};

}  // namespace mbk
