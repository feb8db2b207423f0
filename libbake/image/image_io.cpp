// image_io.h through the image I/O module (libbake/image/image_io_module.h), loaded on first use: from the folder
// of the running executable, else from the build folder it was built in (MICROBAKE_IMAGE_IO_DIR: the test and
// example executables live in subfolders of it). A module that cannot be loaded is an I/O failure (exit 2) naming
// every path tried and why.
#include "libbake/image/image_io.h"

#include <dlfcn.h>

#include <system_error>
#include <thread>

#include "formats/error.h"
#include "libbake/image/image_io_module.h"

namespace mbk {
namespace {

// Loaded once; a failed load is retried by the next call, which fails the same way.
const ImageIoModule& image_io_module(const std::filesystem::path& image) {
  static const ImageIoModule* module = [&] {
    std::error_code ec;
    const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", ec);
    std::vector<std::filesystem::path> folders;
    if (!ec) folders.push_back(executable.parent_path());
    folders.emplace_back(MICROBAKE_IMAGE_IO_DIR);
    return &load_image_io_module(folders, image);
  }();
  return *module;
}

// The thread of start_loading_image_io, joined at exit (a process never ends inside dlopen).
struct BackgroundLoad {
  std::thread thread;
  ~BackgroundLoad() {
    if (thread.joinable()) thread.join();
  }
};

}  // namespace

void start_loading_image_io() {
  static BackgroundLoad load;
  if (load.thread.joinable()) return;
  load.thread = std::thread([] {
    try {
      (void)image_io_module({});
    } catch (const Error&) {  // the next image call tries again and reports it, naming its file
    }
  });
}

const ImageIoModule& load_image_io_module(const std::vector<std::filesystem::path>& folders,
                                          const std::filesystem::path& image) {
  std::string tried;
  for (const std::filesystem::path& folder : folders) {
    const std::filesystem::path file = folder / kImageIoModuleFile;
    if (!tried.empty()) tried += "; ";
    if (void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL)) {
      using Entry = const ImageIoModule* (*)();
      const auto entry = reinterpret_cast<Entry>(::dlsym(handle, kImageIoModuleEntry));
      if (entry && entry()->abi == kImageIoModuleAbi) return *entry();
      ::dlclose(handle);
      tried += file.string() + ": not the image module of this build";
    } else {
      const char* why = ::dlerror();
      tried += why ? why : file.string() + ": cannot be loaded";
    }
  }
  throw Error(ExitCode::io_failure,
              std::string("cannot load the image library ") + kImageIoModuleFile +
                  " (it belongs beside the microbake executable): " + (tried.empty() ? "no folder to look in" : tried),
              image.string());
}

ImageHeader read_image_header(const std::filesystem::path& path) { return image_io_module(path).read_header(path); }

Image load_image(const std::filesystem::path& path, ImageFileInfo* info) {
  return image_io_module(path).load(path, info);
}

void save_image(const std::filesystem::path& path, const Image& image, const ImageSaveOptions& options,
                const std::filesystem::path& format_path) {
  image_io_module(path).save(path, image, options, format_path);
}

ImageHeader read_image_header_within(const std::filesystem::path& path, uint32_t max_side, const std::string& what) {
  const ImageHeader header = read_image_header(path);
  if (header.width > max_side || header.height > max_side)
    throw Error(ExitCode::invalid_input,
                what + " is " + std::to_string(header.width) + "x" + std::to_string(header.height) +
                    " texels; each side may be at most " + std::to_string(max_side),
                path.string());
  return header;
}

}  // namespace mbk
