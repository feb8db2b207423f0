// Numbers as error and finding messages print them: integers in full, real numbers with at most 9 significant
// digits ("1e+300", never the 300 digits std::to_string prints for a large double).
#pragma once

#include <string>
#include <type_traits>

namespace mbk {

std::string real_number_text(double x);

template <typename T>
std::string number_text(T x) {
  if constexpr (std::is_integral_v<T>)
    return std::to_string(x);
  else
    return real_number_text(double(x));
}

}  // namespace mbk
