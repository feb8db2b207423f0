// The malformed-input corpus: a few hundred hostile inputs, generated here from a handful of valid files (so the
// repository holds no corpus files), each run through the command that reads it. Every case names its command
// line, its expected exit code and the first words of its error, and the test asserts for each: that exit code, no
// signal, no hang (killed after kCaseSeconds), exactly one line `microbake: error: <first words>...` on stderr
// (validate reports on stdout instead: "INVALID" and the finding, nothing on stderr), and no output file left
// behind. Inputs: truncated, bit-flipped and resealed-but-edited assets of every kind (read by info, validate,
// render and synth), damaged and odd images for every baking command, hostile JSON for every JSON reader, hostile
// SVG, and bad command-line values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <filesystem>
#include <fstream>
#include <limits>

#include <nlohmann/json.hpp>

#include "formats/asset.h"
#include "formats/atomic_file.h"
#include "formats/element_type.h"
#include "libbake/image/image_io.h"
#include "tests/formats/asset_fixtures.h"
#include "tests/corpus/run_microbake.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {
namespace fs = std::filesystem;
using Bytes = std::vector<uint8_t>;

using test::kCaseSeconds;
using test::run_microbake;

struct CorpusCase {
  std::string name;
  std::vector<std::string> args;  // after the executable
  int exit_code;
  std::string first_words;  // of the error after "microbake: error: " (validate: a fragment of its report)
  std::string output;       // a file the command must not leave behind ("" when it writes none)
};

void write_bytes(const fs::path& p, const Bytes& b) { write_file_bytes(p, b, p.string()); }
void write_text(const fs::path& p, const std::string& s) { std::ofstream(p, std::ios::binary) << s; }
Bytes read_bytes(const fs::path& p) { return read_file_bytes(p); }

// The valid files every malformed one is made from, made once by the executable itself.
class Corpus {
 public:
  Corpus() : dir_("corpus") {
    const std::vector<std::vector<std::string>> setup = {
        {"gen", "bumps", "--size", "16", "-q", "-o", "bumps.png"},
        {"gen", "panels", "--size", "32", "-q", "-o", "panels.png", "--creases", "panels.json"},
        {"gen", "flakes", "--size", "16", "-q", "-o", "flakes.png"},
        {"mip", "bumps.png", "-q", "-o", "valid.mip.mbk"},
        {"sh", "bumps.png", "--order", "2", "-q", "-o", "valid.sh.mbk"},
        {"vmf", "bumps.png", "--lobes", "2", "--max-iterations", "10", "-q", "-o", "valid.vmf.mbk"},
        {"lut", "bumps.png", "-q", "-o", "valid.lut.mbk"},
        {"rmq", "bumps.png", "--patch", "4", "-q", "-o", "valid.rmq.mbk"},
        {"moments", "bumps.png", "-q", "-o", "valid.moments.mbk"},
        {"histogram", "bumps.png", "--method", "exact", "-q", "-o", "valid.histogram.mbk"},
        {"histogram", "bumps.png", "--iterations", "20", "--batch", "64", "-q", "-o", "valid.neural_histogram.mbk"},
        {"colormap", "stripes.json", "--size", "16x8", "-q", "-o", "valid.colormap.mbk"},
        {"crease", "panels.png", "--curves", "panels.json", "-q", "-o", "valid.crease.mbk"},
        {"graph", "graph.json", "-q", "-o", "valid.graph.mbk"},
        {"render", "mip_scene.json", "--reference", "1", "-q", "-o", "valid.exr"},
        {"bake", "filtered_ndf_scene.json", "-q"},
        {"bake", "colormap_scene.json", "-q"},
    };
    fs::copy_file(fs::path(MICROBAKE_SOURCE_DIR) / "examples" / "colormaps" / "stripes.json", path("stripes.json"));
    fs::copy_file(fs::path(MICROBAKE_SOURCE_DIR) / "examples" / "colormaps" / "stripes.json", path("cli_stripes.json"));
    for (const char* scene : {"mip_scene.json", "filtered_ndf_scene.json", "colormap_scene.json"})
      fs::copy_file(fs::path(MICROBAKE_SOURCE_DIR) / "tests" / "cli" / "scenes" / scene, path(scene));
    write_text(path("graph.json"),
               R"({"exemplars": [{"id": "a", "path": "bumps.png"}], "root": "a",
                   "edges": [{"source": "a", "destination": "a", "r": 1}]})");
    for (const auto& args : setup) {
      const test::Run r = run_microbake(args, dir_.path());
      if (r.exit_code != 0) throw std::runtime_error("corpus setup failed: " + args[0] + " " + args[1] + ": " + r.err);
    }
  }
  fs::path path(const std::string& name) const { return dir_.path() / name; }
  const fs::path& dir() const { return dir_.path(); }

 private:
  test::ScratchDir dir_;
};

const Corpus& corpus() {
  static const Corpus c;
  return c;
}

// --- assets --------------------------------------------------------------------------------------------------

