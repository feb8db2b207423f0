// The yardstick of scripts/bench.sh: the wall time of memcpy of BYTES bytes into a freshly allocated buffer (its
// pages faulted in by the copy, as a bake's output pages are by the bake), from a source touched beforehand. Prints
// the median over REPEATS copies, in seconds, and nothing else. With PATH, each copy is then also written to PATH
// and flushed to disk (fsync), as a bake that builds its output while writing it (rmq) is measured with its write.
//
//   bench_memcpy BYTES [REPEATS [PATH]]        # REPEATS defaults to 5
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

// Writes the bytes to `path` (replacing it) and fsyncs it; false on any failure.
bool write_and_flush(const char* path, const unsigned char* data, size_t size) {
  const int fd = ::open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return false;
  for (size_t done = 0; done < size;) {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n <= 0) return ::close(fd), false;
    done += size_t(n);
  }
  const bool flushed = ::fsync(fd) == 0;
  return ::close(fd) == 0 && flushed;
}

int main(int argc, char** argv) {
  if (argc < 2 || argc > 4) {
    std::fprintf(stderr, "usage: bench_memcpy BYTES [REPEATS [PATH]]\n");
    return 2;
  }
  const size_t bytes = std::stoull(argv[1]);
  const int repeats = argc > 2 ? std::max(1, std::stoi(argv[2])) : 5;
  std::vector<unsigned char> source(bytes, 1);
  std::vector<double> seconds;
  unsigned checksum = 0;  // read back so that the copies cannot be optimised away
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<unsigned char[]> destination(new unsigned char[bytes]);
    std::memcpy(destination.get(), source.data(), bytes);
    if (argc > 3 && !write_and_flush(argv[3], destination.get(), bytes)) {
      std::perror(argv[3]);
      return 2;
    }
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    checksum += bytes ? destination[bytes / 2] : 0;
  }
  std::sort(seconds.begin(), seconds.end());
  std::printf("%.6f\n", seconds[seconds.size() / 2]);
  return checksum == unsigned(repeats) * (bytes ? 1 : 0) ? 0 : 1;
}
