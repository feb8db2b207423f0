// Strict JSON object and value readers (see json_fields.h).
#include "libbake/scene/json_fields.h"

#include <cmath>

#include "formats/error.h"
#include "formats/number_text.h"

namespace mbk {
namespace {

[[noreturn]] void fail(const std::string& what, const std::string& path) {
  throw Error(ExitCode::invalid_input, what, path);
}

// "number 2.5", "string \"3\"", "object": the type, and the value when it is short enough to quote.
std::string found_text(const nlohmann::json& v) {
  if (v.is_structured()) return v.type_name();
  std::string text = v.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return std::string(v.type_name()) + " " + text;
}

// Builds the document as nlohmann's DOM parser does, refusing a key repeated in one object and nesting deeper than
// kMaxJsonDepth as they are read. (A SAX handler rather than nlohmann's parser callback: in 3.11 the callback parser
// rescans the whole enclosing array for discarded values after every object it closes, which is quadratic in the
// array's length - 200,000 colour stops took 16 s.)
class StrictDocumentBuilder final : public nlohmann::json_sax<nlohmann::json> {
 public:
  explicit StrictDocumentBuilder(const std::string& file) : file_(file) {}
  nlohmann::json take() { return std::move(document_); }

  bool null() override { return add(nullptr); }
  bool boolean(bool value) override { return add(value); }
  bool number_integer(number_integer_t value) override { return add(value); }
  bool number_unsigned(number_unsigned_t value) override { return add(value); }
  bool number_float(number_float_t value, const string_t&) override { return add(value); }
  bool string(string_t& value) override { return add(std::move(value)); }
  bool binary(binary_t& value) override { return add(nlohmann::json::binary(std::move(value))); }
  bool start_object(std::size_t) override { return open(nlohmann::json::object()); }
  bool start_array(std::size_t) override { return open(nlohmann::json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }
  bool key(string_t& key) override {
    Open& object = open_.back();
    object.key = key;
    if (!object.keys.insert(key).second)
      throw Error(ExitCode::invalid_input, "duplicate key '" + key + "' (a key may appear once)",
                  file_ + ": " + current_path());
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::json::exception& e) override { throw e; }

 private:
  // An object or array being filled, and where in it the parser is.
  struct Open {
    nlohmann::json* value;
    std::set<std::string> keys;  // objects: the keys read so far
    std::string key;             // objects: the key of the current member
  };

  // The JSON path of where the parser is. An array holds its current element already when something inside it
  // is open; the innermost one does not yet. Paths are built only for an error message, so that parsing stays
  // linear in the depth of nesting.
  std::string current_path() const {
    std::string path;
    for (size_t depth = 0; depth < open_.size(); ++depth) {
      const Open& o = open_[depth];
      const bool element_placed = depth + 1 < open_.size();
      path = o.value->is_object() ? json_child_path(path, o.key)
                                  : json_index_path(path, o.value->size() - (element_placed ? 1 : 0));
    }
    return path;
  }
  // Stores `value` where the parser is; returns where it went.
  nlohmann::json* place(nlohmann::json&& value) {
    if (open_.empty()) {
      document_ = std::move(value);
      return &document_;
    }
    nlohmann::json& parent = *open_.back().value;
    if (parent.is_object()) return &(parent[open_.back().key] = std::move(value));
    parent.push_back(std::move(value));
    return &parent.back();  // stable: the array grows again only after this element is closed
  }
  bool add(nlohmann::json&& value) {
    place(std::move(value));
    return true;
  }
  bool open(nlohmann::json&& empty) {
    if (open_.size() >= kMaxJsonDepth)
      throw Error(ExitCode::invalid_input,
                  "objects and arrays nested more than " + std::to_string(kMaxJsonDepth) + " deep",
                  file_ + ": " + current_path());
    nlohmann::json* value = place(std::move(empty));
    open_.push_back({value, {}, {}});
    return true;
  }
  bool close() {
    open_.pop_back();
    return true;
  }

  const std::string& file_;
  nlohmann::json document_;
  std::vector<Open> open_;
};

}  // namespace

nlohmann::json parse_json_strict(std::string_view text, const std::string& file) {
  if (text.size() > kMaxJsonBytes)
    throw Error(ExitCode::invalid_input,
                "JSON file of " + std::to_string(text.size()) + " bytes; at most " + std::to_string(kMaxJsonBytes) +
                    " are read",
                file);
  StrictDocumentBuilder builder(file);
  try {
    nlohmann::json::sax_parse(text.begin(), text.end(), &builder);
  } catch (const nlohmann::json::exception& e) {  // parse errors, and numbers overflowing double
    throw Error(ExitCode::invalid_input, std::string("malformed JSON: ") + e.what(), file);
  }
  return builder.take();
}

std::string json_child_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}
std::string json_index_path(const std::string& parent, size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

JsonObjectReader::JsonObjectReader(const nlohmann::json& value, std::string path)
    : object_(value), path_(std::move(path)) {
  if (!value.is_object()) fail("expected an object, found " + found_text(value), path_.empty() ? "(top level)" : path_);
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
  if (!v.is_number()) fail("expected a number, found " + found_text(v), path);
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi)
    fail("value " + number_text(x) + " is outside [" + number_text(lo) + ", " + number_text(hi) + "]", path);
  return x;
}

uint32_t json_uint(const nlohmann::json& v, const std::string& path, uint32_t lo, uint32_t hi) {
  if (!v.is_number_integer()) fail("expected an integer, found " + found_text(v), path);
  // Above INT64_MAX only unsigned JSON integers exist: read those as uint64_t, so that none wraps to negative.
  const bool in_range = v.is_number_unsigned() ? v.get<uint64_t>() >= lo && v.get<uint64_t>() <= hi
                                               : v.get<int64_t>() >= int64_t(lo) && v.get<int64_t>() <= int64_t(hi);
  if (!in_range)
    fail("value " + v.dump() + " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]", path);
  return v.get<uint32_t>();
}

bool json_bool(const nlohmann::json& v, const std::string& path) {
  if (!v.is_boolean()) fail("expected true or false, found " + found_text(v), path);
  return v.get<bool>();
}

std::string json_string(const nlohmann::json& v, const std::string& path) {
  if (!v.is_string()) fail("expected a string, found " + found_text(v), path);
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
