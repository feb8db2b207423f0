// lower_extension: the one case-insensitive extension every format choice goes through.
#include <gtest/gtest.h>

#include "formats/file_extension.h"

namespace mbk {
namespace {

TEST(FileExtension, LowercasesOnlyTheLastExtension) {
  EXPECT_EQ(lower_extension("out/Map.PNG"), ".png");
  EXPECT_EQ(lower_extension("a.Tar.GZ"), ".gz");
  EXPECT_EQ(lower_extension("DIR.X/file.ExR"), ".exr");
}

TEST(FileExtension, EmptyWithoutAnExtension) {
  EXPECT_EQ(lower_extension("README"), "");
  EXPECT_EQ(lower_extension(".hidden"), "");  // a leading dot names the file, it is not an extension
}

}  // namespace
}  // namespace mbk