const char* const kKinds[] = {
    "mip", "sh", "vmf", "lut", "rmq", "moments", "colormap", "crease", "graph", "histogram", "neural_histogram"};

// `f` with metadata parameters[key] set to `value`, resealed. The producer's name is shortened to make room, since
// the metadata block cannot grow.
Bytes with_parameter(const Bytes& f, const std::string& key, const nlohmann::json& value) {
  const uint64_t meta_off = load_le<uint64_t>(&f[24]), meta_size = load_le<uint64_t>(&f[32]);
  nlohmann::json m =
      nlohmann::json::parse(std::string(f.begin() + ptrdiff_t(meta_off), f.begin() + ptrdiff_t(meta_off + meta_size)));
  m["parameters"][key] = value;
  m["producer"]["name"] = "mb";
  Bytes out = f;
  test::replace_metadata(out, m.dump());
  return out;
}

// The first section holding `type` elements, or -1.
int first_section_of(const Bytes& f, ElementType type) {
  const Asset a = Asset::parse(f, "valid");
  for (size_t i = 0; i < a.sections().size(); ++i)
    if (a.sections()[i].type == type && a.sections()[i].byte_length > 0) return int(i);
  return -1;
}

void add_asset_cases(std::vector<CorpusCase>& cases) {
  for (const std::string kind : kKinds) {
    const Bytes valid = read_bytes(corpus().path("valid." + kind + ".mbk"));
    const std::string stem = "bad." + kind;
    // Damage the checksums see: every command refuses it before looking inside.
    const std::pair<std::string, Bytes> unsealed[] = {
        {"empty", {}},
        {"header_only", Bytes(valid.begin(), valid.begin() + 64)},
        {"half", Bytes(valid.begin(), valid.begin() + ptrdiff_t(valid.size() / 2))},
        {"extended",
         [&] {
           Bytes b = valid;
           b.resize(b.size() + 64, 0);
           return b;
         }()},
        {"data_byte_flipped",
         [&] {
           Bytes b = valid;
           b[b.size() - 1] ^= 0x5a;
           return b;
         }()},
        {"header_byte_flipped",
         [&] {
           Bytes b = valid;
           b[20] ^= 0x01;
           return b;
         }()},
    };
    const std::map<std::string, std::pair<std::string, std::string>> expected_error = {
        // name -> (info's first words, validate's finding)
        {"empty", {"invalid asset: [1001]", "error 1001"}},
        {"header_only", {"invalid asset: [1004]", "error 1004"}},
        {"half", {"invalid asset: [1004]", "error 1004"}},
        {"extended", {"invalid asset: [1004]", "error 1004"}},
        {"data_byte_flipped", {"a section checksum does not match", "error 3"}},
        {"header_byte_flipped", {"invalid asset: [1004]", "error 1004"}},  // byte 20: the recorded file size
    };
    for (const auto& [name, bytes] : unsealed) {
      const std::string file = stem + "." + name + ".mbk";
      write_bytes(corpus().path(file), bytes);
      const auto& [info_words, finding] = expected_error.at(name);
      cases.push_back({"info_" + kind + "_" + name, {"info", file}, 3, info_words, ""});
      if (name == "half" || name == "data_byte_flipped")
        cases.push_back({"validate_" + kind + "_" + name, {"validate", file}, 3, finding, ""});
    }
    // A required section renamed (resealed): a structurally sound file that is not an asset of its kind.
    {
      const Asset parsed = Asset::parse(valid, "valid");
      const std::string required = parsed.kind().required_sections.front().name;
      Bytes renamed = valid;
      for (size_t i = 0; i < parsed.sections().size(); ++i)
        if (parsed.sections()[i].name == required) renamed[test::entry_offset(renamed, i)] = 'x';
      test::reseal_header(renamed);
      const std::string file = stem + ".required_section_renamed.mbk";
      write_bytes(corpus().path(file), renamed);
      cases.push_back({"info_" + kind + "_required_section_renamed", {"info", file}, 3, "invalid asset: [3", ""});
    }
    // Edits resealed behind the checksums: only the kind's invariants can see them; readers must refuse them as
    // validate does (exit 3), never crash or exit 4.
    std::vector<std::pair<std::string, Bytes>> resealed;
    const nlohmann::json params = Asset::parse(valid, "valid").metadata()["parameters"];
    if (params.contains("levels")) {  // a pyramid of 0 or 7.0 levels once crashed render
      resealed.push_back({"levels_zero", with_parameter(valid, "levels", 0)});
      resealed.push_back({"levels_fraction", with_parameter(valid, "levels", 7.0)});
      resealed.push_back({"levels_string", with_parameter(valid, "levels", "7")});
    }
    if (const int s = first_section_of(valid, ElementType::f32); s >= 0) {
      resealed.push_back({"nan_in_data", test::with_f32_element(valid, size_t(s), 0, std::nanf(""))});
      resealed.push_back(
          {"inf_in_data", test::with_f32_element(valid, size_t(s), 0, std::numeric_limits<float>::infinity())});
    }
    for (const auto& [name, bytes] : resealed) {
      const std::string file = stem + "." + name + ".mbk";
      write_bytes(corpus().path(file), bytes);
      cases.push_back({"validate_" + kind + "_" + name, {"validate", file}, 3, "INVALID", ""});
      if (kind == "graph")
        cases.push_back({"synth_" + name,
                         {"synth", file, "--level", "0", "--window", "0,0,4,4", "-q", "-o", "synth_" + name + ".png"},
                         3,
                         "invalid asset: [",
                         "synth_" + name + ".png"});
    }
  }
}

