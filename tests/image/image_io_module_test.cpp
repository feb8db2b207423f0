// load_image_io_module (libbake/image/image_io_module.h): the module is found in the first folder that holds it and
// reads images; a folder without it, or with a file of its name that is no module, is an I/O failure whose one line
// names every path tried and why; start_loading_image_io's background load leaves image calls working.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "formats/error.h"
#include "libbake/image/image_io.h"
#include "libbake/image/image_io_module.h"
#include "tests/scratch_dir.h"

namespace mbk {
namespace {

using test::ScratchDir;

const std::filesystem::path kModuleFolder = std::filesystem::path(MICROBAKE_EXE).parent_path();

// The Error load_image_io_module throws for `folders` (fails the test when it loads).
Error load_failure(const std::vector<std::filesystem::path>& folders) {
  try {
    load_image_io_module(folders, "normals.png");
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "the module loaded";
  return Error(ExitCode::runtime_failure, "");
}

TEST(ImageIoModule, FoundInTheFirstFolderThatHoldsItAndReadsImages) {
  const ScratchDir empty("image_io_module_empty");
  const ImageIoModule& module = load_image_io_module({empty.path(), kModuleFolder}, "normals.png");
  EXPECT_EQ(module.abi, kImageIoModuleAbi);
  const ScratchDir dir("image_io_module_reads");
  const Image written{
      3, 2, 3, {0.f, 0.2f, 0.4f, 0.6f, 0.8f, 1.f, 1.f, 0.8f, 0.6f, 0.4f, 0.2f, 0.f, 0.5f, 0.5f, 1.f, 0.f, 0.f, 0.f}};
  module.save(dir.path() / "t.exr", written, ImageSaveOptions{}, {});
  ImageFileInfo info;
  const Image read = module.load(dir.path() / "t.exr", &info);
  EXPECT_EQ(read.pixels, written.pixels);
  EXPECT_TRUE(info.is_float);
}

// start_loading_image_io: the background load, started twice, leaves the library usable by the next image call,
// which waits for it (a command starts it before its bake and writes its image after).
TEST(ImageIoModule, LoadingInTheBackgroundLeavesImageCallsWorking) {
  start_loading_image_io();
  start_loading_image_io();
  ScratchDir dir;
  save_image(dir / "a.exr", Image{2, 1, 1, {0.25f, -3.0f}});
  EXPECT_EQ(load_image(dir / "a.exr").pixels, (std::vector<float>{0.25f, -3.0f}));
}

TEST(ImageIoModule, MissingEverywhereIsAnIoFailureNamingEveryPathTried) {
  const ScratchDir a("image_io_module_a"), b("image_io_module_b");
  const Error e = load_failure({a.path(), b.path()});
  EXPECT_EQ(e.code(), ExitCode::io_failure);
  const std::string message = e.what();
  EXPECT_NE(message.find((a.path() / kImageIoModuleFile).string()), std::string::npos) << message;
  EXPECT_NE(message.find((b.path() / kImageIoModuleFile).string()), std::string::npos) << message;
  EXPECT_NE(message.find("beside the microbake executable"), std::string::npos) << message;
  EXPECT_EQ(e.where(), "normals.png");
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(ImageIoModule, AFileOfItsNameThatIsNoModuleIsRefusedWithTheLoadersReason) {
  const ScratchDir dir("image_io_module_bogus");
  std::ofstream(dir.path() / kImageIoModuleFile) << "not a shared library";
  const Error e = load_failure({dir.path()});
  EXPECT_EQ(e.code(), ExitCode::io_failure);
  const std::string message = e.what();
  EXPECT_NE(message.find((dir.path() / kImageIoModuleFile).string()), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(ImageIoModule, NoFolderToLookInSaysSo) {
  EXPECT_NE(std::string(load_failure({}).what()).find("no folder to look in"), std::string::npos);
}

}  // namespace
}  // namespace mbk
