// A driver for the fuzz targets in the ordinary build (no libFuzzer): runs the target on every
// file given, or on every file in a folder given. With --bad, only files named bad_* in folders,
// and each must be refused with a located one-line error (the malformed-input corpus).
#include "fuzz/fuzz_input.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--bad") {
      kessler::fuzz::expectError() = true;
    } else if (fs::is_directory(arg)) {
      for (const auto& entry : fs::directory_iterator(arg))
        if (entry.is_regular_file() &&
            (!kessler::fuzz::expectError() || entry.path().filename().string().rfind("bad_", 0) == 0))
          files.push_back(entry.path());
    } else {
      files.emplace_back(arg);
    }
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::fprintf(stderr, "%s\n", file.string().c_str());
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("%zu inputs, no crash%s\n", files.size(), kessler::fuzz::expectError() ? ", each refused" : "");
  return files.empty() ? 1 : 0;
}
