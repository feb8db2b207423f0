// The help layout (see help_formatter.h).
#include "cli/help_formatter.h"

namespace mbk::cli {

HelpFormatter::HelpFormatter() {
  label("Positionals", "Arguments");
  label("SUBCOMMAND", "COMMAND");
  label("REQUIRED", "(required)");
  column_width(34);
}

std::string HelpFormatter::make_option_opts(const CLI::Option* option) const {
  if (option->get_positional() || option->get_type_size() == 0) return "";  // a name or a flag says it all
  std::string text = " " + option->get_type_name();
  if (option->get_expected_max() == CLI::detail::expected_max_vector_size) text += " ...";
  if (option->get_required()) text += " " + get_label("REQUIRED");
  return text;
}

std::string HelpFormatter::make_option_desc(const CLI::Option* option) const {
  const std::string& fallback = option->get_default_str();
  return option->get_description() + (fallback.empty() ? "" : " (default: " + fallback + ")");
}

}  // namespace mbk::cli