// Damaged assets where render finds them: the baked assets of two scenes, each replaced by a damaged copy.
void add_render_cases(std::vector<CorpusCase>& cases) {
  for (const std::string scene : {"filtered_ndf_scene", "colormap_scene"}) {
    const fs::path folder = corpus().path(scene + ".assets");
    std::vector<fs::path> assets;
    for (const auto& e : fs::directory_iterator(folder))
      if (e.path().extension() == ".mbk") assets.push_back(e.path());
    std::sort(assets.begin(), assets.end());
    for (const fs::path& asset : assets) {
      const Bytes valid = read_bytes(asset);
      const std::string kind = Asset::parse(valid, asset.string()).kind().name.data();
      const int s = first_section_of(valid, ElementType::f32);
      std::vector<std::pair<std::string, Bytes>> damaged = {
          {"truncated", Bytes(valid.begin(), valid.begin() + ptrdiff_t(valid.size() / 2))}};
      if (s >= 0) damaged.push_back({"nan", test::with_f32_element(valid, size_t(s), 0, std::nanf(""))});
      if (Asset::parse(valid, "valid").metadata()["parameters"].contains("levels"))
        damaged.push_back({"levels_zero", with_parameter(valid, "levels", 0)});
      for (const auto& [name, bytes] : damaged) {
        const std::string case_folder = scene + "." + kind + "." + name + ".assets";
        fs::create_directories(corpus().path(case_folder));
        for (const fs::path& other : assets)
          fs::copy_file(other, corpus().path(case_folder) / other.filename(), fs::copy_options::overwrite_existing);
        write_bytes(corpus().path(case_folder) / asset.filename(), bytes);
        const std::string out = "render_" + scene + "_" + kind + "_" + name + ".png";
        cases.push_back({"render_" + scene + "_" + kind + "_" + name,
                         {"render", scene + ".json", "--assets", case_folder, "-q", "-o", out},
                         3,
                         kind + " asset of ",  // "of effect 'x'" or "of the baseline"
                         out});
      }
    }
  }
}

// --- images --------------------------------------------------------------------------------------------------

void save(const std::string& file, uint32_t w, uint32_t h, uint32_t c, const std::function<float(size_t)>& value,
          ImageSaveOptions options = {}) {
  Image image;
  image.width = w;
  image.height = h;
  image.channels = c;
  image.pixels.resize(size_t(w) * h * c);
  for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = value(i);
  save_image(corpus().path(file), image, options);
}

// The EXR `valid.exr` with its data window (and display window) edited to declare side x side pixels: the header
// is well formed, the pixels are not there.
void write_exr_declaring(const std::string& file, int32_t side) {
  Bytes b = read_bytes(corpus().path("valid.exr"));
  for (const std::string attribute : {"dataWindow", "displayWindow"}) {
    const std::string key = attribute + std::string(1, '\0') + "box2i" + std::string(1, '\0');
    const auto at = std::search(b.begin(), b.end(), key.begin(), key.end());
    if (at == b.end()) throw std::runtime_error("no " + attribute + " in the EXR header");
    const size_t box = size_t(at - b.begin()) + key.size() + 4;  // after the attribute's size
    for (int i = 0; i < 4; ++i) store_le<int32_t>(&b[box + 4 * size_t(i)], i < 2 ? 0 : side - 1);
  }
  write_bytes(corpus().path(file), b);
}

