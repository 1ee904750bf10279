// FieldWriter: values read back with the HDF5 C API, derived fields against hand-computed values,
// the XDMF checked against the HDF5 files it references, atomic replacement and error reports.
#include "io/fields_writer.hpp"

#include "core/error.hpp"
#include "solver/otm/node_store.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace kessler::io {
namespace {

namespace fs = std::filesystem;

// 5 owned points and 4 owned nodes, each followed by one ghost that must not be written.
struct Stores {
  otm::NodeStore nodes;
  PointStore points;
};

Stores makeStores(double shift) {
  Stores s;
  s.points.resize(6);
  s.points.owned = 5;
  for (int p = 0; p < 6; ++p) {
    const double d = p;
    s.points.id[p] = 1000 + p;
    s.points.body[p] = p < 3 ? 0 : 1;
    s.points.x[p] = Vec3(d, 2 * d, 3 * d + shift);
    s.points.v[p] = Vec3(-d, 0.5 * d, shift);
    s.points.mass[p] = 2.0 + d;
    s.points.volume[p] = 0.5;
    s.points.plastic_strain[p] = 0.125 * d;
    s.points.temperature[p] = 293.0 + d;
    s.points.broken[p] = p == 4 ? 1 : 0;
  }
  // Uniaxial, pure shear, hydrostatic, general, zero.
  s.points.stress[0] = Vec3(3e8, 0, 0).asDiagonal();
  s.points.stress[1] << 0, 1e8, 0, 1e8, 0, 0, 0, 0, 0;
  s.points.stress[2] = -2e9 * Mat3::Identity();
  s.points.stress[3] << 1e8, 2e7, -3e7, 2e7, -5e7, 4e7, -3e7, 4e7, 2.5e8;
  s.nodes.resize(5);
  s.nodes.owned = 4;
  for (int a = 0; a < 5; ++a) {
    const double d = a;
    s.nodes.id[a] = 7 + a;
    s.nodes.body[a] = a % 2;
    s.nodes.x[a] = Vec3(0.1 * d, -d, shift);
    s.nodes.v[a] = Vec3(d, d + shift, -d);
    s.nodes.mass[a] = 1.5 * d;
  }
  return s;
}

struct Dataset {
  std::vector<hsize_t> dims;
  H5T_class_t type_class = H5T_NO_CLASS;
  std::size_t type_size = 0;
  H5T_sign_t sign = H5T_SGN_ERROR;
};

// Shape and stored type of a dataset, or nullopt if the file or the dataset is missing.
std::optional<Dataset> inspect(const fs::path& file, const std::string& name) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return std::nullopt;
  std::optional<Dataset> result;
  if (H5Lexists(f, name.c_str(), H5P_DEFAULT) > 0) {
    const hid_t d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
    const hid_t space = H5Dget_space(d);
    const hid_t type = H5Dget_type(d);
    Dataset info;
    info.dims.resize(static_cast<std::size_t>(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, info.dims.data(), nullptr);
    info.type_class = H5Tget_class(type);
    info.type_size = H5Tget_size(type);
    info.sign = H5Tget_sign(type);
    H5Tclose(type);
    H5Sclose(space);
    H5Dclose(d);
    result = info;
  }
  H5Fclose(f);
  return result;
}

template <class T>
std::vector<T> read(const fs::path& file, const std::string& name, hid_t memory_type) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << file;
  const hid_t d = H5Dopen2(f, name.c_str(), H5P_DEFAULT);
  EXPECT_GE(d, 0) << name;
  const hid_t space = H5Dget_space(d);
  std::vector<T> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  EXPECT_GE(H5Dread(d, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), 0) << name;
  H5Sclose(space);
  H5Dclose(d);
  H5Fclose(f);
  return values;
}

double readTimeAttribute(const fs::path& file) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t a = H5Aopen(f, "time", H5P_DEFAULT);
  double time = -1.0;
  EXPECT_GE(H5Aread(a, H5T_NATIVE_DOUBLE, &time), 0);
  H5Aclose(a);
  H5Fclose(f);
  return time;
}

