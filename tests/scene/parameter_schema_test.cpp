// The option schemas (libbake/scene/technique_parameters.h) against everything that must agree with them: each scene
// effect reads exactly its declared keys, with the declared defaults and ranges (the edges accepted, one step beyond
// refused at the key's JSON path); an effect key taken from a technique stays inside the technique's range; every
// technique parameter with an option is that command's option in `microbake <technique> --help` with the same values
// and default, refused one step beyond its range by the real command; the option table of the command's page
// (docs/commands/<command>.md) lists it with the same default; and the tables of docs/SCENES.md list every effect key
// (and the keys of an object key with declared fields) with the same default. A drift in any of them fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "formats/error.h"
#include "libbake/scene/effect_registry.h"
#include "libbake/scene/scene.h"
#include "libbake/scene/technique_parameters.h"
#include "tests/image/cli_run.h"
#include "tests/scene/scene_test_fixtures.h"

namespace mbk {
namespace {

using nlohmann::json;

json scene_with(const json& effect) {
  return testing::one_material_scene({{"normal_map", {{"path", "maps/n.png"}}}, {"effects", {effect}}});
}

// The effect object with its required keys (the files) and `extra`.
json effect_object(const EffectInfo& e, const json& extra = json::object()) {
  json o = {{"name", e.name}};
  for (const Parameter& p : e.parameters)
    if (p.type == ParameterType::file && !p.optional_file) o[p.name] = "file.json";
  for (auto it = extra.begin(); it != extra.end(); ++it) o[it.key()] = it.value();
  return o;
}

// The canonical options the scene reads for `effect`, or the error it throws.
json options_of(const json& effect) {
  const Scene s = parse_scene(scene_with(effect), "/scenes");
  return s.materials.at("m").effects.at(0).options;
}

Error error_of(const json& effect) {
  try {
    options_of(effect);
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "accepted: " << effect.dump();
  return Error(ExitCode::success, "");
}

// Values one step outside the declared range (none for an unbounded side).
std::vector<json> outside(const Parameter& p) {
  std::vector<json> values;
  if (p.type == ParameterType::number) {
    values.push_back(std::nextafter(p.min, -INFINITY));
    values.push_back(std::nextafter(p.max, INFINITY));
  } else if (p.type == ParameterType::integer) {
    values.push_back(int64_t(p.min) - 1);
    if (p.max < 4294967295.0) values.push_back(int64_t(p.max) + 1);
    if (!p.allowed.empty()) values.push_back(p.allowed[0] + 1);
    if (p.power_of_two) values.push_back(int64_t(p.min) * 2 + 1);
  } else if (p.type == ParameterType::choice) {
    values.push_back("zz");
  } else if (p.type == ParameterType::size2) {
    values.push_back(json::array({int64_t(p.min) - 1, int64_t(p.min)}));
    values.push_back(json::array({int64_t(p.min), int64_t(p.max) + 1}));
  }
  return values;
}

// Values at the edges of the declared range, all valid.
std::vector<json> edges(const Parameter& p) {
  switch (p.type) {
    case ParameterType::number:
      return {p.min, p.max};
    case ParameterType::integer:
      if (!p.allowed.empty()) return {p.allowed.front(), p.allowed.back()};
      return {uint32_t(p.min), p.power_of_two ? uint32_t(std::exp2(std::floor(std::log2(p.max)))) : uint32_t(p.max)};
    case ParameterType::choice:
      return {p.choices.begin(), p.choices.end()};
    case ParameterType::size2:
      return {json::array({uint32_t(p.min), uint32_t(p.max)})};
    default:
      return {};
  }
}

TEST(ParameterSchema, EveryEffectReadsExactlyItsDeclaredKeys) {
  for (const EffectInfo& e : effect_registry()) {
    std::set<std::string> declared;
    for (const Parameter& p : e.parameters) EXPECT_TRUE(declared.insert(p.name).second) << e.name << ": " << p.name;
    if (!e.parse_options) continue;  // the scene reads each declared key itself (scene.cpp)
    const json object = effect_object(e);
    JsonObjectReader r(object, "e");
    (void)r.optional("name");
    e.parse_options(r, "/scenes");
    std::set<std::string> read = r.keys_read();
    read.erase("name");
    EXPECT_EQ(read, declared) << e.name;
  }
}

TEST(ParameterSchema, EffectKeysHonourTheirDefaultsAndRanges) {
  for (const EffectInfo& e : effect_registry()) {
    for (const Parameter& p : e.parameters) {
      const std::string what = e.name + "." + p.name;
      EXPECT_FALSE(p.doc.empty()) << what;
      if (p.type == ParameterType::file || p.type == ParameterType::object) continue;
      const json defaults = options_of(effect_object(e));
      if (!p.default_value.is_null()) {
        EXPECT_EQ(defaults.at(p.name), p.default_value) << what;
      }
      for (const json& v : edges(p)) {
        const json got = options_of(effect_object(e, {{p.name, v}})).at(p.name);
        if (p.type == ParameterType::number)
          EXPECT_NEAR(got.get<double>(), v.get<double>(), std::abs(v.get<double>()) * 1e-7) << what;
        else
          EXPECT_EQ(got, v) << what;
      }
      for (const json& v : outside(p)) {
        const Error err = error_of(effect_object(e, {{p.name, v}}));
        EXPECT_EQ(err.code(), ExitCode::invalid_input) << what << " = " << v.dump();
        EXPECT_EQ(err.where().rfind("materials.m.effects[0]." + p.name, 0), 0u)
            << what << " = " << v.dump() << ": " << err.where();
      }
    }
  }
}

TEST(ParameterSchema, KeysTakenFromATechniqueStayInsideItsRange) {
  size_t derived = 0;
  for (const EffectInfo& e : effect_registry())
    for (const Parameter& p : e.parameters) {
      if (p.source.empty()) continue;
      ++derived;
      const size_t dot = p.source.find('.');
      const Parameter& t = technique_schema(p.source.substr(0, dot)).at(p.source.substr(dot + 1));
      EXPECT_EQ(p.type, t.type) << p.source;
      EXPECT_GE(p.min, t.min) << p.source;
      EXPECT_LE(p.max, t.max) << p.source;
      EXPECT_EQ(p.allowed, t.allowed) << p.source;
      EXPECT_EQ(p.power_of_two, t.power_of_two) << p.source;
      for (const std::string& c : p.choices)  // a narrower choice, like a narrower range
        EXPECT_NE(std::find(t.choices.begin(), t.choices.end(), c), t.choices.end()) << p.source << ": " << c;
      EXPECT_EQ(p.choices.empty(), t.choices.empty()) << p.source;
      if (!p.default_value.is_null()) {
        EXPECT_TRUE(parameter_value_error(t, p.default_value).empty()) << p.source;
      }
    }
  EXPECT_GE(derived, 5u);  // glints' patch, lut_size and bits; colormap's table_size and sigma_max
}

// Every technique parameter with an option in a scene is read by an effect with the same range.
TEST(ParameterSchema, SceneParametersOfATechniqueAreSomeEffectsKeys) {
  for (const TechniqueSchema& t : technique_schemas())
    for (const Parameter& p : t.parameters) {
      if (!p.in_scenes) continue;
      bool found = false;
      for (const EffectInfo& e : effect_registry())
        for (const Parameter& k : e.parameters) found = found || k.source == t.technique + "." + p.name;
      EXPECT_TRUE(found) << t.technique << "." << p.name << " is read by no effect";
    }
}

std::string help_of(const std::string& command) {
  const test::ScratchDir dir;
  const test::CliRun r = test::run_cli(command + " --help", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.out;
}

// What a command line needs besides the option `tested`.
std::string required_arguments(const std::string& technique, const std::string& tested) {
  std::string args = " in.png -o out.mbk";
  if (technique == "crease") args += " --curves c.json";
  if (technique == "synth") args = " in.mbk -o out.png --window 0,0,1,1";
  if (technique == "synth" && tested != "--level") args += " --level 1";
  return args;
}

std::vector<std::string> outside_texts(const Parameter& p) {
  std::vector<std::string> texts;
  for (const json& v : outside(p)) {
    char exact[40];
    std::snprintf(exact, sizeof exact, "%.17g", v.is_number() ? v.get<double>() : 0.0);
    texts.push_back(p.type == ParameterType::size2    ? v[0].dump() + "x" + v[1].dump()
                    : p.type == ParameterType::number ? std::string(exact)
                                                      : parameter_value_text(p, v));
  }
  if (p.type == ParameterType::number) texts.push_back("nan");
  return texts;
}

TEST(ParameterSchema, EveryTechniqueParameterIsItsCommandsOptionWithTheSameValues) {
  for (const TechniqueSchema& t : technique_schemas()) {
    if (t.parameters.empty()) continue;
    const std::string help = help_of(t.technique);
    for (const Parameter& p : t.parameters) {
      if (p.option.empty()) continue;
      const std::string what = t.technique + " " + p.option;
      EXPECT_NE(help.find("  " + p.option + " " + parameter_label(p)), std::string::npos) << what << "\n" << help;
      if (!p.default_value.is_null()) {
        EXPECT_NE(help.find("(default: " + parameter_value_text(p, p.default_value) + ")"), std::string::npos) << what;
      }
      if (p.required) {
        EXPECT_NE(help.find(p.option + " " + parameter_label(p) + " (required)"), std::string::npos) << what;
      }
      const test::ScratchDir dir;
      for (const std::string& text : outside_texts(p)) {
        const test::CliRun r =
            test::run_cli(t.technique + required_arguments(t.technique, p.option) + " " + p.option + " " + text, dir);
        EXPECT_EQ(r.exit_code, 1) << what << " " << text << ": " << r.err;
        EXPECT_NE(r.err.find(p.option + ": '" + text + "' is not"), std::string::npos)
            << what << " " << text << ": " << r.err;
      }
    }
  }
}

// The rows "| `--option ...` | default | meaning |" of the command's page, docs/commands/<command>.md.
std::map<std::string, std::string> page_option_defaults(const std::string& command) {
  std::ifstream in(std::string(MICROBAKE_SOURCE_DIR) + "/docs/commands/" + command + ".md");
  std::map<std::string, std::string> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| `--", 0) != 0) continue;
    const size_t name_end = line.find_first_of(" `", 3);
    auto separator = [&](size_t from) {  // the next '|' that is not an escaped "\|"
      size_t at = line.find('|', from);
      while (at != std::string::npos && line[at - 1] == '\\') at = line.find('|', at + 1);
      return at;
    };
    const size_t cell = separator(1);
    const size_t cell_end = separator(cell + 1);
    std::string fallback = line.substr(cell + 1, cell_end - cell - 1);
    fallback.erase(std::remove(fallback.begin(), fallback.end(), '`'), fallback.end());
    const size_t text = fallback.find_first_not_of(' ');
    rows[line.substr(3, name_end - 3)] = text == std::string::npos ? "" : fallback.substr(text);
  }
  return rows;
}

TEST(ParameterSchema, TheOptionTableOfEachCommandsPageListsItsOptionsWithTheirDefaults) {
  for (const TechniqueSchema& t : technique_schemas()) {
    const auto rows = page_option_defaults(t.technique);
    for (const Parameter& p : t.parameters) {
      if (p.option.empty()) continue;
      const std::string what = t.technique + " " + p.option;
      ASSERT_TRUE(rows.count(p.option)) << what << " is not in the table of docs/commands/" << t.technique << ".md";
      const std::string& cell = rows.at(p.option);
      if (p.required) {
        EXPECT_EQ(cell.rfind("(required)", 0), 0u) << what << ": " << cell;
      } else if (p.type == ParameterType::number || (p.type == ParameterType::integer && !p.default_value.is_null())) {
        EXPECT_EQ(std::stod(cell), p.default_value.get<double>()) << what << ": " << cell;
      } else if (!p.default_value.is_null()) {
        EXPECT_EQ(cell.substr(0, cell.find(' ')), parameter_value_text(p, p.default_value)) << what << ": " << cell;
      }
    }
  }
}

// A table row of docs/SCENES.md in a table whose last column is "default": its cells (trimmed), and the "###"
// heading above it.
struct SceneDocRow {
  std::vector<std::string> cells;
  std::string heading;
  bool has_default = false;  // its table's last column is "default"
};

std::vector<SceneDocRow> scene_doc_rows() {
  std::ifstream in(std::string(MICROBAKE_SOURCE_DIR) + "/docs/SCENES.md");
  std::vector<SceneDocRow> rows;
  bool in_default_table = false;
  std::string heading;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) in_default_table = false;
    if (line.rfind("### ", 0) == 0) heading = line;
    if (line.rfind("|---", 0) == 0 && !rows.empty()) {  // the row above was the header: keep tables with defaults
      in_default_table = rows.back().cells.back() == "default";
      rows.pop_back();
      continue;
    }
    if (line.rfind("| ", 0) != 0) continue;
    SceneDocRow row{{}, heading, in_default_table};
    size_t from = 1;
    for (size_t at = from; (at = line.find('|', at)) != std::string::npos; ++at) {
      if (line[at - 1] == '\\') continue;  // an escaped "\|" inside a cell
      std::string cell = line.substr(from, at - from);
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      row.cells.push_back(cell);
      from = at + 1;
    }
    rows.push_back(row);
  }
  std::vector<SceneDocRow> kept;
  std::copy_if(rows.begin(), rows.end(), std::back_inserter(kept), [](const SceneDocRow& r) { return r.has_default; });
  return kept;
}

// The part of a row's cell that belongs to key `index` of a cell listing several ("`scale`, `offset`" | "`1`, `0`"),
// without backticks.
std::string cell_part(const std::string& cell, size_t index, size_t parts) {
  std::vector<std::string> pieces;
  std::stringstream in(cell);
  for (std::string piece; std::getline(in, piece, ',');) pieces.push_back(piece);
  std::string text = pieces.size() == parts ? pieces[index] : cell;
  text.erase(std::remove(text.begin(), text.end(), '`'), text.end());
  text.erase(0, text.find_first_not_of(' '));
  return text;
}

// The docs/SCENES.md row of key `key` about effect `effect`: a row with a cell listing `key`, and either a cell naming
// the effect or "all", or no such cell and the effect in the heading above it. Sets `index`/`parts` to the key's place
// in its cell; nullptr when there is none.
const SceneDocRow* scene_doc_row(const std::vector<SceneDocRow>& rows, const std::string& effect,
                                 const std::string& key, size_t& index, size_t& parts) {
  const std::string quoted_effect = "`" + effect + "`";
  for (const SceneDocRow& row : rows) {
    for (size_t c = 0; c < row.cells.size(); ++c) {
      const std::string& cell = row.cells[c];
      std::vector<std::string> keys;
      std::stringstream in(cell);
      for (std::string piece; std::getline(in, piece, ',');) {
        piece.erase(0, piece.find_first_not_of(' '));
        keys.push_back(piece);
      }
      const auto found = std::find(keys.begin(), keys.end(), "`" + key + "`");
      if (found == keys.end()) continue;
      bool names_effects = false, names_this = false;
      for (size_t o = 0; o < row.cells.size(); ++o) {
        if (o == c) continue;
        const bool all = row.cells[o] == "all";
        const bool effect_cell = all || row.cells[o].find("`colormap") == 0 || row.cells[o] == "`sh`" ||
                                 row.cells[o] == "`vmf`" || row.cells[o] == "`toksvig`";
        names_effects = names_effects || effect_cell;
        names_this = names_this || all || (effect_cell && row.cells[o].find(quoted_effect) != std::string::npos);
      }
      const bool heading_names = row.heading.find(quoted_effect) != std::string::npos;
      if (names_this || (!names_effects && heading_names)) {
        index = size_t(found - keys.begin());
        parts = keys.size();
        return &row;
      }
    }
  }
  return nullptr;
}

// A declared default as a documented default cell must spell it.
void expect_documented_default(const Parameter& p, const std::string& cell, const std::string& what) {
  if (p.required || (p.type == ParameterType::file && !p.optional_file)) {
    EXPECT_EQ(cell.rfind("required", 0), 0u) << what << ": " << cell;
  } else if (p.type == ParameterType::object && !p.fields.empty()) {
    json defaults = json::object();
    for (const Parameter& f : p.fields) defaults[f.name] = f.default_value;
    EXPECT_EQ(json::parse(cell, nullptr, false), defaults) << what << ": " << cell;
  } else if (p.type == ParameterType::size2) {
    EXPECT_EQ(json::parse(cell, nullptr, false), p.default_value) << what << ": " << cell;
  } else if (p.default_value.is_number()) {
    EXPECT_EQ(std::stod(cell), p.default_value.get<double>()) << what << ": " << cell;
  } else if (p.default_value.is_string()) {
    EXPECT_EQ(cell.substr(0, cell.find(' ')), p.default_value.get<std::string>()) << what << ": " << cell;
  }
}

TEST(ParameterSchema, TheScenePageListsEveryEffectKeyWithItsDefault) {
  const std::vector<SceneDocRow> rows = scene_doc_rows();
  ASSERT_FALSE(rows.empty());
  size_t checked = 0;
  for (const EffectInfo& e : effect_registry()) {
    for (const Parameter& p : e.parameters) {
      const std::string what = "effect " + e.name + " key " + p.name;
      size_t index = 0, parts = 1;
      const SceneDocRow* row = scene_doc_row(rows, e.name, p.name, index, parts);
      ASSERT_NE(row, nullptr) << what << " is not in a table of docs/SCENES.md";
      expect_documented_default(p, cell_part(row->cells.back(), index, parts), what);
      ++checked;
    }
  }
  EXPECT_GE(checked, 30u);
}

}  // namespace
}  // namespace mbk
