// Temporary-then-rename output files (see atomic_file.h).
#include "formats/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

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
// The pid in `name` when it is a temporary of `destination` (".<stem>.partial-<pid>-<n><ext>"), else 0.
pid_t temporary_owner(const std::string& name, const fs::path& destination) {
  const std::string prefix = "." + destination.stem().string() + ".partial-", ext = destination.extension().string();
  if (name.size() <= prefix.size() + ext.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - ext.size(), ext.size(), ext) != 0)
    return 0;
  const std::string middle = name.substr(prefix.size(), name.size() - prefix.size() - ext.size());  // "<pid>-<n>"
  const size_t dash = middle.find('-');
  if (dash == 0 || dash == std::string::npos || dash > 9 || dash + 1 == middle.size() ||
      middle.find_first_not_of("0123456789-") != std::string::npos || middle.find('-', dash + 1) != std::string::npos)
    return 0;
  return pid_t(std::stol(middle.substr(0, dash)));
}

// A command killed while writing (SIGKILL, power loss) leaves its temporary behind. The next command writing the
// same destination removes those whose process is gone; a temporary of a live process (another command writing
// the same output right now, or a reused pid) is left alone, so cleaning never races a writer.
void remove_stale_temporaries(const fs::path& dir, const fs::path& destination) {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const pid_t owner = temporary_owner(it->path().filename().string(), destination);
    if (owner <= 0 || owner == ::getpid()) continue;
    if (::kill(owner, 0) == 0 || errno != ESRCH) continue;  // alive, or not ours to signal: keep
    std::error_code ignored;
    fs::remove(it->path(), ignored);
  }
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
  remove_stale_temporaries(dir, destination_);
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    std::error_code ec;
    fs::remove(temporary_, ec);
  }
}

void AtomicFile::write_all(std::span<const uint8_t> bytes) {
  write_file_bytes(temporary_, bytes, destination_.string());
}

void AtomicFile::check_stream(const char* what) {
  if (!stream_) throw Error(ExitCode::io_failure, what, destination_.string());
}

void AtomicFile::append(std::span<const uint8_t> bytes) {
  if (!stream_.is_open()) {
    stream_.open(temporary_, std::ios::binary | std::ios::trunc);
    check_stream("cannot create output file");
  }
  stream_.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  check_stream("cannot write output file (disk full?)");
}

void AtomicFile::overwrite(uint64_t offset, std::span<const uint8_t> bytes) {
  if (!stream_.is_open()) throw Error(ExitCode::runtime_failure, "internal: overwrite before any append");
  stream_.seekp(static_cast<std::streamoff>(offset));
  stream_.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  stream_.seekp(0, std::ios::end);
  check_stream("cannot write output file (disk full?)");
}

void write_file_bytes(const fs::path& path, std::span<const uint8_t> bytes, const std::string& where) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw Error(ExitCode::io_failure, "cannot create output file", where);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw Error(ExitCode::io_failure, "cannot write output file (disk full?)", where);
}

void AtomicFile::commit() {
  if (stream_.is_open()) {
    stream_.close();
    check_stream("cannot write output file (disk full?)");
  }
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
