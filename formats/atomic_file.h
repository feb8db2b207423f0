// Outputs appear only when complete: AtomicFile writes to a temporary file in the destination folder
// (same extension, so extension-driven writers such as OpenImageIO pick the right format), and commit()
// flushes it to disk and renames it into place. Destroyed without commit(), it removes the temporary, so a
// failed command never leaves a partial output behind. A temporary that a killed command (SIGKILL) left behind is
// removed by the next AtomicFile for the same destination once its process is gone (atomic_file.cpp).
#pragma once

#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <vector>

namespace mbk {

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path destination);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Where to write before commit(): ".<stem>.partial-<pid>-<n><ext>" beside the destination.
  const std::filesystem::path& temporary_path() const { return temporary_; }

  // Writes bytes to the temporary path (replacing its content). Throws Error(io_failure).
  void write_all(std::span<const uint8_t> bytes);
  // Streamed writing, for output produced while it is written (an asset whose sections are built as they are
  // written, formats/asset_writer.h): append() adds bytes at the end of the temporary (the first call creates it
  // empty); overwrite() replaces bytes written earlier at `offset` (a header known only at the end). Both throw
  // Error(io_failure) as soon as a write fails (a full disk stops a long bake early).
  void append(std::span<const uint8_t> bytes);
  void overwrite(uint64_t offset, std::span<const uint8_t> bytes);
  // Closes a streamed temporary (checking the close), fsyncs the temporary and renames it onto the destination.
  // Throws Error(io_failure).
  void commit();

 private:
  void check_stream(const char* what);
  std::filesystem::path destination_;
  std::filesystem::path temporary_;
  std::ofstream stream_;
  bool committed_ = false;
};

// Writes `bytes` to `path` (replacing its content), checking every write and the close, so that a full disk or a
// file-size limit is an Error(io_failure) at `where`, never a silently short file.
void write_file_bytes(const std::filesystem::path& path, std::span<const uint8_t> bytes, const std::string& where);

// Reads a whole file. Throws Error(io_failure) naming the path when it cannot.
std::vector<uint8_t> read_file_bytes(const std::filesystem::path& path);

}  // namespace mbk
