#include "io/hdf5_file.hpp"

#include "core/error.hpp"

#include <fmt/ranges.h>

#include <functional>
#include <numeric>
#include <utility>
#include <vector>

namespace kessler::io {

std::string hdf5Reason() {
  std::vector<std::string> descriptions;
  auto collect = [](unsigned, const H5E_error2_t* error, void* data) -> herr_t {
    static_cast<std::vector<std::string>*>(data)->emplace_back(error->desc ? error->desc : "");
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, collect, &descriptions);
  H5Eclear2(H5E_DEFAULT);
  if (descriptions.empty()) return "no reason given by HDF5";
  if (descriptions.size() == 1) return descriptions.front();
  return fmt::format("{} ({})", descriptions.front(), descriptions.back());
}

Hdf5Id& Hdf5Id::operator=(Hdf5Id&& other) noexcept {
  if (this != &other) {
    release();
    id_ = std::exchange(other.id_, H5I_INVALID_HID);
    closer_ = other.closer_;
  }
  return *this;
}

herr_t Hdf5Id::release() {
  if (id_ < 0 || closer_ == nullptr) return 0;
  const herr_t status = closer_(std::exchange(id_, H5I_INVALID_HID));
  return status;
}

Hdf5Writer::Hdf5Writer(std::filesystem::path path) : path_(std::move(path)) {
  // The automatic printer would write HDF5's stack to stderr behind our back; we report it instead.
  if (H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr) < 0) fail("switch off HDF5's error printing");
  file_ = Hdf5Id(H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  if (file_.get() < 0) fail("create the file");
}

void Hdf5Writer::createGroup(const std::string& name) {
  Hdf5Id group(H5Gcreate2(file_.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (group.get() < 0) fail(fmt::format("create group '{}'", name));
  if (group.release() < 0) fail(fmt::format("close group '{}'", name));
}

void Hdf5Writer::writeDataset(const std::string& name, std::span<const double> data,
                              std::initializer_list<hsize_t> dims) {
  writeRaw(name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data.data(), data.size(), dims);
}

void Hdf5Writer::writeDataset(const std::string& name, std::span<const std::int64_t> data,
                              std::initializer_list<hsize_t> dims) {
  writeRaw(name, H5T_STD_I64LE, H5T_NATIVE_INT64, data.data(), data.size(), dims);
}

void Hdf5Writer::writeDataset(const std::string& name, std::span<const std::int32_t> data,
                              std::initializer_list<hsize_t> dims) {
  writeRaw(name, H5T_STD_I32LE, H5T_NATIVE_INT32, data.data(), data.size(), dims);
}

void Hdf5Writer::writeDataset(const std::string& name, std::span<const std::uint8_t> data,
                              std::initializer_list<hsize_t> dims) {
  writeRaw(name, H5T_STD_U8LE, H5T_NATIVE_UINT8, data.data(), data.size(), dims);
}

void Hdf5Writer::writeAttribute(const std::string& name, double value) {
  writeScalarAttribute(name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

void Hdf5Writer::writeAttribute(const std::string& name, std::int64_t value) {
  writeScalarAttribute(name, H5T_STD_I64LE, H5T_NATIVE_INT64, &value);
}

void Hdf5Writer::close() {
  if (file_.release() < 0) fail("close (flush) the file");
}

void Hdf5Writer::writeRaw(const std::string& name, hid_t file_type, hid_t memory_type, const void* data,
                          std::size_t count, std::initializer_list<hsize_t> dims) {
  const std::vector<hsize_t> shape(dims);
  const hsize_t expected = std::accumulate(shape.begin(), shape.end(), hsize_t{1}, std::multiplies<>());
  KESSLER_VERIFY(!shape.empty() && expected == count, "dataset '{}' in '{}': {} values do not fill shape [{}]", name,
                 path_.string(), count, fmt::join(shape, ", "));
  Hdf5Id space(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), H5Sclose);
  if (space.get() < 0) fail(fmt::format("create the dataspace of '{}'", name));
  Hdf5Id set(H5Dcreate2(file_.get(), name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
             H5Dclose);
  if (set.get() < 0) fail(fmt::format("create dataset '{}'", name));
  // HDF5 refuses a null buffer even for an empty selection, and an empty vector may have one.
  if (count > 0 && H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    fail(fmt::format("write dataset '{}'", name));
  if (set.release() < 0) fail(fmt::format("close dataset '{}'", name));
  if (space.release() < 0) fail(fmt::format("close the dataspace of '{}'", name));
}

void Hdf5Writer::writeScalarAttribute(const std::string& name, hid_t file_type, hid_t memory_type, const void* value) {
  Hdf5Id space(H5Screate(H5S_SCALAR), H5Sclose);
  if (space.get() < 0) fail(fmt::format("create the dataspace of attribute '{}'", name));
  Hdf5Id attribute(H5Acreate2(file_.get(), name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (attribute.get() < 0) fail(fmt::format("create attribute '{}'", name));
  if (H5Awrite(attribute.get(), memory_type, value) < 0) fail(fmt::format("write attribute '{}'", name));
  if (attribute.release() < 0) fail(fmt::format("close attribute '{}'", name));
}

void Hdf5Writer::fail(const std::string& what) const {
  throw Error(fmt::format("HDF5 file '{}': cannot {}: {}", path_.string(), what, hdf5Reason()));
}

}  // namespace kessler::io
