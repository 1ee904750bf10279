#include "io/hdf5_reader.hpp"

#include "core/error.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <functional>
#include <numeric>
#include <utility>

namespace kessler::io {
namespace {

template <class T>
struct Native;
template <>
struct Native<double> {
  static hid_t type() { return H5T_NATIVE_DOUBLE; }
  static constexpr H5T_class_t type_class = H5T_FLOAT;
};
template <>
struct Native<std::int64_t> {
  static hid_t type() { return H5T_NATIVE_INT64; }
  static constexpr H5T_class_t type_class = H5T_INTEGER;
};
template <>
struct Native<std::int32_t> {
  static hid_t type() { return H5T_NATIVE_INT32; }
  static constexpr H5T_class_t type_class = H5T_INTEGER;
};
template <>
struct Native<std::uint8_t> {
  static hid_t type() { return H5T_NATIVE_UINT8; }
  static constexpr H5T_class_t type_class = H5T_INTEGER;
};

}  // namespace

Hdf5Reader::Hdf5Reader(std::filesystem::path path) : path_(std::move(path)) {
  if (H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr) < 0) fail("switch off HDF5's error printing");
  std::error_code error;
  if (!std::filesystem::is_regular_file(path_, error)) throw Error(fmt::format("'{}': no such file", path_.string()));
  file_ = Hdf5Id(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (file_.get() < 0) fail("open the file (not an HDF5 file, or damaged)");
}

bool Hdf5Reader::has(const std::string& name) const {
  // H5Lexists needs each parent to exist, so walk the path one level at a time.
  std::size_t at = 0;
  while (at != std::string::npos) {
    at = name.find('/', at + 1);
    const std::string prefix = name.substr(0, at);
    if (prefix.empty() || prefix == "/") continue;
    const htri_t exists = H5Lexists(file_.get(), prefix.c_str(), H5P_DEFAULT);
    if (exists < 0) fail(fmt::format("look up '{}'", prefix));
    if (exists == 0) return false;
  }
  return true;
}

std::vector<hsize_t> Hdf5Reader::shape(const std::string& name) const {
  if (!has(name)) fail(fmt::format("find dataset '{}'", name));
  Hdf5Id set(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
  if (set.get() < 0) fail(fmt::format("open dataset '{}'", name));
  Hdf5Id space(H5Dget_space(set.get()), H5Sclose);
  const int rank = space.get() < 0 ? -1 : H5Sget_simple_extent_ndims(space.get());
  if (rank < 0) fail(fmt::format("read the shape of '{}'", name));
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  if (rank > 0 && H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr) < 0)
    fail(fmt::format("read the shape of '{}'", name));
  return dims;
}

template <class T>
std::vector<T> Hdf5Reader::read(const std::string& name) const {
  const std::vector<hsize_t> dims = shape(name);
  const hsize_t count = std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
  std::vector<T> values(static_cast<std::size_t>(count));
  readRaw(name, Native<T>::type(), Native<T>::type_class, sizeof(T), values.data(), values.size());
  return values;
}

template std::vector<double> Hdf5Reader::read<double>(const std::string&) const;
template std::vector<std::int64_t> Hdf5Reader::read<std::int64_t>(const std::string&) const;
template std::vector<std::int32_t> Hdf5Reader::read<std::int32_t>(const std::string&) const;
template std::vector<std::uint8_t> Hdf5Reader::read<std::uint8_t>(const std::string&) const;

std::vector<std::uint8_t> Hdf5Reader::readBytes(const std::string& name) const {
  const std::vector<hsize_t> dims = shape(name);
  const hsize_t count = std::accumulate(dims.begin(), dims.end(), hsize_t{1}, std::multiplies<>());
  Hdf5Id set(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
  if (set.get() < 0) fail(fmt::format("open dataset '{}'", name));
  Hdf5Id type(H5Dget_type(set.get()), H5Tclose);
  if (type.get() < 0) fail(fmt::format("read the type of '{}'", name));
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(count) * H5Tget_size(type.get()));
  if (!bytes.empty() && H5Dread(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data()) < 0)
    fail(fmt::format("read dataset '{}'", name));
  return bytes;
}

void Hdf5Reader::readRaw(const std::string& name, hid_t memory_type, H5T_class_t type_class, std::size_t type_size,
                         void* data, std::size_t count) const {
  Hdf5Id set(H5Dopen2(file_.get(), name.c_str(), H5P_DEFAULT), H5Dclose);
  if (set.get() < 0) fail(fmt::format("open dataset '{}'", name));
  Hdf5Id type(H5Dget_type(set.get()), H5Tclose);
  if (type.get() < 0) fail(fmt::format("read the type of '{}'", name));
  if (H5Tget_class(type.get()) != type_class || H5Tget_size(type.get()) != type_size)
    fail(fmt::format("read '{}': it holds {}-byte {} values, expected {}-byte {}", name, H5Tget_size(type.get()),
                     H5Tget_class(type.get()) == H5T_FLOAT ? "floating-point" : "other", type_size,
                     type_class == H5T_FLOAT ? "floating-point" : "integer"));
  if (count > 0 && H5Dread(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    fail(fmt::format("read dataset '{}'", name));
}

void Hdf5Reader::readAttributeRaw(const std::string& name, hid_t memory_type, H5T_class_t type_class,
                                  void* value) const {
  const htri_t exists = H5Aexists(file_.get(), name.c_str());
  if (exists <= 0) fail(fmt::format("find attribute '{}'", name));
  Hdf5Id attribute(H5Aopen(file_.get(), name.c_str(), H5P_DEFAULT), H5Aclose);
  if (attribute.get() < 0) fail(fmt::format("open attribute '{}'", name));
  Hdf5Id type(H5Aget_type(attribute.get()), H5Tclose);
  Hdf5Id space(H5Aget_space(attribute.get()), H5Sclose);
  if (type.get() < 0 || space.get() < 0 || H5Tget_class(type.get()) != type_class ||
      H5Sget_simple_extent_npoints(space.get()) != 1)
    fail(fmt::format("read attribute '{}': not a single value of the expected type", name));
  if (H5Aread(attribute.get(), memory_type, value) < 0) fail(fmt::format("read attribute '{}'", name));
}

double Hdf5Reader::readDoubleAttribute(const std::string& name) const {
  double value = 0.0;
  readAttributeRaw(name, H5T_NATIVE_DOUBLE, H5T_FLOAT, &value);
  return value;
}

std::int64_t Hdf5Reader::readInt64Attribute(const std::string& name) const {
  std::int64_t value = 0;
  readAttributeRaw(name, H5T_NATIVE_INT64, H5T_INTEGER, &value);
  return value;
}

std::vector<std::string> Hdf5Reader::datasets(const std::string& group) const {
  std::vector<std::string> names;
  auto visit = [](hid_t, const char* name, const H5O_info_t* info, void* data) -> herr_t {
    if (info->type == H5O_TYPE_DATASET) static_cast<std::vector<std::string>*>(data)->emplace_back(name);
    return 0;
  };
  Hdf5Id root(H5Oopen(file_.get(), group.c_str(), H5P_DEFAULT), H5Oclose);
  if (root.get() < 0) fail(fmt::format("open group '{}'", group));
  if (H5Ovisit2(root.get(), H5_INDEX_NAME, H5_ITER_INC, visit, &names, H5O_INFO_BASIC) < 0)
    fail(fmt::format("list the datasets of '{}'", group));
  const std::string prefix = group.ends_with('/') ? group : group + "/";
  for (std::string& name : names) name = prefix + name;
  std::sort(names.begin(), names.end());
  return names;
}

void Hdf5Reader::fail(const std::string& what) const {
  throw Error(fmt::format("HDF5 file '{}': cannot {}: {}", path_.string(), what, hdf5Reason()));
}

}  // namespace kessler::io
