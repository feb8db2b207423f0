// Outputs appear only when complete: AtomicFile writes to a temporary file in the destination folder
// (same extension, so extension-driven writers such as OpenImageIO pick the right format), and commit()
// flushes it to disk and renames it into place. Destroyed without commit(), it removes the temporary, so a
// failed command never leaves a partial output behind. A temporary that a killed command (SIGKILL) left behind is
// removed by the next AtomicFile for the same destination once its process is gone (atomic_file.cpp).
#pragma once

#include <filesystem>
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
  // Writes the pieces one after the other to the temporary path (replacing its content). Throws Error(io_failure).
  void write_all(const std::vector<std::span<const uint8_t>>& pieces);
  // fsyncs the temporary and renames it onto the destination. Throws Error(io_failure).
  void commit();

 private:
  std::filesystem::path destination_;
  std::filesystem::path temporary_;
  bool committed_ = false;
};

// Writes `bytes` to `path` (replacing its content), checking every write and the close, so that a full disk or a
// file-size limit is an Error(io_failure) at `where`, never a silently short file.
void write_file_bytes(const std::filesystem::path& path, std::span<const uint8_t> bytes, const std::string& where);
// The same for bytes given as consecutive pieces (a streamed asset: header, metadata, then each section).
void write_file_pieces(const std::filesystem::path& path, const std::vector<std::span<const uint8_t>>& pieces,
                       const std::string& where);

// Reads a whole file. Throws Error(io_failure) naming the path when it cannot.
std::vector<uint8_t> read_file_bytes(const std::filesystem::path& path);

}  // namespace mbk
