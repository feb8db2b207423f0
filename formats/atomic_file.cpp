// Temporary-then-rename output files (see atomic_file.h).
#include "formats/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <vector>

#include "formats/error.h"

namespace mbk {
namespace fs = std::filesystem;

namespace {
std::atomic<unsigned> g_counter{0};

void fsync_path(const fs::path& path) {
  int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0)
    throw Error(ExitCode::io_failure, std::string("cannot reopen output: ") + std::strerror(errno), path.string());
  int rc = ::fsync(fd);
  ::close(fd);
  if (rc != 0)
    throw Error(ExitCode::io_failure, std::string("cannot flush output: ") + std::strerror(errno), path.string());
}
}  // namespace

AtomicFile::AtomicFile(fs::path destination) : destination_(std::move(destination)) {
  fs::path dir = destination_.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw Error(ExitCode::io_failure, "output folder does not exist", dir.string());
  if (fs::is_directory(destination_, ec))
    throw Error(ExitCode::io_failure, "output path is a folder", destination_.string());
  std::string name = "." + destination_.stem().string() + ".partial-" + std::to_string(::getpid()) + "-" +
                     std::to_string(g_counter++) + destination_.extension().string();
  temporary_ = dir / name;
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    std::error_code ec;
    fs::remove(temporary_, ec);
  }
}

void AtomicFile::write_all(std::span<const uint8_t> bytes) { write_all(std::vector{bytes}); }

void AtomicFile::write_all(const std::vector<std::span<const uint8_t>>& pieces) {
  std::ofstream out(temporary_, std::ios::binary | std::ios::trunc);
  if (!out) throw Error(ExitCode::io_failure, "cannot create output file", destination_.string());
  for (std::span<const uint8_t> piece : pieces)
    out.write(reinterpret_cast<const char*>(piece.data()), static_cast<std::streamsize>(piece.size()));
  out.close();
  if (!out) throw Error(ExitCode::io_failure, "cannot write output file (disk full?)", destination_.string());
}

void AtomicFile::commit() {
  std::error_code ec;
  if (!fs::exists(temporary_, ec)) throw Error(ExitCode::io_failure, "output was not written", destination_.string());
  fsync_path(temporary_);
  fs::rename(temporary_, destination_, ec);
  if (ec) throw Error(ExitCode::io_failure, "cannot move output into place: " + ec.message(), destination_.string());
  committed_ = true;
}

std::vector<uint8_t> read_file_bytes(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(ExitCode::io_failure, "file not found", path.string());
  if (fs::is_directory(path, ec)) throw Error(ExitCode::io_failure, "is a folder, not a file", path.string());
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ExitCode::io_failure, "cannot open file", path.string());
  in.seekg(0, std::ios::end);
  std::streamoff size = in.tellg();
  if (size < 0) throw Error(ExitCode::io_failure, "cannot read file", path.string());
  in.seekg(0, std::ios::beg);
  std::vector<uint8_t> bytes(static_cast<size_t>(size));
  in.read(reinterpret_cast<char*>(bytes.data()), size);
  if (!in) throw Error(ExitCode::io_failure, "cannot read file", path.string());
  return bytes;
}

}  // namespace mbk
