// Command-line options made from parameter declarations (libbake/scene/parameter_schema.h), so that an option's
// name, range, default, help line and error message come from one place: add_parameter_option for one option bound to
// a typed variable (also for the options every command shares, common_options.h), SchemaOptions for all the options
// of a technique's schema (libbake/scene/technique_parameters.h), read back as canonical JSON values, the same a
// scene effect reads.
#pragma once

#include <deque>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "libbake/scene/parameter_schema.h"

namespace mbk::cli {

// A command's own integer option (not a technique's parameter): values in [min, max], the default (null: none) and
// the help line.
Parameter integer_option(std::string option, double min, double max, nlohmann::json default_value, std::string doc);

// The check of a value against its declaration (parse_parameter_text); a choice is rewritten to its canonical
// spelling, so `--format JSON` means json.
CLI::Validator parameter_validator(const Parameter& p);

// Adds option p.option bound to `target`, checked by the declaration; the declared default (if any) is assigned to
// `target` and shown in help; a required one must be given.
template <class T>
CLI::Option* add_parameter_option(CLI::App& app, const Parameter& p, T& target) {
  CLI::Option* option = app.add_option(p.option, target, p.doc)->type_name(parameter_label(p));
  // CLI11 lets only transforms rewrite a value (a choice's spelling); any other check leaves it as written.
  if (p.type == ParameterType::choice)
    option->transform(parameter_validator(p));
  else
    option->check(parameter_validator(p));
  if (!p.default_value.is_null()) option->default_val(parameter_value_text(p, p.default_value));
  if (p.required) option->required();
  return option;
}

// Every parameter of a technique's schema that has an option.
class SchemaOptions {
 public:
  void add(CLI::App& app, const TechniqueSchema& schema);
  // The same options under help heading `group`, none of them required by the parser: for options that only matter
  // together with another one (`plan --synth`), whose command checks what they need.
  void add_optional_group(CLI::App& app, const TechniqueSchema& schema, const std::string& group);
  // After parsing: every parameter of the schema, given or defaulted (null when neither; scene-only ones have their
  // declared default), as JSON values of its type.
  nlohmann::json values() const;

 private:
  void add_each(CLI::App& app, const TechniqueSchema& schema, const std::string* optional_group);

  const TechniqueSchema* schema_ = nullptr;
  std::deque<std::string> texts_;  // one per parameter, in schema order (a deque keeps CLI11's pointers valid)
};

}  // namespace mbk::cli
