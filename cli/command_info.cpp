// `microbake info FILE [--format text|json]`: an asset's header, metadata (producer, inputs, parameters,
// conventions, statistics) and sections with type, shape, bytes and checksum status. A structurally broken
// file is an error (exit 3); a section whose checksum fails is listed as such, then exit 3. --format json prints
// the same as one object (schema "microbake.info/1", formats/schema/info.schema.json).
#include <cstdio>
#include <iostream>

#include "cli/command.h"
#include "cli/common_options.h"
#include "formats/asset.h"
#include "formats/atomic_file.h"
#include "formats/validate.h"

namespace mbk::cli {
namespace {

std::string shape_text(const std::vector<uint64_t>& shape) {
  std::string s = "[";
  for (size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
  return s + "]";
}

// "convention: -Y, detected (requested auto; curl statistic -0.956, confidence 0.956, 0.250 needed)" for a
// normal-map input (convention_requested and convention_evidence, libbake/image/normal_map.h), else "".
std::string convention_line(const nlohmann::json& in) {
  if (!in.is_object() || !in.contains("convention_evidence") || !in["convention_evidence"].is_object()) return "";
  const nlohmann::json& e = in["convention_evidence"];
  auto number = [&](const char* key, const char* format) {
    char text[32] = "?";
    if (e.contains(key) && e[key].is_number()) std::snprintf(text, sizeof text, format, e[key].get<double>());
    return std::string(text);
  };
  auto text = [](const nlohmann::json& j, const char* key) {
    return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string("?");
  };
  return "convention: " + text(in, "convention") + ", " + text(e, "decision") + " (requested " +
         text(in, "convention_requested") + "; curl statistic " + number("statistic", "%+.3f") + ", confidence " +
         number("confidence", "%.3f") + ", " + number("required_confidence", "%.3f") + " needed)";
}

class InfoCommand : public Command {
 public:
  void add_options(CLI::App& app) override {
    app.add_option("FILE", options_.file, "Asset (.mbk) to describe")->required();
    add_format_option(app, options_.format);
  }

  int run() override {
    const std::vector<uint8_t> bytes = read_file_bytes(options_.file);
    std::vector<Finding> findings;
    auto parsed = parse_container(bytes, findings);
    throw_first_error(findings, options_.file);
    const ParsedContainer& p = *parsed;
    const AssetKind* kind = find_kind(p.header.kind);
    std::vector<bool> checksum_ok;
    bool all_ok = true;
    for (const auto& s : p.sections) {
      checksum_ok.push_back(checksum_of(bytes.data() + s.offset, s.byte_length) == s.checksum);
      all_ok = all_ok && checksum_ok.back();
    }
    if (options_.format == OutputFormat::json) {
      nlohmann::json j;
      j["schema"] = "microbake.info/1";
      j["file"] = options_.file;
      j["file_size"] = bytes.size();
      j["format_version"] = std::to_string(p.header.major) + "." + std::to_string(p.header.minor);
      j["kind"] = kind->name;
      j["kind_id"] = kind->id;
      j["metadata"] = p.metadata;
      j["sections"] = nlohmann::json::array();
      for (size_t i = 0; i < p.sections.size(); ++i) {
        const auto& s = p.sections[i];
        j["sections"].push_back({{"name", s.name},
                                 {"type", element_name(s.type)},
                                 {"shape", s.shape},
                                 {"offset", s.offset},
                                 {"bytes", s.byte_length},
                                 {"checksum", "xxh3:" + checksum_hex(s.checksum)},
                                 {"checksum_ok", bool(checksum_ok[i])}});
      }
      std::cout << j.dump(2) << "\n";
    } else {
      const auto& m = p.metadata;
      std::cout << "file:        " << options_.file << " (" << bytes.size() << " bytes)\n"
                << "format:      .mbk " << p.header.major << "." << p.header.minor << "\n"
                << "kind:        " << kind->name << " (id " << kind->id << "): " << kind->summary << "\n"
                << "producer:    " << m["producer"].value("name", "?") << " " << m["producer"].value("version", "?")
                << "\n";
      std::cout << "inputs:\n";
      for (const auto& in : m["inputs"]) {
        std::cout << "  " << in.dump() << "\n";
        if (const std::string line = convention_line(in); !line.empty()) std::cout << "    " << line << "\n";
      }
      for (const char* block : {"parameters", "conventions", "statistics"}) {
        std::cout << block << ":\n";
        if (m[block].is_object())
          for (auto it = m[block].begin(); it != m[block].end(); ++it)
            std::cout << "  " << it.key() << ": " << it.value().dump() << "\n";
      }
      std::cout << "sections:    " << p.sections.size() << "\n";
      for (size_t i = 0; i < p.sections.size(); ++i) {
        const auto& s = p.sections[i];
        std::printf("  %-20s %-4s %-22s %12llu bytes  xxh3:%s %s\n", s.name.c_str(),
                    std::string(element_name(s.type)).c_str(), shape_text(s.shape).c_str(),
                    static_cast<unsigned long long>(s.byte_length), checksum_hex(s.checksum).c_str(),
                    checksum_ok[i] ? "ok" : "MISMATCH");
      }
      std::fflush(stdout);
    }
    if (!all_ok)
      throw Error(ExitCode::invalid_input, "a section checksum does not match (see 'microbake validate')",
                  options_.file);
    // Listed, yet not an asset of its kind: a required section is missing or of the wrong type.
    std::vector<Finding> section_findings;
    check_sections(p, bytes, section_findings);
    throw_first_error(section_findings, options_.file);
    return 0;
  }

 private:
  struct Options {
    std::string file;
    OutputFormat format = OutputFormat::text;
  } options_;
};

}  // namespace

std::unique_ptr<Command> make_info_command() { return std::make_unique<InfoCommand>(); }

}  // namespace mbk::cli