void add_image_cases(std::vector<CorpusCase>& cases) {
  write_text(corpus().path("empty.png"), "");
  write_text(corpus().path("text.png"), "just some text\n");
  fs::create_directories(corpus().path("folder.png"));
  const Bytes png = read_bytes(corpus().path("bumps.png"));
  write_bytes(corpus().path("truncated.png"), Bytes(png.begin(), png.begin() + ptrdiff_t(png.size() / 2)));
  Bytes flipped = png;
  for (size_t i = 60; i < flipped.size(); i += 7) flipped[i] ^= 0xff;
  write_bytes(corpus().path("scrambled.png"), flipped);
  const Bytes exr = read_bytes(corpus().path("valid.exr"));
  write_bytes(corpus().path("truncated.exr"), Bytes(exr.begin(), exr.begin() + ptrdiff_t(exr.size() / 2)));
  write_exr_declaring("huge.exr", 16385);
  save("tall.exr", 1, 16385, 3, [](size_t i) { return float(i % 3) / 2; });
  save("wide.exr", 16385, 1, 3, [](size_t i) { return float(i % 3) / 2; });
  // Normal maps whose texels are not normals (stored as float EXR, so the values arrive as they are).
  save("nan.exr", 8, 8, 3, [](size_t i) { return i == 12 ? std::nanf("") : (i % 3 == 2 ? 1.0f : 0.0f); });
  save("inf.exr", 8, 8, 3, [](size_t i) { return i == 5 ? INFINITY : (i % 3 == 2 ? 1.0f : 0.0f); });
  save("zero.exr", 8, 8, 3, [](size_t) { return 0.0f; });
  save("below.exr", 8, 8, 3, [](size_t i) { return i % 3 == 2 ? -1.0f : 0.0f; });

  struct ImageInput {
    std::string file;
    int exit_code;
    std::string first_words;
  };
  const ImageInput inputs[] = {
      {"absent.png", 2, "file not found"},
      {"folder.png", 2, "is a folder"},
      {"empty.png", 3, "not a readable image"},
      {"text.png", 3, "not a readable image"},
      {"truncated.png", 3, "cannot decode image"},
      {"scrambled.png", 3, ""},
      {"truncated.exr", 3, ""},
      {"huge.exr", 3, ""},
  };
  const std::vector<std::vector<std::string>> commands = {
      {"mip"}, {"sh", "--order", "2"}, {"vmf", "--max-iterations", "3"}, {"lut"}, {"rmq", "--patch", "4"}, {"moments"}};
  for (const auto& command : commands)
    for (const ImageInput& in : inputs) {
      // every damaged image through mip; the others read images through the same loader, so fewer suffice
      if (command[0] != "mip" && in.file != "folder.png" && in.file != "empty.png" && in.file != "truncated.png")
        continue;
      std::vector<std::string> args = command;
      const std::string out = command[0] + "_" + in.file + ".mbk";
      args.insert(args.begin() + 1, in.file);
      args.insert(args.end(), {"-q", "-o", out});
      cases.push_back({command[0] + "_" + in.file, args, in.exit_code, in.first_words, out});
    }
  // Colour maps, crease inputs and compare read images too.
  for (const ImageInput& in : inputs) {
    const std::string out = "colormap_" + in.file + ".mbk";
    cases.push_back({"colormap_" + in.file, {"colormap", in.file, "-q", "-o", out}, in.exit_code, in.first_words, out});
    const std::string crease_out = "crease_" + in.file + ".mbk";
    cases.push_back({"crease_" + in.file,
                     {"crease", in.file, "--curves", "panels.json", "-q", "-o", crease_out},
                     in.exit_code,
                     in.first_words,
                     crease_out});
    cases.push_back({"compare_a_" + in.file, {"compare", in.file, "valid.exr"}, in.exit_code, in.first_words, ""});
  }
  // Texels that are not normals, for every command that reads a normal map.
  for (const auto& command : commands) {
    // a driver image is not a normal map (any finite value is data); lut and rmq load maps as mip does
    if (command[0] == "moments" || command[0] == "lut" || command[0] == "rmq") continue;
    for (const std::string bad : {"nan.exr", "inf.exr", "zero.exr", "below.exr"}) {
      std::vector<std::string> args = command;
      const std::string out = command[0] + "_" + bad + ".mbk";
      args.insert(args.begin() + 1, bad);
      args.insert(args.end(), {"-q", "-o", out});
      cases.push_back({command[0] + "_" + bad, args, 3, "", out});
    }
  }
  cases.push_back({"moments_nan.exr", {"moments", "nan.exr", "-q", "-o", "m_nan.mbk"}, 3, "", "m_nan.mbk"});
}

// --- JSON and SVG ----------------------------------------------------------------------------------------------

