// Strict JSON object and value readers (see json_fields.h).
#include "libbake/scene/json_fields.h"

#include <cmath>
#include <sstream>

#include "formats/error.h"

namespace mbk {
namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path) {
  throw Error(ExitCode::invalid_input, what, path);
}

std::string type_name(const nlohmann::json& v) { return v.type_name(); }

std::string number_text(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

}  // namespace

std::string json_child_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}
std::string json_index_path(const std::string& parent, size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

JsonObjectReader::JsonObjectReader(const nlohmann::json& value, std::string path)
    : object_(value), path_(std::move(path)) {
  if (!value.is_object()) fail("expected an object, found " + type_name(value), path_.empty() ? "(top level)" : path_);
}

const nlohmann::json* JsonObjectReader::optional(const std::string& key) {
  read_.insert(key);
  auto it = object_.find(key);
  return it == object_.end() ? nullptr : &*it;
}

const nlohmann::json& JsonObjectReader::required(const std::string& key) {
  const nlohmann::json* v = optional(key);
  if (!v) fail("missing key '" + key + "'", child(key));
  return *v;
}

void JsonObjectReader::reject_unknown_keys() const {
  for (auto it = object_.begin(); it != object_.end(); ++it) {
    if (read_.count(it.key())) continue;
    std::string known;
    for (const auto& k : read_) known += (known.empty() ? "" : ", ") + k;
    fail("unknown key '" + it.key() + "' (known here: " + known + ")", child(it.key()));
  }
}

double json_number(const nlohmann::json& v, const std::string& path, double lo, double hi) {
  if (!v.is_number()) fail("expected a number, found " + type_name(v), path);
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi)
    fail("value " + number_text(x) + " is outside [" + number_text(lo) + ", " + number_text(hi) + "]", path);
  return x;
}

uint32_t json_uint(const nlohmann::json& v, const std::string& path, uint32_t lo, uint32_t hi) {
  if (!v.is_number_integer()) fail("expected an integer, found " + type_name(v), path);
  const int64_t x = v.get<int64_t>();
  if (x < int64_t(lo) || x > int64_t(hi))
    fail("value " + std::to_string(x) + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]", path);
  return uint32_t(x);
}

bool json_bool(const nlohmann::json& v, const std::string& path) {
  if (!v.is_boolean()) fail("expected true or false, found " + type_name(v), path);
  return v.get<bool>();
}

std::string json_string(const nlohmann::json& v, const std::string& path) {
  if (!v.is_string()) fail("expected a string, found " + type_name(v), path);
  return v.get<std::string>();
}

std::string json_choice(const nlohmann::json& v, const std::string& path, const std::vector<std::string>& choices) {
  const std::string s = json_string(v, path);
  std::string list;
  for (const auto& c : choices) {
    if (c == s) return s;
    list += (list.empty() ? "" : ", ") + c;
  }
  fail("unknown value '" + s + "' (expected one of: " + list + ")", path);
}

namespace {
std::vector<double> number_array(const nlohmann::json& v, const std::string& path, size_t n, double lo, double hi) {
  if (!v.is_array() || v.size() != n) fail("expected an array of " + std::to_string(n) + " numbers", path);
  std::vector<double> out;
  for (size_t i = 0; i < n; ++i) out.push_back(json_number(v[i], json_index_path(path, i), lo, hi));
  return out;
}
constexpr double kHuge = 1e30;  // coordinates beyond this overflow squared distances in double
}  // namespace

Vec3 json_vec3(const nlohmann::json& v, const std::string& path) {
  const auto a = number_array(v, path, 3, -kHuge, kHuge);
  return Vec3(a[0], a[1], a[2]);
}

Vec2 json_vec2(const nlohmann::json& v, const std::string& path, double lo, double hi) {
  const auto a = number_array(v, path, 2, lo, hi);
  return Vec2(a[0], a[1]);
}

Vec3 json_rgb(const nlohmann::json& v, const std::string& path, double lo, double hi) {
  if (v.is_number()) return Vec3::Constant(json_number(v, path, lo, hi));
  const auto a = number_array(v, path, 3, lo, hi);
  return Vec3(a[0], a[1], a[2]);
}

Vec3 json_direction(const nlohmann::json& v, const std::string& path) {
  const Vec3 d = json_vec3(v, path);
  const double len = d.norm();
  // Below this the direction is dominated by the rounding of its inputs.
  if (!(len > 1e-12)) fail("expected a non-zero direction", path);
  return d / len;
}

}  // namespace mbk
