// Strict reading of JSON (scene files, colour-map stops, crease curves): parse_json_strict refuses an object
// that names a key twice (the JSON parser would keep the last one silently); every key of an object must be read,
// and a key nobody read is an error naming its JSON path ("materials.brick.rougness"), so a typo is never
// silently ignored (docs/ARCHITECTURE.md, "Strict input"). Wrong types and values
// out of range are errors naming their path too. Errors are Error(invalid_input, what, json_path); callers
// that know the file prefix the path with it.
#pragma once

#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "libbake/core/eigen.h"

namespace mbk {

// Limits of every JSON input (checked before and while parsing, so that hostile files fail fast): the size of the
// text, and how deep objects and arrays may nest (microbake's formats nest at most 5 deep).
inline constexpr size_t kMaxJsonBytes = size_t(16) << 20;
inline constexpr size_t kMaxJsonDepth = 64;

// Parses a JSON document from `file`. Error(invalid_input) "malformed JSON: ..." at `file`, or
// "duplicate key 'k'", or a limit above exceeded, at "<file>: <JSON path of the second k>" (e.g. "scene.json:
// materials.brick.roughness").
nlohmann::json parse_json_strict(std::string_view text, const std::string& file);

// "a.b" + "c" -> "a.b.c"; "" + "c" -> "c".
std::string json_child_path(const std::string& parent, const std::string& key);
// "shapes" + 2 -> "shapes[2]".
std::string json_index_path(const std::string& parent, size_t index);

class JsonObjectReader {
 public:
  // Error when `value` is not an object.
  JsonObjectReader(const nlohmann::json& value, std::string path);

  const std::string& path() const { return path_; }
  std::string child(const std::string& key) const { return json_child_path(path_, key); }
  // Marks the key as read and returns its value, or nullptr when absent.
  const nlohmann::json* optional(const std::string& key);
  // Marks the key as read and returns its value; Error "missing key" when absent.
  const nlohmann::json& required(const std::string& key);
  // Error naming the first key (in the object's sorted order) that no one read, listing the keys read.
  void reject_unknown_keys() const;
  // The keys looked up so far, present or not.
  const std::set<std::string>& keys_read() const { return read_; }

 private:
  const nlohmann::json& object_;
  std::string path_;
  std::set<std::string> read_;
};

// Typed values; `path` names the value in errors. Numbers must be finite and inside [lo, hi].
double json_number(const nlohmann::json& v, const std::string& path, double lo, double hi);
// Integer in [lo, hi] (any JSON integer, also beyond 64 bits signed, is compared exactly).
uint32_t json_uint(const nlohmann::json& v, const std::string& path, uint32_t lo, uint32_t hi);
bool json_bool(const nlohmann::json& v, const std::string& path);
std::string json_string(const nlohmann::json& v, const std::string& path);
// One of `choices`; the error lists them.
std::string json_choice(const nlohmann::json& v, const std::string& path, const std::vector<std::string>& choices);
// [x, y, z] of finite numbers.
Vec3 json_vec3(const nlohmann::json& v, const std::string& path);
// [x, y] of numbers inside [lo, hi].
Vec2 json_vec2(const nlohmann::json& v, const std::string& path, double lo, double hi);
// A linear RGB colour: a number (grey) or [r, g, b], each inside [lo, hi].
Vec3 json_rgb(const nlohmann::json& v, const std::string& path, double lo, double hi);
// A non-zero direction, returned normalised.
Vec3 json_direction(const nlohmann::json& v, const std::string& path);

}  // namespace mbk
