// Outputs appear only when complete: a temporary beside the destination, renamed on commit, removed when
// abandoned; failures are io_failure errors and leave nothing behind.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace mbk
