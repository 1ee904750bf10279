#pragma once
// Replacing a file atomically: write everything to a temporary name in the same folder, then
// rename it over the final name. A run killed mid-write therefore never leaves a truncated
// output behind, only a stray temporary that the next write to the same name overwrites.
#include <filesystem>
#include <string_view>

namespace kessler::io {

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path final_path);
  ~AtomicFile();  // removes the temporary unless commit() succeeded
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Where the content goes before commit(); same folder as the final file, so rename is atomic.
  const std::filesystem::path& temporaryPath() const { return temporary_path_; }
  const std::filesystem::path& finalPath() const { return final_path_; }
  // Renames the temporary over the final file; throws kessler::Error if that fails.
  void commit();

 private:
  std::filesystem::path final_path_;
  std::filesystem::path temporary_path_;
  bool committed_ = false;
};

// Writes `text` to `path` through an AtomicFile.
void writeTextAtomically(const std::filesystem::path& path, std::string_view text);

}  // namespace kessler::io
