// One planned asset as the plain command that bakes it alone: `microbake <kind> INPUT [options] -o PATH`, with the
// options of the technique's schema (technique_parameters.h) spelled as `microbake <kind> --help` shows them, each
// value exact (numbers in the shortest text that reads back to the same double). The command writes the same bytes
// as `microbake bake` run from the same folder (tests/cli/plan_test.cpp). `microbake plan` writes these commands
// into Ninja, Make, GNU parallel and Slurm files.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "libbake/scene/effect_registry.h"

namespace mbk {

// argv of the command; `program` is argv[0] ("microbake"). `extra` words (options the technique's schema does not
// declare, such as synth's --window) come after the schema's options, before -o.
std::vector<std::string> asset_command(const AssetRecipe& recipe, const std::filesystem::path& output,
                                       const std::string& program, const std::vector<std::string>& extra = {});

// Appends "--opt value", or "--opt=value" when the value starts with '-' (so that it is not read as an option).
void append_option(std::vector<std::string>& words, const std::string& option, const std::string& value);

// A word quoted for a POSIX shell when it needs it: plain words (letters, digits, -_./=+:,@%) as they are, any other
// in single quotes.
std::string shell_quoted(const std::string& word);
// The words, quoted, separated by spaces.
std::string shell_command_line(const std::vector<std::string>& words);

}  // namespace mbk
