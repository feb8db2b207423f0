// Determinism of every command that writes a file: the same inputs give byte-identical outputs with --threads 1
// and --threads 2, each run twice (docs/ARCHITECTURE.md, "Determinism"). Small inputs, the real executable: what
// a user diffing two runs would see. `bake` is compared file by file over its whole asset folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include "tests/corpus/run_microbake.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {
namespace fs = std::filesystem;

struct Producer {
  std::string name;
  std::vector<std::string> args;  // "OUT" stands for the output path
  std::string extension;          // of the output; "" for a folder (bake --out-dir)
};

class Determinism : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::ScratchDir("determinism");
    const std::string src = MICROBAKE_SOURCE_DIR;
    fs::copy_file(src + "/examples/colormaps/stripes.json", dir_->path() / "cli_stripes.json");
    for (const char* scene : {"filtered_ndf_scene.json", "colormap_scene.json", "mip_scene.json"})
      fs::copy_file(src + "/tests/cli/scenes/" + scene, dir_->path() / scene);
    std::ofstream(dir_->path() / "graph.json")
        << R"({"exemplars": [{"id": "a", "path": "bumps.png"}, {"id": "b", "path": "leather.png"}], "root": "a",
              "edges": [{"source": "a", "destination": "b", "r": 1}, {"source": "b", "destination": "b", "r": 1}]})";
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"gen", "bumps", "--size", "16", "-q", "-o", "bumps.png"},
             {"gen", "leather", "--size", "16", "--seed", "2", "-q", "-o", "leather.png"},
             {"gen", "panels", "--size", "32", "-q", "-o", "panels.png", "--creases", "panels.json"},
             {"graph", "graph.json", "-q", "-o", "graph.mbk"},
             {"bake", "mip_scene.json", "-q"}}) {  // the assets render reads
      const test::Run r = test::run_microbake(args, dir_->path());
      ASSERT_EQ(r.exit_code, 0) << args[0] << ": " << r.err;
    }
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static test::ScratchDir* dir_;
};
test::ScratchDir* Determinism::dir_ = nullptr;

// Every file under `root` (or `root` itself), by relative path, with its bytes.
std::map<std::string, std::string> contents(const fs::path& root) {
  std::map<std::string, std::string> files;
  if (fs::is_regular_file(root)) {
    files[""] = test::file_text(root);
    return files;
  }
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file()) files[fs::relative(e.path(), root).string()] = test::file_text(e.path());
  return files;
}

TEST_F(Determinism, EveryCommandWritesTheSameBytesWhateverTheThreadCount) {
  const Producer producers[] = {
      {"gen", {"gen", "scratches", "--size", "32", "-o", "OUT"}, ".png"},
      {"gen_exr", {"gen", "flakes", "--size", "32", "-o", "OUT"}, ".exr"},
      {"mip", {"mip", "bumps.png", "-o", "OUT"}, ".mbk"},
      {"sh", {"sh", "bumps.png", "--order", "4", "-o", "OUT"}, ".mbk"},
      {"vmf", {"vmf", "bumps.png", "--lobes", "3", "--max-iterations", "20", "-o", "OUT"}, ".mbk"},
      {"vmf_aligned", {"vmf", "bumps.png", "--lobes", "2", "--align", "0.5", "-o", "OUT"}, ".mbk"},
      {"lut", {"lut", "bumps.png", "-o", "OUT"}, ".mbk"},
      {"rmq", {"rmq", "bumps.png", "--patch", "4", "-o", "OUT"}, ".mbk"},
      {"moments", {"moments", "bumps.png", "-o", "OUT"}, ".mbk"},
      {"histogram", {"histogram", "bumps.png", "--method", "exact", "-o", "OUT"}, ".mbk"},
      {"neural_histogram", {"histogram", "bumps.png", "--iterations", "30", "--batch", "100", "-o", "OUT"}, ".mbk"},
      {"colormap", {"colormap", "cli_stripes.json", "--size", "32x16", "-o", "OUT"}, ".mbk"},
      {"crease", {"crease", "panels.png", "--curves", "panels.json", "-o", "OUT"}, ".mbk"},
      {"graph", {"graph", "graph.json", "-o", "OUT"}, ".mbk"},
      {"synth", {"synth", "graph.mbk", "--level", "3", "--window", "5,-3,24,20", "-o", "OUT"}, ".exr"},
      {"bake", {"bake", "filtered_ndf_scene.json", "--out-dir", "OUT"}, ""},
      {"bake_colormap", {"bake", "colormap_scene.json", "--out-dir", "OUT"}, ""},
      {"render", {"render", "mip_scene.json", "-o", "OUT"}, ".exr"},
      {"render_png", {"render", "mip_scene.json", "-o", "OUT"}, ".png"},
      {"render_edges", {"render", "mip_scene.json", "--edge-spp", "9", "-o", "OUT"}, ".exr"},
      {"render_reference", {"render", "mip_scene.json", "--reference", "2", "-o", "OUT"}, ".exr"},
  };
  for (const Producer& p : producers) {
    SCOPED_TRACE(p.name);
    std::map<std::string, std::string> first;
    std::string first_run;
    for (const char* threads : {"1", "2"})
      for (int repeat = 0; repeat < 2; ++repeat) {
        const std::string run = p.name + "_t" + threads + "_" + std::to_string(repeat);
        const std::string out = run + p.extension;
        std::vector<std::string> args;
        for (const std::string& a : p.args) args.push_back(a == "OUT" ? out : a);
        args.insert(args.end(), {"--threads", threads, "-q"});
        const test::Run r = test::run_microbake(args, dir_->path());
        ASSERT_EQ(r.exit_code, 0) << run << ": " << r.err;
        const auto files = contents(dir_->path() / out);
        ASSERT_FALSE(files.empty()) << run << " wrote nothing";
        if (first_run.empty()) {
          first = files;
          first_run = run;
          continue;
        }
        ASSERT_EQ(files.size(), first.size()) << run << " vs " << first_run;
        for (const auto& [name, bytes] : files) {
          ASSERT_TRUE(first.count(name)) << run << " wrote " << name << ", " << first_run << " did not";
          EXPECT_TRUE(bytes == first.at(name)) << run << " and " << first_run << " differ in '" << name << "'";
        }
      }
  }
}

}  // namespace
}  // namespace mbk
