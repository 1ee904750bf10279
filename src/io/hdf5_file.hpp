#pragma once
// A small RAII wrapper of the HDF5 C API for writing result files: groups, contiguous datasets
// of plain numbers and scalar attributes on the root group. Every call is checked; a failure
// throws kessler::Error naming the file, what failed and HDF5's own reason. HDF5's automatic
// printing of its error stack is switched off so that the exception is the only report.
#include <hdf5.h>

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <span>
#include <string>

namespace kessler::io {

// HDF5's error stack for the last failure, outermost and innermost reason (the outer one says what
// the library was doing, the inner one why it failed, often the operating system's errno); clears it.
std::string hdf5Reason();

// Owns one HDF5 identifier and closes it with the matching H5?close function.
class Hdf5Id {
 public:
  using Closer = herr_t (*)(hid_t);

  Hdf5Id() = default;
  Hdf5Id(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  ~Hdf5Id() { release(); }
  Hdf5Id(Hdf5Id&& other) noexcept : id_(other.id_), closer_(other.closer_) { other.id_ = H5I_INVALID_HID; }
  Hdf5Id& operator=(Hdf5Id&& other) noexcept;
  Hdf5Id(const Hdf5Id&) = delete;
  Hdf5Id& operator=(const Hdf5Id&) = delete;

  hid_t get() const { return id_; }
  // Closes now and returns the closer's status, so that callers can check it (H5Fclose flushes).
  herr_t release();

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

class Hdf5Writer {
 public:
  // Creates the file at `path`, replacing any file of that name.
  explicit Hdf5Writer(std::filesystem::path path);

  void createGroup(const std::string& name);
  // Writes `data` as a dataset of shape `dims` (row major); the product of dims must equal data.size().
  void writeDataset(const std::string& name, std::span<const double> data, std::initializer_list<hsize_t> dims);
  void writeDataset(const std::string& name, std::span<const std::int64_t> data, std::initializer_list<hsize_t> dims);
  void writeDataset(const std::string& name, std::span<const std::int32_t> data, std::initializer_list<hsize_t> dims);
  void writeDataset(const std::string& name, std::span<const std::uint8_t> data, std::initializer_list<hsize_t> dims);
  void writeAttribute(const std::string& name, double value);
  void writeAttribute(const std::string& name, std::int64_t value);
  // Flushes and closes the file. Must be called: a failure here means the data may not be on disk.
  void close();

  const std::filesystem::path& path() const { return path_; }

 private:
  void writeRaw(const std::string& name, hid_t file_type, hid_t memory_type, const void* data, std::size_t count,
                std::initializer_list<hsize_t> dims);
  void writeScalarAttribute(const std::string& name, hid_t file_type, hid_t memory_type, const void* value);
  [[noreturn]] void fail(const std::string& what) const;

  std::filesystem::path path_;
  Hdf5Id file_;
};

}  // namespace kessler::io
