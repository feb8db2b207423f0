// Reading and checking parameter values against their declaration (see parameter_schema.h).
#include "libbake/scene/parameter_schema.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "formats/error.h"

namespace mbk {
namespace {

constexpr double kUnboundedInteger = 4294967295.0;
constexpr double kUnboundedNumber = 1e300;

// %g: "1e+06", "0.5", "256".
std::string short_number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

std::string joined(const std::vector<std::string>& items, const char* separator) {
  std::string s;
  for (const auto& item : items) s += (s.empty() ? "" : separator) + item;
  return s;
}

std::vector<std::string> allowed_texts(const Parameter& p) {
  std::vector<std::string> texts;
  for (uint32_t v : p.allowed) texts.push_back(std::to_string(v));
  return texts;
}

std::string interval_text(const Parameter& p) {
  const bool unbounded = p.max >= (p.type == ParameterType::number ? kUnboundedNumber : kUnboundedInteger);
  return unbounded ? ">= " + short_number(p.min) : "in [" + short_number(p.min) + ", " + short_number(p.max) + "]";
}

// A whole number written in decimal digits only ("12"; not "+12", "1e3" or "12 ").
bool whole_number(std::string_view text, uint64_t& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && ec == std::errc() && end == text.data() + text.size();
}

std::string integer_error(const Parameter& p, uint64_t v) {
  if (double(v) < p.min || double(v) > p.max)
    return "is outside [" + short_number(p.min) + ", " + short_number(p.max) + "]";
  if (!p.allowed.empty() && std::find(p.allowed.begin(), p.allowed.end(), v) == p.allowed.end())
    return "is not one of " + joined(allowed_texts(p), ", ");
  if (p.power_of_two && !std::has_single_bit(v)) return "is not a power of two";
  return "";
}

}  // namespace

const Parameter& TechniqueSchema::at(std::string_view name) const {
  for (const Parameter& p : parameters)
    if (p.name == name) return p;
  throw std::out_of_range("no parameter '" + std::string(name) + "' in the schema of " + technique);
}

std::string parameter_range_text(const Parameter& p) {
  switch (p.type) {
    case ParameterType::integer:
      if (!p.allowed.empty()) return joined(allowed_texts(p), "|");
      return p.power_of_two ? "a power of two " + interval_text(p) : interval_text(p);
    case ParameterType::number:
      return interval_text(p);
    case ParameterType::choice:
      return joined(p.choices, "|");
    case ParameterType::size2:
      return "WxH, each side " + interval_text(p);
    case ParameterType::file:
    case ParameterType::object:
      return "";
  }
  return "";
}

std::string parameter_label(const Parameter& p) {
  const std::string range = parameter_range_text(p);
  switch (p.type) {
    case ParameterType::integer:
      return !p.allowed.empty() ? range : "INT" + std::string(p.power_of_two ? ", " : " ") + range;
    case ParameterType::number:
      return "NUM " + range;
    case ParameterType::choice:
    case ParameterType::size2:
      return range;
    case ParameterType::file:
    case ParameterType::object:
      return "FILE";
  }
  return "";
}

std::string parameter_value_text(const Parameter& p, const nlohmann::json& value) {
  if (value.is_null()) return "";
  if (p.type == ParameterType::size2) return value[0].dump() + "x" + value[1].dump();
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_float()) return short_number(value.get<double>());
  return value.dump();
}

std::string parameter_value_error(const Parameter& p, const nlohmann::json& value) {
  const std::string text = value.dump();
  switch (p.type) {
    case ParameterType::integer:
      if (!value.is_number_integer()) return "expected an integer, found " + text;
      if (value.is_number_integer() && !value.is_number_unsigned() && value.get<int64_t>() < 0)
        return "value " + text + " is outside [" + short_number(p.min) + ", " + short_number(p.max) + "]";
      if (const std::string why = integer_error(p, value.get<uint64_t>()); !why.empty())
        return "value " + text + " " + why;
      return "";
    case ParameterType::number:
      if (!value.is_number()) return "expected a number, found " + text;
      if (!std::isfinite(value.get<double>()) || value.get<double>() < p.min || value.get<double>() > p.max)
        return "value " + text + " is outside [" + short_number(p.min) + ", " + short_number(p.max) + "]";
      return "";
    case ParameterType::choice:
      if (!value.is_string() ||
          std::find(p.choices.begin(), p.choices.end(), value.get<std::string>()) == p.choices.end())
        return "unknown value " + text + " (expected one of: " + joined(p.choices, ", ") + ")";
      return "";
    case ParameterType::size2:
      if (!value.is_array() || value.size() != 2) return "expected [width, height], found " + text;
      for (const auto& side : value)
        if (!side.is_number_unsigned() || double(side.get<uint64_t>()) < p.min || double(side.get<uint64_t>()) > p.max)
          return "side " + side.dump() + " is outside [" + short_number(p.min) + ", " + short_number(p.max) + "]";
      return "";
    case ParameterType::file:
      return value.is_string() && !value.get<std::string>().empty() ? "" : "expected a non-empty path";
    case ParameterType::object:
      return value.is_object() ? "" : "expected an object";
  }
  return "";
}

