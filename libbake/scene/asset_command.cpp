// A planned asset as its `microbake <kind>` command (see asset_command.h).
#include "libbake/scene/asset_command.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "libbake/image/normal_map.h"
#include "libbake/scene/technique_parameters.h"

namespace mbk {
namespace {

// What the command line reads back as exactly this value (parameter_value_text rounds numbers for help): a number in
// the fewest significant digits that give the same double ("0", "1e-06", "0.30000001192092896").
std::string exact_value_text(const Parameter& p, const nlohmann::json& value) {
  if (p.type != ParameterType::number) return parameter_value_text(p, value);
  const double x = value.get<double>();
  char text[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, x);
    if (std::strtod(text, nullptr) == x) break;
  }
  return text;
}

}  // namespace

void append_option(std::vector<std::string>& words, const std::string& option, const std::string& value) {
  if (!value.empty() && value[0] == '-') {
    words.push_back(option + "=" + value);
  } else {
    words.push_back(option);
    words.push_back(value);
  }
}

std::vector<std::string> asset_command(const AssetRecipe& recipe, const std::filesystem::path& output,
                                       const std::string& program, const std::vector<std::string>& extra) {
  const std::string& technique = recipe.technique.empty() ? recipe.kind : recipe.technique;
  std::vector<std::string> words = {program, technique};
  for (const BakeInput& in : recipe.inputs)
    if (in.option.empty()) words.push_back(in.path.string());
  for (const BakeInput& in : recipe.inputs) {
    if (!in.option.empty()) append_option(words, in.option, in.path.string());
    if (!in.normal_map) continue;
    if (in.normal_map->convention)
      append_option(words, "--convention", convention_request_name(in.normal_map->convention));
    if (in.normal_map->repair) words.push_back("--repair-invalid");
  }
  for (const Parameter& p : technique_schema(technique).parameters) {
    if (p.option.empty()) continue;
    const nlohmann::json value =
        recipe.technique_values.contains(p.name) ? recipe.technique_values.at(p.name) : p.default_value;
    if (value.is_null())
      throw std::logic_error("no value for " + technique + " parameter '" + p.name + "' (an effect's recipe)");
    append_option(words, p.option, exact_value_text(p, value));
  }
  words.insert(words.end(), extra.begin(), extra.end());
  words.push_back("-o");
  words.push_back(output.string());
  return words;
}

std::string shell_quoted(const std::string& word) {
  bool plain = !word.empty();
  for (char c : word)
    plain = plain && (std::isalnum(static_cast<unsigned char>(c)) ||
                      std::string_view("-_./=+:,@%").find(c) != std::string_view::npos);
  if (plain) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string shell_command_line(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& w : words) line += (line.empty() ? "" : " ") + shell_quoted(w);
  return line;
}

}  // namespace mbk
