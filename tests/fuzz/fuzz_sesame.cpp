// libFuzzer target: the SESAME reader (eos::readSesame) on arbitrary bytes, through a file of this
// process's own in the temporary folder (the reader's interface is a file name).
#include "fuzz/fuzz_input.hpp"
#include "material/eos/tabular.hpp"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace {

// The process's scratch file, removed when the fuzzer exits (a run of many short fuzz jobs
// otherwise leaves one file per process in the temporary folder).
struct ScratchFile {
  std::string path;
  ScratchFile() {
    const char* dir = std::getenv("TMPDIR");
    const std::filesystem::path base = dir != nullptr && *dir != '\0' ? dir : "/tmp";
    path = (base / ("kessler_fuzz_sesame_" + std::to_string(getpid()) + ".ses")).string();
  }
  ~ScratchFile() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const ScratchFile scratch;
  const std::string& file = scratch.path;
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    kessler::eos::readSesame(file, 0);
    kessler::fuzz::accepted(file);
  } catch (const kessler::InputError& e) {
    kessler::fuzz::checkMessage(e, file);
  }
  return 0;
}