void add_text_cases(std::vector<CorpusCase>& cases) {
  const std::string deep_array = std::string(100000, '[');
  const std::pair<std::string, std::string> hostile_json[] = {
      {"empty", ""},
      {"not_json", "this is not json"},
      {"truncated", "{\"camera\": {\"position\": [0, 1"},
      {"array_top", "[1, 2, 3]"},
      {"deep", "{\"a\": " + deep_array},
      {"deep_objects",
       [] {
         std::string s;
         for (int i = 0; i < 50000; ++i) s += "{\"a\":";
         return s;
       }()},
      {"huge_number", "{\"camera\": 1e400}"},
      {"duplicate_keys", "{\"camera\": {}, \"camera\": {}}"},
      {"nul_byte", std::string("{\"a\": \"x\0y\"}", 12)},
      {"oversize", "{\"pad\": \"" + std::string(17 << 20, 'x') + "\"}"},
  };
  struct JsonReader {
    std::string name;
    std::vector<std::string> args;  // "IN" stands for the file
    std::string output;
  };
  const JsonReader readers[] = {
      {"render", {"render", "IN", "-q", "-o", "OUT.png"}, "OUT.png"},
      {"bake", {"bake", "IN", "-q", "--out-dir", "OUT.assets"}, "OUT.assets"},
      {"colormap", {"colormap", "IN", "-q", "-o", "OUT.mbk"}, "OUT.mbk"},
      {"crease", {"crease", "panels.png", "--curves", "IN", "-q", "-o", "OUT.mbk"}, "OUT.mbk"},
      {"graph", {"graph", "IN", "-q", "-o", "OUT.mbk"}, "OUT.mbk"},
  };
  for (const auto& [name, text] : hostile_json) {
    const std::string file = "hostile_" + name + ".json";
    write_text(corpus().path(file), text);
    for (const JsonReader& r : readers) {
      const std::string out_stem = r.name + "_json_" + name;
      std::vector<std::string> args;
      for (std::string a : r.args) {
        if (a == "IN") a = file;
        if (const size_t at = a.find("OUT"); at != std::string::npos) a.replace(at, 3, out_stem);
        args.push_back(a);
      }
      std::string output = r.output;
      output.replace(output.find("OUT"), 3, out_stem);
      cases.push_back({r.name + "_json_" + name, args, 3, "", output});
    }
  }
  // Valid JSON, hostile values: out of range, wrong types, unknown keys, each with its JSON path.
  const std::pair<std::string, std::string> scenes[] = {
      {"width_zero", R"({"camera": {"position": [0, 1, 3], "look_at": [0, 0, 0], "fov_y": 50, "width": 0,
        "height": 16}, "shapes": [], "materials": {}, "lights": []})"},
      {"width_huge", R"({"camera": {"position": [0, 1, 3], "look_at": [0, 0, 0], "fov_y": 50,
        "width": 99999999999999999999999, "height": 16}, "shapes": [], "materials": {}, "lights": []})"},
      {"fov_nan_string", R"({"camera": {"position": [0, 1, 3], "look_at": [0, 0, 0], "fov_y": "nan", "width": 8,
        "height": 8}, "shapes": [], "materials": {}, "lights": []})"},
      {"position_huge", R"({"camera": {"position": [0, 1e300, 3], "look_at": [0, 0, 0], "fov_y": 50, "width": 8,
        "height": 8}, "shapes": [], "materials": {}, "lights": []})"},
      {"roughness_negative", R"({"camera": {"position": [0, 1, 3], "look_at": [0, 0, 0], "fov_y": 50, "width": 8,
        "height": 8}, "shapes": [], "materials": {"m": {"specular": {"roughness": -1}}}, "lights": []})"},
  };
  for (const auto& [name, text] : scenes) {
    const std::string file = "scene_" + name + ".json";
    write_text(corpus().path(file), text);
    cases.push_back({"render_scene_" + name,
                     {"render", file, "-q", "-o", "scene_" + name + ".png"},
                     3,
                     "",
                     "scene_" + name + ".png"});
  }
  const std::pair<std::string, std::string> graphs[] = {
      {"r_huge", R"({"exemplars": [{"id": "a", "path": "bumps.png"}], "root": "a",
        "edges": [{"source": "a", "destination": "a", "r": 99999999999}]})"},
      {"r_negative", R"({"exemplars": [{"id": "a", "path": "bumps.png"}], "root": "a",
        "edges": [{"source": "a", "destination": "a", "r": -1}]})"},
      {"no_exemplars", R"({"exemplars": [], "root": "a", "edges": []})"},
      {"path_empty", R"({"exemplars": [{"id": "a", "path": ""}], "root": "a", "edges": []})"},
  };
  for (const auto& [name, text] : graphs) {
    const std::string file = "graph_" + name + ".json";
    write_text(corpus().path(file), text);
    cases.push_back(
        {"graph_" + name, {"graph", file, "-q", "-o", "graph_" + name + ".mbk"}, 3, "", "graph_" + name + ".mbk"});
  }
  // Hostile SVG.
  const std::pair<std::string, std::string> svgs[] = {
      {"entity_expansion",
       "<?xml version=\"1.0\"?>\n<!DOCTYPE svg [<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;&a;&a;&a;\">]>\n"
       "<svg viewBox=\"0 0 32 32\"><path d=\"&b;\"/></svg>\n"},
      {"deep_groups", "<svg viewBox=\"0 0 32 32\">\n" +
                          [] {
                            std::string s;
                            for (int i = 0; i < 20000; ++i) s += "<g>";
                            return s;
                          }()},
      {"huge_path", "<svg viewBox=\"0 0 32 32\"><path d=\"M1 1" +
                        [] {
                          std::string s;
                          for (int i = 0; i < 200000; ++i) s += " L" + std::to_string(1 + i % 30) + " 40";
                          return s;
                        }() +
                        "\"/></svg>"},
      {"unterminated", "<svg viewBox=\"0 0 32 32\"><path d=\"M1 1 L5 5"},
      {"circle", "<svg viewBox=\"0 0 32 32\"><circle r=\"3\"/></svg>"},
      {"curve_command", "<svg viewBox=\"0 0 32 32\"><path d=\"M1 1 C 2 2 3 3 4 4\"/></svg>"},
      {"nan_coordinate", "<svg viewBox=\"0 0 32 32\"><path d=\"M1 1 L nan 5\"/></svg>"},
      {"not_svg_root", "<html><path d=\"M1 1 L5 5\"/></html>"},
      {"empty", ""},
  };
  for (const auto& [name, text] : svgs) {
    const std::string file = "hostile_" + name + ".svg";
    write_text(corpus().path(file), text);
    const std::string out = "crease_svg_" + name + ".mbk";
    cases.push_back({"crease_svg_" + name, {"crease", "panels.png", "--curves", file, "-q", "-o", out}, 3, "", out});
  }
  // Colour stops.
  const std::pair<std::string, std::string> stops[] = {
      {"one_stop", R"({"stops": [{"at": 0, "color": 0.5}]})"},
      {"three_at_one_place", R"({"stops": [{"at": 0, "color": 0}, {"at": 0, "color": 1}, {"at": 0, "color": 0.5},
        {"at": 1, "color": 1}]})"},
      {"color_above_one", R"({"stops": [{"at": 0, "color": 2}, {"at": 1, "color": 1}]})"},
      {"at_huge", R"({"stops": [{"at": 0, "color": 0}, {"at": 1e308, "color": 1}]})"},
      {"descending", R"({"stops": [{"at": 1, "color": 0}, {"at": 0, "color": 1}]})"},
      {"too_many",
       [] {
         std::string s = R"({"stops": [)";
         for (int i = 0; i < 200000; ++i)
           s += (i ? "," : "") + std::string(R"({"at": )") + std::to_string(i) + R"(, "color": 0.5})";
         return s + "]}";
       }()},
  };
  for (const auto& [name, text] : stops) {
    const std::string file = "stops_" + name + ".json";
    write_text(corpus().path(file), text);
    const std::string out = "colormap_stops_" + name + ".mbk";
    cases.push_back({"colormap_stops_" + name, {"colormap", file, "-q", "-o", out}, 3, "", out});
  }
}

