#pragma once
// Reading back what Hdf5Writer wrote (checkpoints, result files in tests): datasets of plain
// numbers and scalar attributes on the root group. Every call is checked; a missing dataset, a
// wrong type or a damaged file throws kessler::Error naming the file, the dataset and HDF5's
// reason, so that a bad checkpoint is refused with a message instead of read as garbage.
#include "io/hdf5_file.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace kessler::io {

class Hdf5Reader {
 public:
  // Opens `path` read-only.
  explicit Hdf5Reader(std::filesystem::path path);

  // Whether the dataset or group exists (every intermediate group must exist too).
  bool has(const std::string& name) const;
  // The dimensions of a dataset.
  std::vector<hsize_t> shape(const std::string& name) const;
  // All values of a dataset, row major. T is double, std::int64_t, std::int32_t or std::uint8_t,
  // and must match the stored type exactly (no silent conversion of a checkpoint).
  template <class T>
  std::vector<T> read(const std::string& name) const;
  // The raw bytes of a dataset of any plain number type, as stored (for bitwise comparisons).
  std::vector<std::uint8_t> readBytes(const std::string& name) const;

  double readDoubleAttribute(const std::string& name) const;
  std::int64_t readInt64Attribute(const std::string& name) const;
  // Names of all datasets below `group`, sorted, with their full paths ("/points/x").
  std::vector<std::string> datasets(const std::string& group = "/") const;

  const std::filesystem::path& path() const { return path_; }
  [[noreturn]] void fail(const std::string& what) const;

 private:
  void readRaw(const std::string& name, hid_t memory_type, H5T_class_t type_class, std::size_t type_size, void* data,
               std::size_t count) const;
  void readAttributeRaw(const std::string& name, hid_t memory_type, H5T_class_t type_class, void* value) const;

  std::filesystem::path path_;
  Hdf5Id file_;
};

}  // namespace kessler::io
