// The yardstick of scripts/bench.sh: the wall time of memcpy of BYTES bytes into a freshly allocated buffer (its
// pages faulted in by the copy, as a bake's output pages are by the bake), from a source touched beforehand. Prints
// the median over REPEATS copies, in seconds, and nothing else.
//
//   bench_memcpy BYTES [REPEATS]        # REPEATS defaults to 5
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: bench_memcpy BYTES [REPEATS]\n");
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
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    checksum += bytes ? destination[bytes / 2] : 0;
  }
  std::sort(seconds.begin(), seconds.end());
  std::printf("%.6f\n", seconds[seconds.size() / 2]);
  return checksum == unsigned(repeats) * (bytes ? 1 : 0) ? 0 : 1;
}