// --- command-line values -------------------------------------------------------------------------------------

void add_command_line_cases(std::vector<CorpusCase>& cases) {
  struct Bad {
    std::vector<std::string> args;
    std::string output;
  };
  const std::vector<std::pair<std::string, Bad>> bad = {
      {"gen_size_zero", {{"gen", "bumps", "--size", "0", "-o", "o1.png"}, "o1.png"}},
      {"gen_size_negative", {{"gen", "bumps", "--size", "-1", "-o", "o2.png"}, "o2.png"}},
      {"gen_size_1e309", {{"gen", "bumps", "--size", "1e309", "-o", "o3.png"}, "o3.png"}},
      {"gen_size_nan", {{"gen", "bumps", "--size", "nan", "-o", "o4.png"}, "o4.png"}},
      {"gen_size_huge", {{"gen", "bumps", "--size", "99999999999", "-o", "o5.png"}, "o5.png"}},
      {"gen_seed_negative", {{"gen", "bumps", "--seed", "-1", "-o", "o6.png"}, "o6.png"}},
      {"gen_seed_empty", {{"gen", "bumps", "--seed", "", "-o", "o7.png"}, "o7.png"}},
      {"gen_unknown_kind", {{"gen", "frobs", "-o", "o8.png"}, "o8.png"}},
      {"gen_bad_extension", {{"gen", "bumps", "--size", "8", "-o", "o9.frob"}, "o9.frob"}},
      {"mip_threads_negative", {{"mip", "bumps.png", "--threads", "-1", "-o", "o10.mbk"}, "o10.mbk"}},
      {"mip_threads_huge", {{"mip", "bumps.png", "--threads", "99999999999", "-o", "o11.mbk"}, "o11.mbk"}},
      {"mip_threads_nan", {{"mip", "bumps.png", "--threads", "nan", "-o", "o12.mbk"}, "o12.mbk"}},
      {"mip_output_not_mbk", {{"mip", "bumps.png", "-o", "o13.png"}, "o13.png"}},
      {"mip_convention_bad", {{"mip", "bumps.png", "--convention", "+Z", "-o", "o15.mbk"}, "o15.mbk"}},
      {"sh_order_negative", {{"sh", "bumps.png", "--order", "-1", "-o", "o16.mbk"}, "o16.mbk"}},
      {"sh_order_huge", {{"sh", "bumps.png", "--order", "1000", "-o", "o17.mbk"}, "o17.mbk"}},
      {"vmf_lobes_zero", {{"vmf", "bumps.png", "--lobes", "0", "-o", "o18.mbk"}, "o18.mbk"}},
      {"vmf_align_nan", {{"vmf", "bumps.png", "--align", "nan", "-o", "o19.mbk"}, "o19.mbk"}},
      {"vmf_align_inf", {{"vmf", "bumps.png", "--align", "inf", "-o", "o20.mbk"}, "o20.mbk"}},
      {"vmf_tolerance_nan", {{"vmf", "bumps.png", "--tolerance", "nan", "-o", "o21.mbk"}, "o21.mbk"}},
      {"vmf_tolerance_1e309", {{"vmf", "bumps.png", "--tolerance", "1e309", "-o", "o22.mbk"}, "o22.mbk"}},
      {"lut_size_zero", {{"lut", "bumps.png", "--size", "0", "-o", "o23.mbk"}, "o23.mbk"}},
      {"rmq_patch_three", {{"rmq", "bumps.png", "--patch", "3", "-o", "o24.mbk"}, "o24.mbk"}},
      {"rmq_bits_seven", {{"rmq", "bumps.png", "--bits", "7", "-o", "o25.mbk"}, "o25.mbk"}},
      {"colormap_sigma_nan", {{"colormap", "stripes.json", "--sigma-max", "nan", "-o", "o26.mbk"}, "o26.mbk"}},
      {"colormap_sigma_negative", {{"colormap", "stripes.json", "--sigma-max", "-1", "-o", "o27.mbk"}, "o27.mbk"}},
      {"colormap_size_zero", {{"colormap", "stripes.json", "--size", "0x0", "-o", "o28.mbk"}, "o28.mbk"}},
      {"colormap_encoding_bad", {{"colormap", "stripes.json", "--encoding", "cmyk", "-o", "o29.mbk"}, "o29.mbk"}},
      {"moments_channel_empty", {{"moments", "bumps.png", "--channel", "", "-o", "o30.mbk"}, "o30.mbk"}},
      {"moments_channel_huge", {{"moments", "bumps.png", "--channel", "99999999999", "-o", "o31.mbk"}, "o31.mbk"}},
      {"crease_band_nan",
       {{"crease", "panels.png", "--curves", "panels.json", "--band", "nan", "-o", "o32.mbk"}, "o32.mbk"}},
      {"crease_band_zero",
       {{"crease", "panels.png", "--curves", "panels.json", "--band", "0", "-o", "o33.mbk"}, "o33.mbk"}},
      {"crease_curves_txt", {{"crease", "panels.png", "--curves", "stripes.txt", "-o", "o34.mbk"}, "o34.mbk"}},
      {"synth_level_empty",
       {{"synth", "valid.graph.mbk", "--level", "", "--window", "0,0,4,4", "-o", "o35.png"}, "o35.png"}},
      {"synth_level_huge",
       {{"synth", "valid.graph.mbk", "--level", "99999999999", "--window", "0,0,4,4", "-o", "o36.png"}, "o36.png"}},
      {"synth_window_nan",
       {{"synth", "valid.graph.mbk", "--level", "0", "--window", "0,0,nan,4", "-o", "o37.png"}, "o37.png"}},
      {"synth_window_too_large",
       {{"synth", "valid.graph.mbk", "--level", "0", "--window", "0,0,65536,65536", "-o", "o38.png"}, "o38.png"}},
      {"synth_jitter_nan",
       {{"synth", "valid.graph.mbk", "--level", "0", "--window", "0,0,4,4", "--jitter", "nan", "-o", "o39.png"},
        "o39.png"}},
      {"render_spp_zero", {{"render", "mip_scene.json", "--spp", "0", "-o", "o40.png"}, "o40.png"}},
      {"render_reference_negative", {{"render", "mip_scene.json", "--reference", "-1", "-o", "o41.png"}, "o41.png"}},
      {"render_seed_negative", {{"render", "mip_scene.json", "--seed", "-1", "-o", "o42.png"}, "o42.png"}},
      {"compare_max_rmse_nan", {{"compare", "valid.exr", "valid.exr", "--max-rmse", "nan"}, ""}},
      {"compare_max_rmse_negative", {{"compare", "valid.exr", "valid.exr", "--max-rmse", "-1"}, ""}},
      {"compare_block_zero", {{"compare", "valid.exr", "valid.exr", "--block", "0"}, ""}},
      {"info_format_xml", {{"info", "valid.mip.mbk", "--format", "xml"}, ""}},
      {"validate_no_file", {{"validate"}, ""}},
  };
  for (const auto& [name, b] : bad) cases.push_back({name, b.args, 1, "", b.output});
  // Commands whose value is fine for the command line but refused by what it reads (exit 3 or 2).
  cases.push_back({"mip_output_folder_missing",
                   {"mip", "bumps.png", "-o", "no/such/o14.mbk"},
                   2,
                   "output folder does not exist",
                   "no/such/o14.mbk"});
  cases.push_back({"synth_not_a_graph",
                   {"synth", "valid.mip.mbk", "--level", "0", "--window", "0,0,4,4", "-o", "o50.png"},
                   3,
                   "expected a 'graph' asset",
                   "o50.png"});
  cases.push_back(
      {"moments_channel_missing", {"moments", "bumps.png", "--channel", "7", "-o", "o51.mbk"}, 3, "", "o51.mbk"});
  cases.push_back(
      {"colormap_tall_exr", {"colormap", "tall.exr", "-o", "o52.mbk"}, 3, "gradient image is 1x16385", "o52.mbk"});
  cases.push_back({"compare_wide_exr", {"compare", "wide.exr", "valid.exr"}, 3, "image is 16385x1", ""});
}

