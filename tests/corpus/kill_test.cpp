// Whole-or-nothing outputs under SIGKILL and concurrent writers (formats/atomic_file.h). Each trial starts a
// command that writes over an existing valid output, kills it with SIGKILL at a pseudo-random moment of its run,
// and checks that the destination is the old file intact or the complete new one, byte for byte. A killed command
// cannot clean up, so its temporary may stay until the next command writing the same output starts: each trial
// checks that at most the last killed run's temporary is present, and after a final complete run none is. Two
// commands racing to write one output leave one complete file, whichever finished last; two bakes racing on one
// shared asset folder leave the files one bake writes.
#include <gtest/gtest.h>

#include <signal.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "tests/corpus/run_microbake.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {
namespace fs = std::filesystem;

struct Writer {
  std::string name;
  std::vector<std::string> old_args, new_args;  // "OUT" stands for the destination
  std::string destination;
};

std::vector<std::string> with_output(const std::vector<std::string>& args, const std::string& out) {
  std::vector<std::string> r;
  for (const std::string& a : args) r.push_back(a == "OUT" ? out : a);
  return r;
}

size_t temporaries_of(const fs::path& dir, const std::string& destination) {
  const std::string prefix = "." + fs::path(destination).stem().string() + ".partial-";
  size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string().rfind(prefix, 0) == 0;
  return n;
}

class KillTest : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"gen", "bumps", "--size", "512", "-q", "-o", "a.png"},
             {"gen", "scratches", "--size", "512", "--seed", "3", "-q", "-o", "b.png"}}) {
      const test::Run r = test::run_microbake(args, dir_.path());
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
  }
  // The bytes `args` write to `out` when left to finish.
  std::string complete_output(const std::vector<std::string>& args, const std::string& out) {
    const test::Run r = test::run_microbake(with_output(args, out), dir_.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return test::file_text(dir_.path() / out);
  }
  test::ScratchDir dir_{"kill"};
};

TEST_F(KillTest, SigkillLeavesTheOldFileOrTheCompleteNewOne) {
  const Writer writers[] = {
      {"mip", {"mip", "b.png", "-q", "-o", "OUT"}, {"mip", "a.png", "-q", "-o", "OUT"}, "pyramid.mbk"},
      {"sh",
       {"sh", "b.png", "--order", "4", "-q", "-o", "OUT"},
       {"sh", "a.png", "--order", "4", "-q", "-o", "OUT"},
       "ndf.mbk"},
      {"gen_png",
       {"gen", "bumps", "--size", "1024", "-q", "-o", "OUT"},
       {"gen", "scratches", "--size", "1024", "-q", "-o", "OUT"},
       "map.png"},
      {"gen_exr",
       {"gen", "bumps", "--size", "1024", "-q", "-o", "OUT"},
       {"gen", "flakes", "--size", "1024", "-q", "-o", "OUT"},
       "map.exr"},
      {"moments", {"moments", "b.png", "-q", "-o", "OUT"}, {"moments", "a.png", "-q", "-o", "OUT"}, "moments.mbk"},
  };
  constexpr int kTrialsPerWriter = 12;
  int trials = 0, old_kept = 0, new_complete = 0;
  for (const Writer& w : writers) {
    SCOPED_TRACE(w.name);
    const std::string old_bytes = complete_output(w.old_args, "old_" + w.destination);
    const std::string new_bytes = complete_output(w.new_args, "new_" + w.destination);
    ASSERT_NE(old_bytes, new_bytes);
    // How long an uninterrupted run takes: kills are spread over it (startup, reading, baking, writing).
    const auto start = std::chrono::steady_clock::now();
    complete_output(w.new_args, "timed_" + w.destination);
    const double run_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    fs::copy_file(dir_.path() / ("old_" + w.destination), dir_.path() / w.destination,
                  fs::copy_options::overwrite_existing);
    for (int t = 0; t < kTrialsPerWriter; ++t, ++trials) {
      // Moments from 5% to 115% of a run, in a scrambled order (a fixed sequence: reruns kill at the same moments).
      const double fraction = 0.05 + 1.1 * double((t * 7) % kTrialsPerWriter) / kTrialsPerWriter;
      const pid_t child = test::spawn_microbake(with_output(w.new_args, w.destination), dir_.path());
      std::this_thread::sleep_for(std::chrono::microseconds(int64_t(fraction * run_ms * 1000.0)));
      ::kill(child, SIGKILL);
      test::wait_for(child);
      const std::string now = test::file_text(dir_.path() / w.destination);
      EXPECT_TRUE(now == old_bytes || now == new_bytes)
          << "trial " << t << " (killed at " << fraction * 100 << "% of a run): the destination is neither the old "
          << "file nor the complete new one (" << now.size() << " bytes)";
      old_kept += now == old_bytes;
      new_complete += now == new_bytes;
      // This trial's run removed the temporaries of the runs killed before it; its own may remain.
      EXPECT_LE(temporaries_of(dir_.path(), w.destination), 1u) << "trial " << t;
      if (now == new_bytes)  // start the next trial from the old file again
        fs::copy_file(dir_.path() / ("old_" + w.destination), dir_.path() / w.destination,
                      fs::copy_options::overwrite_existing);
    }
    // A complete run cleans up whatever the killed ones left.
    EXPECT_EQ(complete_output(w.new_args, w.destination), new_bytes);
    EXPECT_EQ(temporaries_of(dir_.path(), w.destination), 0u);
  }
  EXPECT_GE(trials, 50);
  std::printf("%d SIGKILL trials: %d kept the old file, %d found the complete new one\n", trials, old_kept,
              new_complete);
}

