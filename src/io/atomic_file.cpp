#include "io/atomic_file.hpp"

#include "core/error.hpp"

#include <fstream>
#include <system_error>
#include <utility>

namespace kessler::io {

AtomicFile::AtomicFile(std::filesystem::path final_path)
    : final_path_(std::move(final_path)), temporary_path_(final_path_) {
  temporary_path_ += ".tmp";
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    std::error_code ignored;
    std::filesystem::remove(temporary_path_, ignored);
  }
}

void AtomicFile::commit() {
  std::error_code error;
  std::filesystem::rename(temporary_path_, final_path_, error);
  if (error)
    throw Error(fmt::format("cannot rename '{}' to '{}': {}", temporary_path_.string(), final_path_.string(),
                            error.message()));
  committed_ = true;
}

void writeTextAtomically(const std::filesystem::path& path, std::string_view text) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temporaryPath(), std::ios::binary | std::ios::trunc);
    if (!out) throw Error(fmt::format("cannot open '{}' for writing", file.temporaryPath().string()));
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw Error(fmt::format("cannot write '{}'", file.temporaryPath().string()));
  }
  file.commit();
}

}  // namespace kessler::io