std::vector<CorpusCase> all_cases() {
  std::vector<CorpusCase> cases;
  add_asset_cases(cases);
  add_render_cases(cases);
  add_image_cases(cases);
  add_text_cases(cases);
  add_command_line_cases(cases);
  return cases;
}

// Runs every case, a few at a time (most of a case's time is the process starting), and checks each.
TEST(MalformedCorpus, EveryCaseFailsCleanlyWithItsExitCode) {
  const std::vector<CorpusCase> cases = all_cases();
  EXPECT_GE(cases.size(), 200u);
  constexpr size_t kInFlight = 4;
  for (size_t first = 0; first < cases.size(); first += kInFlight) {
    std::vector<pid_t> running;
    for (size_t i = first; i < std::min(first + kInFlight, cases.size()); ++i)
      running.push_back(test::spawn_microbake(cases[i].args, corpus().dir(),
                                              ".case" + std::to_string(i - first) + "_out",
                                              ".case" + std::to_string(i - first) + "_err"));
    for (size_t k = 0; k < running.size(); ++k) {
      const CorpusCase& c = cases[first + k];
      SCOPED_TRACE(c.name);
      test::Run r = test::wait_for(running[k]);
      r.out = test::file_text(corpus().path(".case" + std::to_string(k) + "_out"));
      r.err = test::file_text(corpus().path(".case" + std::to_string(k) + "_err"));
      std::string command = "microbake";
      for (const std::string& a : c.args) command += " '" + (a.size() > 60 ? a.substr(0, 57) + "..." : a) + "'";
      EXPECT_FALSE(r.timed_out) << command << ": still running after " << kCaseSeconds << " s";
      EXPECT_EQ(r.signal, 0) << command << ": killed by signal " << r.signal << "\n" << r.err;
      EXPECT_EQ(r.exit_code, c.exit_code) << command << "\nstdout: " << r.out.substr(0, 400) << "\nstderr: " << r.err;
      if (c.args.front() == "validate" && c.exit_code == 3) {
        EXPECT_EQ(r.err, "") << command;
        EXPECT_NE(r.out.find("INVALID"), std::string::npos) << command << ": " << r.out;
        EXPECT_NE(r.out.find(c.first_words), std::string::npos) << command << ": " << r.out;
      } else {
        const std::string prefix = "microbake: error: " + c.first_words;
        EXPECT_EQ(r.err.compare(0, prefix.size(), prefix), 0)
            << command << ": stderr should start with '" << prefix << "':\n"
            << r.err;
        const bool one_line = !r.err.empty() && r.err.back() == '\n' && r.err.find('\n') == r.err.size() - 1;
        EXPECT_TRUE(one_line) << command << ": stderr must be one line:\n" << r.err;
        EXPECT_TRUE(r.err.size() >= 2 && r.err[r.err.size() - 2] == ')')
            << command << ": the error must end with its location '(<where>)':\n"
            << r.err;
      }
      if (!c.output.empty()) {
        EXPECT_FALSE(fs::exists(corpus().path(c.output))) << command << " left " << c.output;
      }
    }
  }
  for (const auto& e : fs::directory_iterator(corpus().dir()))
    EXPECT_EQ(e.path().filename().string().find(".partial-"), std::string::npos)
        << "a temporary was left: " << e.path();
  std::printf("%zu malformed-input cases\n", cases.size());
}

