// The version string (see version.h); MICROBAKE_VERSION is defined for this file only, by CMakeLists.txt.
#include "formats/version.h"

namespace mbk {

const std::string& microbake_version() {
  static const std::string version = MICROBAKE_VERSION;
  return version;
}

}  // namespace mbk
