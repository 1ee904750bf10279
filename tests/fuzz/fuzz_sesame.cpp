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

namespace {

std::string scratchFile() {
  const char* dir = std::getenv("TMPDIR");
  const std::filesystem::path base = dir != nullptr && *dir != '\0' ? dir : "/tmp";
  return (base / ("kessler_fuzz_sesame_" + std::to_string(getpid()) + ".ses")).string();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string file = scratchFile();
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