// bake's freshness check reads existing assets as validate does: a resealed edit that only the kind's invariants
// see makes the asset stale, and bake rebuilds it instead of keeping it as "up to date".
TEST(MalformedCorpus, BakeRebuildsAnAssetThatValidateRejects) {
  const fs::path folder = corpus().path("colormap_scene.assets");
  for (const auto& e : fs::directory_iterator(folder)) {
    if (e.path().extension() != ".mbk") continue;
    SCOPED_TRACE(e.path().filename().string());
    const Bytes valid = read_bytes(e.path());
    const int s = first_section_of(valid, ElementType::f32);
    ASSERT_GE(s, 0);
    write_bytes(e.path(), test::with_f32_element(valid, size_t(s), 0, std::nanf("")));
    const test::Run damaged = run_microbake({"validate", e.path().string()}, corpus().dir());
    EXPECT_EQ(damaged.exit_code, 3) << damaged.out;
    const test::Run bake = run_microbake({"bake", "colormap_scene.json"}, corpus().dir());
    EXPECT_EQ(bake.exit_code, 0) << bake.err;
    EXPECT_NE(bake.out.find("rebuilt " + e.path().filename().string()), std::string::npos) << bake.out;
    EXPECT_EQ(read_bytes(e.path()), valid) << "the rebuilt asset should be the asset baked before";
  }
}

}  // namespace
}  // namespace mbk