nlohmann::json read_parameter(JsonObjectReader& r, const Parameter& p) {
  const std::string path = r.child(p.name);
  if (p.type == ParameterType::file) {
    const std::string file = json_string(r.required(p.name), path);
    if (file.empty()) throw Error(ExitCode::invalid_input, "empty path", path);
    return file;
  }
  const nlohmann::json* v = r.optional(p.name);
  if (!v) return p.default_value;
  switch (p.type) {
    case ParameterType::integer: {
      const uint32_t x = json_uint(*v, path, uint32_t(p.min), uint32_t(p.max));
      if (const std::string why = integer_error(p, x); !why.empty())
        throw Error(ExitCode::invalid_input, "value " + std::to_string(x) + " " + why, path);
      return x;
    }
    case ParameterType::number:
      return json_number(*v, path, p.min, p.max);
    case ParameterType::choice:
      return json_choice(*v, path, p.choices);
    case ParameterType::size2: {
      if (!v->is_array() || v->size() != 2) throw Error(ExitCode::invalid_input, "expected [width, height]", path);
      nlohmann::json sides = nlohmann::json::array();
      for (size_t i = 0; i < 2; ++i)
        sides.push_back(json_uint((*v)[i], json_index_path(path, i), uint32_t(p.min), uint32_t(p.max)));
      return sides;
    }
    case ParameterType::object:
      if (!v->is_object()) throw Error(ExitCode::invalid_input, "expected an object", path);
      return *v;
    case ParameterType::file:
      break;
  }
  return *v;
}

std::string parse_parameter_text(const Parameter& p, const std::string& text, nlohmann::json& value) {
  if (text.empty()) return "an empty value";
  const std::string quoted = "'" + (text.size() > 40 ? text.substr(0, 37) + "..." : text) + "'";
  switch (p.type) {
    case ParameterType::integer: {
      uint64_t v = 0;
      const bool whole = whole_number(text, v);
      if (!whole || !integer_error(p, v).empty()) {
        if (!p.allowed.empty()) return quoted + " is not one of " + parameter_range_text(p);
        return quoted + " is not " + (p.power_of_two ? "" : "an integer ") + parameter_range_text(p);
      }
      value = v;
      return "";
    }
    case ParameterType::number: {
      double x = 0.0;
      size_t used = 0;
      try {
        x = std::stod(text, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != text.size() || !std::isfinite(x) || x < p.min || x > p.max)
        return quoted + " is not " +
               (p.max >= kUnboundedNumber ? "a finite number >= " + short_number(p.min)
                                          : "a number in [" + short_number(p.min) + ", " + short_number(p.max) + "]");
      value = x;
      return "";
    }
    case ParameterType::choice: {
      std::string lower = text;
      for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
      for (const std::string& c : p.choices)
        if (c == lower) {
          value = c;
          return "";
        }
      return quoted + " is not one of " + parameter_range_text(p);
    }
    case ParameterType::size2: {
      const size_t x = text.find_first_of("xX");
      uint64_t w = 0, h = 0;
      if (x == std::string::npos || !whole_number(std::string_view(text).substr(0, x), w) ||
          !whole_number(std::string_view(text).substr(x + 1), h) || double(w) < p.min || double(w) > p.max ||
          double(h) < p.min || double(h) > p.max)
        return quoted + " is not " + parameter_range_text(p);
      value = {w, h};
      return "";
    }
    case ParameterType::file:
    case ParameterType::object:
      value = text;
      return "";
  }
  return "";
}

}  // namespace mbk
