// Image reading and writing through OpenImageIO (the contract is libbake/image/image_io.h): the only file that talks to
// OIIO, built alone into the module libmicrobake_image_io.so that libbake/image/image_io.cpp loads on first use, so
// that OpenImageIO's ~260 shared libraries are loaded only by commands that read or write images.
#include "libbake/image/image_io_module.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <mutex>

#include "formats/atomic_file.h"
#include "formats/error.h"
#include "formats/file_extension.h"
#include "libbake/core/huge_pages.h"

namespace mbk {
namespace {

// OpenImageIO's messages may span lines; errors are one line (docs/ARCHITECTURE.md, "Errors").
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text.empty() ? "unknown error" : text;
}

// Codec libraries print some complaints straight to stderr (libpng: "libpng error: IDAT: Read error"), which
// would put a line of theirs before our one error line. While a guard lives, fd 2 points at a temporary file;
// the destructor points it back. OpenImageIO reports the same problems through geterror(), so our message
// carries them; captured() is the fallback when it says nothing. fd 2 belongs to the whole process: one guard
// at a time, and anything another thread prints meanwhile is held back too (image loading happens before the
// work that shows progress). Test: CLI cases MipTruncatedPng, MipTruncatedJpeg.
class QuietStderr {
 public:
  QuietStderr() : lock_(mutex()) {
    std::fflush(stderr);
    sink_ = std::tmpfile();
    saved_ = sink_ ? ::dup(STDERR_FILENO) : -1;
    if (saved_ >= 0 && ::dup2(::fileno(sink_), STDERR_FILENO) < 0) {
      ::close(saved_);
      saved_ = -1;
    }
  }
  ~QuietStderr() {
    restore();
    if (sink_) std::fclose(sink_);
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

  // What was printed to stderr so far (the guard keeps capturing).
  std::string captured() {
    if (!sink_) return {};
    std::fflush(stderr);
    std::string text;
    std::rewind(sink_);
    for (int c; (c = std::fgetc(sink_)) != EOF;) text += char(c);
    return text;
  }

 private:
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    ::dup2(saved_, STDERR_FILENO);
    ::close(saved_);
    saved_ = -1;
  }
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  std::lock_guard<std::mutex> lock_;
  std::FILE* sink_ = nullptr;
  int saved_ = -1;
};

// OpenImageIO's `message`, else what the codec printed, as one line.
std::string codec_message(std::string message, QuietStderr& quiet) {
  return one_line(message.empty() ? quiet.captured() : std::move(message));
}

// Throws "cannot decode image" when a read or close of `in` failed or left a message: a truncated JPEG decodes
// "successfully" (libjpeg fills the rest with grey) and leaves only "Premature end of JPEG file" behind.
void require_decoded(bool ok, OIIO::ImageInput& in, QuietStderr& quiet, const std::filesystem::path& path) {
  std::string message = in.geterror();  // has_error() does not see these messages in OpenImageIO 2.4
  if (ok && message.empty()) return;
  throw Error(ExitCode::invalid_input, "cannot decode image: " + codec_message(std::move(message), quiet),
              path.string());
}

// Missing files, folders and unreadable files are I/O failures (exit 2), distinct from files that exist
// but are not images (exit 3).
void require_readable_file(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw Error(ExitCode::io_failure, "file not found", path.string());
  if (std::filesystem::is_directory(status))
    throw Error(ExitCode::io_failure, "is a folder, not an image file", path.string());
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw Error(ExitCode::io_failure, "cannot open file for reading", path.string());
}

bool is_float_type(OIIO::TypeDesc t) {
  return t.basetype == OIIO::TypeDesc::HALF || t.basetype == OIIO::TypeDesc::FLOAT ||
         t.basetype == OIIO::TypeDesc::DOUBLE;
}

// Opens an image and checks that it is a flat 2-D image microbake can hold. The caller holds `quiet` until the
// image is closed.
std::unique_ptr<OIIO::ImageInput> open_image(const std::filesystem::path& path, ImageHeader& header,
                                             QuietStderr& quiet) {
  require_readable_file(path);
  OIIO::ImageSpec config;
  // Without this, OpenImageIO multiplies colour by alpha for PNG/TGA/TIFF: a normal map whose alpha holds
  // a height map would come back scaled (test: NormalMapDecode.AlphaDoesNotScaleNormals).
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  if (!in)
    throw Error(ExitCode::invalid_input, "not a readable image: " + codec_message(OIIO::geterror(), quiet),
                path.string());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.deep) throw Error(ExitCode::invalid_input, "deep images are not supported", path.string());
  if (spec.depth > 1) throw Error(ExitCode::invalid_input, "volume images are not supported", path.string());
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw Error(ExitCode::invalid_input, "image has no pixels", path.string());
  header.width = uint32_t(spec.width);
  header.height = uint32_t(spec.height);
  header.info.pixel_format = spec.format.c_str();
  header.info.is_float = is_float_type(spec.format);
  header.info.is_signed = !header.info.is_float && spec.format.is_signed();
  header.info.integer_bits = header.info.is_float ? 0 : int(8 * spec.format.basesize());
  header.info.file_channels = uint32_t(spec.nchannels);
  return in;
}

// Rounds [0, 1] to the nearest of `max_code` + 1 codes; clamps out-of-range values, NaN becomes 0.
template <typename T>
std::vector<T> quantize(const std::vector<float>& pixels, double max_code) {
  std::vector<T> codes(pixels.size());
  for (size_t i = 0; i < pixels.size(); ++i) {
    const double v = pixels[i];
    codes[i] = std::isnan(v) ? T(0) : T(std::floor(std::clamp(v, 0.0, 1.0) * max_code + 0.5));
  }
  return codes;
}

