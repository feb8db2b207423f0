// Files the evaluator loads once per render even when several materials use them (a normal map, its
// pyramid, an asset): each is made on first request under a key that says what it is ("asset|<file>") and
// shared afterwards. Single-threaded: used while shaders are built, before the pixel loop.
#pragma once

#include <map>
#include <memory>
#include <string>

namespace mbk {

class LoadCache {
 public:
  // The object stored under `key`, made by `make()` (returning a T) on first request. A key must always
  // be requested with the same T.
  template <class T, class Make>
  std::shared_ptr<const T> get(const std::string& key, Make&& make) {
    auto it = loaded_.find(key);
    if (it == loaded_.end()) it = loaded_.emplace(key, std::make_shared<const T>(make())).first;
    return std::static_pointer_cast<const T>(it->second);
  }

 private:
  std::map<std::string, std::shared_ptr<const void>> loaded_;
};

}  // namespace mbk
