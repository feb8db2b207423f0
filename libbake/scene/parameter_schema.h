// A technique's parameters, declared once: name, type, default, range and a one-line doc (docs/ARCHITECTURE.md,
// "One option schema per technique"). The command line turns each declaration into its option (cli/schema_options.h),
// the scene effects read their JSON keys through it (read_parameter), and tests check that the commands, the effects
// and the README's option tables agree with it (tests/scene/parameter_schema_test.cpp, tests/cli/schema_test.cpp).
// The declarations themselves are in technique_parameters.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "libbake/scene/json_fields.h"

namespace mbk {

enum class ParameterType {
  integer,  // a whole number in [min, max]; `allowed` and `power_of_two` narrow it further
  number,   // a finite real number in [min, max]
  choice,   // one of `choices`
  size2,    // two integers in [min, max]: [width, height] in a scene, "WxH" on the command line
  file,     // a path (in a scene relative to the scene file); required unless `optional_file`
  object,   // a JSON object the effect reads itself (scenes only)
};

struct Parameter {
  std::string name;    // the scene key (snake_case)
  std::string option;  // the command-line option ("--max-iterations"); empty: scenes only
  bool in_scenes = true;
  ParameterType type = ParameterType::integer;
  double min = 0.0, max = 0.0;
  bool power_of_two = false;
  std::vector<uint32_t> allowed;     // integer: when not empty, the only values
  std::vector<std::string> choices;  // choice
  nlohmann::json default_value;      // null: none (the doc says what happens without a value)
  bool required = false;             // no default: a value must be given (files always are, unless optional_file)
  bool optional_file = false;        // file: may be absent; the effect reads it only when given (read_parameter
                                     // is not for such keys: effects read them with JsonObjectReader::optional)
  std::string doc;
  // For an effect key that is a technique's parameter under another name or a narrower range: "rmq.patch".
  std::string source;
  // object: the keys it holds when they are a fixed set (each read by read_parameter, others refused); empty: the
  // effect reads the object itself.
  std::vector<Parameter> fields;
};

struct TechniqueSchema {
  std::string technique;  // the command and asset kind ("sh"), or an effect's name
  std::vector<Parameter> parameters;
  // The parameter called `name`; std::out_of_range when there is none (a programming error).
  const Parameter& at(std::string_view name) const;
};

// The values a parameter takes, for help and messages: "[0, 256]", "8|16", "a power of two in [1, 4096]",
// "f16|f32", "WxH, each side in [2, 8192]", ">= 0".
std::string parameter_range_text(const Parameter& p);
// What help shows after the option's name: "INT in [0, 256]", "f16|f32", "NUM >= 0", "WxH, each side in [2, 8192]".
std::string parameter_label(const Parameter& p);
// A value as the command line spells it: 8, f16, 1e-06, 256x256.
std::string parameter_value_text(const Parameter& p, const nlohmann::json& value);

// Checks a JSON value against the declaration: "" when it fits, else why not ("value 300 is outside [0, 256]").
std::string parameter_value_error(const Parameter& p, const nlohmann::json& value);

// Scene side: the value of key p.name in `r`, checked (Error(invalid_input) at its JSON path), or p's default when
// absent. A file parameter is required and returned as written (see effect_file_option for resolving it).
nlohmann::json read_parameter(JsonObjectReader& r, const Parameter& p);

// Command-line side: the text of an option as a JSON value of p's type, checked; "" on success, else the reason
// ("'300' is not an integer in [0, 256]"; "an empty value").
std::string parse_parameter_text(const Parameter& p, const std::string& text, nlohmann::json& value);

}  // namespace mbk