ImageHeader read_header(const std::filesystem::path& path) {
  QuietStderr quiet;
  ImageHeader header;
  open_image(path, header, quiet);
  return header;
}

Image load(const std::filesystem::path& path, ImageFileInfo* info) {
  QuietStderr quiet;  // declared first: lives until `in` is closed and destroyed
  ImageHeader header;
  auto in = open_image(path, header, quiet);
  Image image;
  image.width = header.width;
  image.height = header.height;
  image.channels = header.info.file_channels;
  image.pixels.resize(size_t(image.width) * image.height * image.channels);
  require_decoded(in->read_image(0, 0, 0, int(image.channels), OIIO::TypeDesc::FLOAT, image.pixels.data()), *in, quiet,
                  path);
  require_decoded(in->close(), *in, quiet, path);
  if (info) *info = header.info;
  return image;
}

void save(const std::filesystem::path& path, const Image& image, const ImageSaveOptions& options,
          const std::filesystem::path& format_path) {
  const std::filesystem::path& named = format_path.empty() ? path : format_path;
  if (image.width == 0 || image.height == 0 || image.channels == 0 ||
      image.pixels.size() != size_t(image.width) * image.height * image.channels)
    throw Error(ExitCode::runtime_failure, "internal: image buffer does not match its size", path.string());
  if (options.png_bits != 8 && options.png_bits != 16)
    throw Error(ExitCode::runtime_failure, "internal: png_bits must be 8 or 16", path.string());
  if (options.float_bits != 16 && options.float_bits != 32)
    throw Error(ExitCode::runtime_failure, "internal: float_bits must be 16 or 32", path.string());

  auto out = OIIO::ImageOutput::create(named.string());
  if (!out) {
    OIIO::geterror();  // clear OpenImageIO's pending message; ours names the extension
    const std::string ext = named.extension().string();
    throw Error(ExitCode::bad_command_line,
                ext.empty() ? "output has no file extension to choose an image format from"
                            : "no image format for the extension '" + ext + "' (use .png or .exr)",
                named.string());
  }
  const bool exr = lower_extension(named) == ".exr";
  OIIO::TypeDesc stored = exr ? (options.float_bits == 16 ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT)
                              : (options.png_bits == 16 ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8);
  OIIO::ImageSpec spec(int(image.width), int(image.height), int(image.channels), stored);
  // Stated, so files do not change with OIIO's default.
  if (exr) spec.attribute("compression", options.exr_zip ? "zip" : "none");
  // Channels are stored as given: without this, OpenImageIO divides colour by alpha when writing PNG, TGA
  // and TIFF (test: NormalMapDecode.AlphaDoesNotScaleNormals).
  spec.attribute("oiio:UnassociatedAlpha", 1);
  // OpenImageIO stamps the current time into EXR (capDate) and TIFF files unless DateTime is given; an empty
  // one keeps outputs byte-identical between runs (test: ImageIo.SameImageGivesByteIdenticalFiles).
  spec.attribute("DateTime", "");
  // The codec writes into memory when it can, and the bytes reach the file through write_file_bytes, which checks
  // every write: codecs writing to a FILE* of their own do not all notice a full disk (libpng's did not, and a
  // truncated PNG replaced the old output). Codecs without memory output write the file and are read back whole.
  // The buffer is sized up front for the unencoded pixels plus headers and tables (a bound for EXR; PNG's output is
  // smaller), so it is filled once instead of being regrown and copied; untouched pages cost nothing.
  std::vector<unsigned char> bytes;
  bytes.reserve(image.pixels.size() * stored.size() + image.height * sizeof(uint64_t) + (size_t(1) << 16));
  advise_huge_pages(bytes.data(), bytes.capacity());
  OIIO::Filesystem::IOVecOutput encoded(bytes);
  const bool in_memory = out->supports("ioproxy");
  if (in_memory) out->set_ioproxy(&encoded);
  if (!out->open(path.string(), spec))
    throw Error(ExitCode::io_failure, "cannot write image: " + one_line(out->geterror()), named.string());
  bool ok;
  if (exr) {
    ok = out->write_image(OIIO::TypeDesc::FLOAT, image.pixels.data());
  } else if (options.png_bits == 16) {
    const auto codes = quantize<uint16_t>(image.pixels, 65535.0);
    ok = out->write_image(OIIO::TypeDesc::UINT16, codes.data());
  } else {
    const auto codes = quantize<uint8_t>(image.pixels, 255.0);
    ok = out->write_image(OIIO::TypeDesc::UINT8, codes.data());
  }
  ok = out->close() && ok;
  if (!ok) throw Error(ExitCode::io_failure, "cannot write image: " + one_line(out->geterror()), named.string());
  if (in_memory) {
    write_file_bytes(path, encoded.buffer(), named.string());
  } else {
    try {
      (void)load(path, nullptr);
    } catch (const Error& e) {
      throw Error(ExitCode::io_failure, std::string("image written incompletely (disk full?): ") + e.what(),
                  named.string());
    }
  }
}

}  // namespace
}  // namespace mbk

extern "C" __attribute__((visibility("default"))) const mbk::ImageIoModule* microbake_image_io_module() {
  static const mbk::ImageIoModule module{mbk::kImageIoModuleAbi, mbk::read_header, mbk::load, mbk::save};
  return &module;
}