TEST_F(KillTest, RacingWritersLeaveOneCompleteFile) {
  const std::vector<std::string> a = {"mip", "a.png", "-q", "-o", "OUT"}, b = {"mip", "b.png", "-q", "-o", "OUT"};
  const std::string a_bytes = complete_output(a, "race_a.mbk"), b_bytes = complete_output(b, "race_b.mbk");
  for (int round = 0; round < 4; ++round) {
    const pid_t first = test::spawn_microbake(with_output(round % 2 ? a : b, "race.mbk"), dir_.path());
    const pid_t second = test::spawn_microbake(with_output(round % 2 ? b : a, "race.mbk"), dir_.path());
    const test::Run r1 = test::wait_for(first), r2 = test::wait_for(second);
    EXPECT_EQ(r1.exit_code, 0);
    EXPECT_EQ(r2.exit_code, 0);
    const std::string now = test::file_text(dir_.path() / "race.mbk");
    EXPECT_TRUE(now == a_bytes || now == b_bytes) << "round " << round << ": " << now.size() << " bytes";
    EXPECT_EQ(temporaries_of(dir_.path(), "race.mbk"), 0u) << "round " << round;
  }
}

// The shared-folder case of a cluster (docs/commands/plan.md "Baking a large library"): two `bake`s of one scene into
// one asset folder at once both succeed, and leave exactly the files a bake alone writes, byte for byte, with no
// temporary.
TEST_F(KillTest, RacingBakesOfOneSceneLeaveTheFilesOneBakeWrites) {
  std::ofstream(dir_.path() / "race.json")
      << R"({"camera": {"position": [0, 1.5, 3], "look_at": [0, 0, 0], "fov_y": 45, "width": 8, "height": 6},
            "shapes": [{"type": "plane", "size": [2, 2], "material": "m"}],
            "lights": [{"type": "point", "position": [1, 2, 1], "intensity": 4}],
            "materials": {"m": {"normal_map": {"path": "a.png", "convention": "+Y"},
                                "effects": [{"name": "sh", "order": 4}, "toksvig"]}}})";
  const test::Run solo = test::run_microbake({"bake", "race.json", "--out-dir", "solo", "-q"}, dir_.path());
  ASSERT_EQ(solo.exit_code, 0) << solo.err;
  for (int round = 0; round < 3; ++round) {
    const std::string folder = "shared" + std::to_string(round);
    const pid_t first = test::spawn_microbake({"bake", "race.json", "--out-dir", folder, "-q"}, dir_.path());
    const pid_t second = test::spawn_microbake({"bake", "race.json", "--out-dir", folder, "-q"}, dir_.path());
    EXPECT_EQ(test::wait_for(first).exit_code, 0) << "round " << round;
    EXPECT_EQ(test::wait_for(second).exit_code, 0) << "round " << round;
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir_.path() / "solo")) {
      ++files;
      EXPECT_EQ(test::file_text(dir_.path() / folder / e.path().filename()), test::file_text(e.path()))
          << "round " << round << ": " << e.path().filename();
    }
    EXPECT_EQ(files, 2u);  // sh, and the mip of toksvig and the baseline
    EXPECT_EQ(size_t(std::distance(fs::directory_iterator(dir_.path() / folder), fs::directory_iterator())), files)
        << "round " << round << ": a temporary or another file was left";
  }
}

}  // namespace
}  // namespace mbk
