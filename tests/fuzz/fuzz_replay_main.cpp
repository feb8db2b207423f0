// Replays files through a fuzz target without libFuzzer, so that any compiler builds the targets and the test suite
// (ctest fuzz_regression_<target>, also under sanitizers) runs every seed and every regression file in
// tests/fuzz/corpus/<target>/. Arguments: files or folders (each file in a folder, in name order). Exits 0 when every
// input ran to its end; a crash or a sanitizer report ends the process as it would end the fuzzer.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace {

void replay(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "fuzz replay: cannot read %s\n", file.c_str());
    std::exit(2);
  }
  const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
}

}  // namespace

int main(int argc, char** argv) {
  size_t inputs = 0;
  for (int i = 1; i < argc; ++i) {
    const std::filesystem::path arg = argv[i];
    std::vector<std::filesystem::path> files;
    if (std::filesystem::is_directory(arg)) {
      for (const auto& entry : std::filesystem::directory_iterator(arg))
        if (entry.is_regular_file()) files.push_back(entry.path());
      std::sort(files.begin(), files.end());
    } else {
      files.push_back(arg);
    }
    for (const auto& f : files) replay(f), ++inputs;
  }
  if (inputs == 0) {
    std::fprintf(stderr, "fuzz replay: no inputs\n");
    return 2;
  }
  std::printf("fuzz replay: %zu inputs ran cleanly\n", inputs);
  return 0;
}
