// One effect as a material names it in a scene file: the effect's name and its options. In the scene an
// effect is either its name ("mip") or an object {"name": "glints", <options>}; the effect itself reads and
// checks its options (effect_registry.h), so `options` is canonical: every option with its value, defaults
// filled in, file options as written. Files named by options are also resolved against the scene folder.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace mbk {

struct EffectUse {
  std::string name;
  nlohmann::json options = nlohmann::json::object();
  std::map<std::string, std::filesystem::path> files;  // option name -> file, resolved
};

}  // namespace mbk
