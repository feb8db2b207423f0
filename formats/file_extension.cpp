// Case-insensitive file extensions (see file_extension.h).
#include "formats/file_extension.h"

#include <cctype>

namespace mbk {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

}  // namespace mbk
