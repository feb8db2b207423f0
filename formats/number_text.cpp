// Short real numbers for messages (see number_text.h).
#include "formats/number_text.h"

#include <cstdio>

namespace mbk {

std::string real_number_text(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", x);
  return text;
}

}  // namespace mbk
