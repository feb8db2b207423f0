// Options from parameter declarations (see parameter_options.h).
#include "cli/parameter_options.h"

#include <utility>

namespace mbk::cli {

Parameter integer_option(std::string option, double min, double max, nlohmann::json default_value, std::string doc) {
  Parameter p;
  p.option = std::move(option);
  p.min = min;
  p.max = max;
  p.default_value = std::move(default_value);
  p.doc = std::move(doc);
  return p;
}

CLI::Validator parameter_validator(const Parameter& p) {
  // No description: help shows parameter_label() instead of CLI11's own text.
  return CLI::Validator(
      [p](std::string& value) -> std::string {
        nlohmann::json parsed;
        const std::string error = parse_parameter_text(p, value, parsed);
        if (error.empty() && p.type == ParameterType::choice) value = parsed.get<std::string>();
        return error;
      },
      "", p.name);
}

void SchemaOptions::add(CLI::App& app, const TechniqueSchema& schema) { add_each(app, schema, nullptr); }

void SchemaOptions::add_optional_group(CLI::App& app, const TechniqueSchema& schema, const std::string& group) {
  add_each(app, schema, &group);
}

void SchemaOptions::add_each(CLI::App& app, const TechniqueSchema& schema, const std::string* optional_group) {
  schema_ = &schema;
  for (const Parameter& declared : schema.parameters) {
    texts_.emplace_back();
    if (declared.option.empty()) continue;
    Parameter p = declared;
    if (optional_group) p.required = false;
    CLI::Option* option = add_parameter_option(app, p, texts_.back());
    if (optional_group) option->group(*optional_group);
  }
}

nlohmann::json SchemaOptions::values() const {
  nlohmann::json values = nlohmann::json::object();
  for (size_t i = 0; i < schema_->parameters.size(); ++i) {
    const Parameter& p = schema_->parameters[i];
    nlohmann::json& value = values[p.name] = p.default_value;
    if (!texts_[i].empty()) (void)parse_parameter_text(p, texts_[i], value);  // checked while parsing
  }
  return values;
}

}  // namespace mbk::cli