std::string slurp(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<double> flat(const std::vector<Vec3>& vectors, std::size_t n) {
  std::vector<double> values;
  for (std::size_t i = 0; i < n; ++i) values.insert(values.end(), {vectors[i].x(), vectors[i].y(), vectors[i].z()});
  return values;
}

class FieldWriterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("kessler_fields_" + std::to_string(getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Two outputs: step 0 at t = 0 and step 25 at t = 2.5 us.
  void writeTwo() {
    FieldWriter writer(dir_ / "run");
    const Stores first = makeStores(0.0), second = makeStores(1.0);
    writer.write(0, 0.0, first.nodes.cloud(), first.points);
    writer.write(25, 2.5e-6, second.nodes.cloud(), second.points);
  }

  fs::path dir_;
};

TEST_F(FieldWriterTest, CreatesFoldersAndOneFilePerOutput) {
  FieldWriter writer(dir_ / "a" / "b");
  EXPECT_EQ(writer.directory(), dir_ / "a" / "b");
  EXPECT_TRUE(fs::is_directory(dir_ / "a" / "b" / "fields"));
  writeTwo();
  const fs::path run = dir_ / "run";
  EXPECT_TRUE(fs::exists(run / "fields" / "fields_00000000.h5"));
  EXPECT_TRUE(fs::exists(run / "fields" / "fields_00000025.h5"));
  EXPECT_TRUE(fs::exists(run / "points.xdmf"));
  EXPECT_TRUE(fs::exists(run / "nodes.xdmf"));
  // Nothing but the outputs: every temporary was renamed.
  int entries = 0;
  for (const auto& entry : fs::recursive_directory_iterator(run)) {
    EXPECT_EQ(entry.path().extension().string().find("tmp"), std::string::npos) << entry.path();
    ++entries;
  }
  EXPECT_EQ(entries, 5);
}

TEST_F(FieldWriterTest, WritesOwnedValuesExactly) {
  writeTwo();
  const fs::path file = dir_ / "run" / "fields" / "fields_00000025.h5";
  const Stores s = makeStores(1.0);
  EXPECT_EQ(readTimeAttribute(file), 2.5e-6);

  EXPECT_EQ(read<double>(file, "/points/position", H5T_NATIVE_DOUBLE), flat(s.points.x, 5));
  EXPECT_EQ(read<double>(file, "/points/velocity", H5T_NATIVE_DOUBLE), flat(s.points.v, 5));
  const std::vector<double> strain(s.points.plastic_strain.begin(), s.points.plastic_strain.begin() + 5);
  EXPECT_EQ(read<double>(file, "/points/plastic_strain", H5T_NATIVE_DOUBLE), strain);
  const std::vector<double> temperature(s.points.temperature.begin(), s.points.temperature.begin() + 5);
  EXPECT_EQ(read<double>(file, "/points/temperature", H5T_NATIVE_DOUBLE), temperature);
  EXPECT_EQ(read<double>(file, "/points/volume", H5T_NATIVE_DOUBLE), std::vector<double>(5, 0.5));
  EXPECT_EQ(read<double>(file, "/points/density", H5T_NATIVE_DOUBLE), (std::vector<double>{4, 6, 8, 10, 12}));
  EXPECT_EQ(read<std::uint8_t>(file, "/points/eroded", H5T_NATIVE_UINT8), (std::vector<std::uint8_t>{0, 0, 0, 0, 1}));
  EXPECT_EQ(read<std::int32_t>(file, "/points/body", H5T_NATIVE_INT32), (std::vector<std::int32_t>{0, 0, 0, 1, 1}));
  EXPECT_EQ(read<std::int64_t>(file, "/points/id", H5T_NATIVE_INT64),
            (std::vector<std::int64_t>{1000, 1001, 1002, 1003, 1004}));

  EXPECT_EQ(read<double>(file, "/nodes/position", H5T_NATIVE_DOUBLE), flat(s.nodes.x, 4));
  EXPECT_EQ(read<double>(file, "/nodes/velocity", H5T_NATIVE_DOUBLE), flat(s.nodes.v, 4));
  EXPECT_EQ(read<double>(file, "/nodes/mass", H5T_NATIVE_DOUBLE), (std::vector<double>{0, 1.5, 3, 4.5}));
  EXPECT_EQ(read<std::int32_t>(file, "/nodes/body", H5T_NATIVE_INT32), (std::vector<std::int32_t>{0, 1, 0, 1}));
  EXPECT_EQ(read<std::int64_t>(file, "/nodes/id", H5T_NATIVE_INT64), (std::vector<std::int64_t>{7, 8, 9, 10}));

  // The first output holds the first state, not the second.
  const fs::path first = dir_ / "run" / "fields" / "fields_00000000.h5";
  EXPECT_EQ(readTimeAttribute(first), 0.0);
  EXPECT_EQ(read<double>(first, "/nodes/position", H5T_NATIVE_DOUBLE), flat(makeStores(0.0).nodes.x, 4));
}

TEST_F(FieldWriterTest, PressureAndVonMisesFromStress) {
  writeTwo();
  const fs::path file = dir_ / "run" / "fields" / "fields_00000000.h5";
  const auto pressure = read<double>(file, "/points/pressure", H5T_NATIVE_DOUBLE);
  const auto von_mises = read<double>(file, "/points/von_mises", H5T_NATIVE_DOUBLE);
  ASSERT_EQ(pressure.size(), 5u);
  ASSERT_EQ(von_mises.size(), 5u);
  // Uniaxial 300 MPa: p = -100 MPa, von Mises = 300 MPa (exact in binary floating point).
  EXPECT_EQ(pressure[0], -1e8);
  EXPECT_EQ(von_mises[0], 3e8);
  // Pure shear 100 MPa: p = 0, von Mises = sqrt(3) 100 MPa.
  EXPECT_EQ(pressure[1], 0.0);
  EXPECT_DOUBLE_EQ(von_mises[1], std::sqrt(3.0) * 1e8);
  // Hydrostatic compression 2 GPa: p = 2 GPa, no deviator.
  EXPECT_EQ(pressure[2], 2e9);
  EXPECT_EQ(von_mises[2], 0.0);
  // General tensor against the textbook formula in components.
  const double xx = 1e8, yy = -5e7, zz = 2.5e8, xy = 2e7, yz = 4e7, zx = -3e7;
  EXPECT_DOUBLE_EQ(pressure[3], -(xx + yy + zz) / 3.0);
  const double textbook = std::sqrt(0.5 * ((xx - yy) * (xx - yy) + (yy - zz) * (yy - zz) + (zz - xx) * (zz - xx) +
                                           6.0 * (xy * xy + yz * yz + zx * zx)));
  EXPECT_DOUBLE_EQ(von_mises[3], textbook);
  EXPECT_EQ(pressure[4], 0.0);
  EXPECT_EQ(von_mises[4], 0.0);
}

// Every DataItem of an XDMF file names an existing dataset of the stated shape and type.
void checkXdmf(const fs::path& xdmf, const std::vector<double>& times, hsize_t count) {
  const std::string text = slurp(xdmf);
  ASSERT_NE(text.find("<Xdmf Version=\"3.0\">"), std::string::npos);
  ASSERT_NE(text.find("GridType=\"Collection\" CollectionType=\"Temporal\""), std::string::npos);

  const std::regex time_pattern(R"re(<Time Value="([^"]*)"/>)re");
  std::vector<double> found_times;
  for (std::sregex_iterator m(text.begin(), text.end(), time_pattern), end; m != end; ++m)
    found_times.push_back(std::stod((*m)[1]));
  EXPECT_EQ(found_times, times);

  const std::regex topology_pattern(
      R"re(<Topology TopologyType="Polyvertex" NumberOfElements="(\d+)" NodesPerElement="1">\s*<DataItem )re");
  int topologies = 0;
  for (std::sregex_iterator m(text.begin(), text.end(), topology_pattern), end; m != end; ++m, ++topologies)
    EXPECT_EQ(std::stoull((*m)[1]), count);
  EXPECT_EQ(topologies, static_cast<int>(times.size()));

  const std::regex item_pattern(R"re(<DataItem Dimensions="([^"]*)" NumberType="([^"]*)" Precision="(\d+)" )re"
                                R"re(Format="HDF">([^:<]*):([^<]*)</DataItem>)re");
  int items = 0;
  for (std::sregex_iterator m(text.begin(), text.end(), item_pattern), end; m != end; ++m, ++items) {
    const std::string file = (*m)[4], name = (*m)[5];
    SCOPED_TRACE(file + ":" + name);
    EXPECT_FALSE(fs::path(file).is_absolute());
    const auto dataset = inspect(xdmf.parent_path() / file, name);
    ASSERT_TRUE(dataset.has_value());
    std::istringstream dims_text((*m)[1]);
    std::vector<hsize_t> dims;
    for (hsize_t d; dims_text >> d;) dims.push_back(d);
    EXPECT_EQ(dataset->dims, dims);
    EXPECT_EQ(dataset->dims.front(), count);
    EXPECT_EQ(dataset->type_size, std::stoul((*m)[3]));
    const std::string number_type = (*m)[2];
    if (number_type == "Float") {
      EXPECT_EQ(dataset->type_class, H5T_FLOAT);
    } else {
      EXPECT_EQ(dataset->type_class, H5T_INTEGER);
      const bool is_unsigned = number_type == "UInt" || number_type == "UChar";
      EXPECT_EQ(dataset->sign, is_unsigned ? H5T_SGN_NONE : H5T_SGN_2);
    }
  }
  EXPECT_GT(items, 0);
}

TEST_F(FieldWriterTest, XdmfListsEveryOutputWithMatchingDatasets) {
  writeTwo();
  checkXdmf(dir_ / "run" / "points.xdmf", {0.0, 2.5e-6}, 5);
  checkXdmf(dir_ / "run" / "nodes.xdmf", {0.0, 2.5e-6}, 4);
  // 2 grids x (vertex cells + geometry + 12 attributes) for points.
  const std::string points = slurp(dir_ / "run" / "points.xdmf");
  std::size_t items = 0;
  for (auto at = points.find("<DataItem "); at != std::string::npos; at = points.find("<DataItem ", at + 1)) ++items;
  EXPECT_EQ(items, 28u);
  for (const char* name : {"velocity", "density", "pressure", "von_mises", "plastic_strain", "temperature", "eroded",
                           "loose", "carrier", "body", "id", "volume"})
    EXPECT_NE(points.find(std::string("<Attribute Name=\"") + name + "\""), std::string::npos) << name;
}

TEST_F(FieldWriterTest, RewritingAStepReplacesIt) {
  FieldWriter writer(dir_);
  const Stores a = makeStores(0.0), b = makeStores(3.0);
  writer.write(1, 1e-6, a.nodes.cloud(), a.points);
  writer.write(2, 2e-6, a.nodes.cloud(), a.points);
  writer.write(2, 2e-6, b.nodes.cloud(), b.points);
  checkXdmf(dir_ / "points.xdmf", {1e-6, 2e-6}, 5);
  EXPECT_EQ(read<double>(dir_ / "fields" / "fields_00000002.h5", "/nodes/position", H5T_NATIVE_DOUBLE),
            flat(b.nodes.x, 4));
}

TEST_F(FieldWriterTest, EmptyStoresWriteEmptyGrids) {
  FieldWriter writer(dir_);
  writer.write(0, 0.0, NodeCloud{}, PointStore{});
  checkXdmf(dir_ / "points.xdmf", {0.0}, 0);
  checkXdmf(dir_ / "nodes.xdmf", {0.0}, 0);
}

TEST_F(FieldWriterTest, CannotCreateFolderNamesIt) {
  fs::create_directories(dir_);
  std::ofstream(dir_ / "plain_file") << "x";
  try {
    FieldWriter writer(dir_ / "plain_file" / "out");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find((dir_ / "plain_file").string()), std::string::npos) << e.what();
  }
}

TEST_F(FieldWriterTest, Hdf5FailureThrowsQuietlyAndKeepsEarlierOutputs) {
  FieldWriter writer(dir_);
  const Stores s = makeStores(0.0);
  writer.write(1, 1e-6, s.nodes.cloud(), s.points);
  // A folder where the temporary file should go makes H5Fcreate fail.
  fs::create_directories(dir_ / "fields" / "fields_00000002.h5.tmp");
  std::ofstream(dir_ / "fields" / "fields_00000002.h5.tmp" / "keep") << "x";
  ::testing::internal::CaptureStderr();
  try {
    writer.write(2, 2e-6, s.nodes.cloud(), s.points);
    ADD_FAILURE() << "expected an error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("fields_00000002.h5"), std::string::npos) << what;
    EXPECT_NE(what.find("create the file"), std::string::npos) << what;
  }
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_FALSE(fs::exists(dir_ / "fields" / "fields_00000002.h5"));
  checkXdmf(dir_ / "points.xdmf", {1e-6}, 5);
  // The writer is still usable once the obstacle is gone.
  fs::remove_all(dir_ / "fields" / "fields_00000002.h5.tmp");
  writer.write(2, 2e-6, s.nodes.cloud(), s.points);
  checkXdmf(dir_ / "points.xdmf", {1e-6, 2e-6}, 5);
}

TEST_F(FieldWriterTest, StoreShorterThanOwnedIsAnError) {
  FieldWriter writer(dir_);
  Stores s = makeStores(0.0);
  s.points.temperature.resize(2);
  EXPECT_THROW(writer.write(0, 0.0, s.nodes.cloud(), s.points), Error);
  EXPECT_FALSE(fs::exists(dir_ / "points.xdmf"));
  EXPECT_FALSE(fs::exists(dir_ / "fields" / "fields_00000000.h5"));
  EXPECT_FALSE(fs::exists(dir_ / "fields" / "fields_00000000.h5.tmp"));
}

}  // namespace
}  // namespace kessler::io
