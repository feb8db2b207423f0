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

void SchemaOptions::add(CLI::App& app, const TechniqueSchema& schema) {
  schema_ = &schema;
  for (const Parameter& p : schema.parameters) {
    texts_.emplace_back();
    if (!p.option.empty()) add_parameter_option(app, p, texts_.back());
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
