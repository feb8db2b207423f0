// Outputs appear only when complete: a temporary beside the destination, renamed on commit, removed when
// abandoned; failures are io_failure errors and leave nothing behind.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "formats/atomic_file.h"
#include "formats/error.h"
#include "tests/formats/asset_fixtures.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {
namespace fs = std::filesystem;

class AtomicFileTest : public ::testing::Test {
 protected:
  size_t entries() const { return size_t(std::distance(fs::directory_iterator(dir_), fs::directory_iterator())); }
  test::ScratchDir scratch_;
  const fs::path dir_ = scratch_.path();
};

TEST_F(AtomicFileTest, CommitRenamesIntoPlaceWithSameExtension) {
  const std::vector<uint8_t> bytes = {1, 2, 3};
  {
    AtomicFile f(dir_ / "out.mbk");
    EXPECT_EQ(f.temporary_path().parent_path(), dir_);
    EXPECT_EQ(f.temporary_path().extension(), ".mbk");
    f.write_all(bytes);
    EXPECT_FALSE(fs::exists(dir_ / "out.mbk"));
    f.commit();
  }
  EXPECT_EQ(read_file_bytes(dir_ / "out.mbk"), bytes);
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, AbandonedWriteLeavesNothingAndKeepsOldFile) {
  { std::ofstream(dir_ / "out.png") << "old"; }
  {
    AtomicFile f(dir_ / "out.png");
    f.write_all(std::vector<uint8_t>{9, 9});
    // no commit: as if the command failed after writing
  }
  EXPECT_EQ(entries(), 1u);
  auto old = read_file_bytes(dir_ / "out.png");
  EXPECT_EQ(std::string(old.begin(), old.end()), "old");
}

// Streamed writing: appended pieces in order, a header overwritten at the start after them; nothing at the
// destination before commit(), nothing at all when abandoned.
TEST_F(AtomicFileTest, AppendedPiecesAndAnOverwrittenHeadCommitAsOneFile) {
  {
    AtomicFile f(dir_ / "out.mbk");
    f.append(std::vector<uint8_t>{0, 0, 0});
    f.append(std::vector<uint8_t>{4, 5});
    f.append(std::vector<uint8_t>{});
    f.overwrite(0, std::vector<uint8_t>{1, 2});
    f.append(std::vector<uint8_t>{6});  // after an overwrite, appending continues at the end
    EXPECT_FALSE(fs::exists(dir_ / "out.mbk"));
    f.commit();
  }
  EXPECT_EQ(read_file_bytes(dir_ / "out.mbk"), (std::vector<uint8_t>{1, 2, 0, 4, 5, 6}));
  EXPECT_EQ(entries(), 1u);
  {
    AtomicFile f(dir_ / "other.mbk");
    f.append(std::vector<uint8_t>{1});
  }
  EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFileTest, MissingFolderIsAnIoFailure) {
  try {
    AtomicFile f(dir_ / "no" / "such" / "out.mbk");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::io_failure);
  }
}

TEST_F(AtomicFileTest, CommitWithoutWriteFails) {
  AtomicFile f(dir_ / "out.mbk");
  EXPECT_THROW(f.commit(), Error);
  EXPECT_EQ(entries(), 0u);
}

TEST_F(AtomicFileTest, ReadMissingFileIsAnIoFailure) {
  try {
    read_file_bytes(dir_ / "absent.mbk");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ExitCode::io_failure);
    EXPECT_NE(e.where().find("absent.mbk"), std::string::npos);
  }
}

TEST_F(AtomicFileTest, WriterOutputReadsBack) {
  test::mip_writer(4, 4).write(dir_ / "a.mbk");
  EXPECT_EQ(read_file_bytes(dir_ / "a.mbk"), test::valid_mip_bytes(4, 4));
  EXPECT_EQ(entries(), 1u);
}

// A pid that no process has: a child that has exited and been reaped.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

TEST_F(AtomicFileTest, StaleTemporaryOfADeadProcessIsRemovedByTheNextWriter) {
  const std::string dead = std::to_string(dead_pid()), alive = std::to_string(::getppid());
  const fs::path stale = dir_ / (".out.partial-" + dead + "-0.png");
  const fs::path live = dir_ / (".out.partial-" + alive + "-3.png");          // a writer that is still running
  const fs::path other = dir_ / (".other.partial-" + dead + "-0.png");        // another destination's
  const fs::path lookalike = dir_ / (".out.partial-" + dead + "-0.png.bak");  // not a temporary name
  for (const fs::path& p : {stale, live, other, lookalike}) std::ofstream(p) << "partial";
  {
    AtomicFile f(dir_ / "out.png");
    f.write_all(std::vector<uint8_t>{1});
    f.commit();
  }
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other));
  EXPECT_TRUE(fs::exists(lookalike));
  EXPECT_TRUE(fs::exists(dir_ / "out.png"));
}

}  // namespace
}  // namespace mbk
