// A path's extension compared without regard to case: every command and reader that picks a format or a
// reader from a file name (".PNG" is ".png") uses this one helper.
#pragma once

#include <filesystem>
#include <string>

namespace mbk {

// The extension of `path` with its dot, ASCII-lowercased (".exr"), or "" when it has none.
std::string lower_extension(const std::filesystem::path& path);

}  // namespace mbk
