// Checkpoints: a written and re-read model is bitwise the same, a run continued from a checkpoint
// is bitwise the same as one that never stopped, and files that are not complete checkpoints of
// this run are refused with a message.
#include "core/error.hpp"
#include "geometry/structured_mesh.hpp"
#include "io/checkpoint.hpp"
#include "io/fields_writer.hpp"
#include "io/hdf5_reader.hpp"
#include "material/neo_hookean.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/otm_method.hpp"
#include "solver/otm/setup.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>

namespace kessler::io {
namespace {

namespace fs = std::filesystem;

MaterialPtr aluminium() {
  NeoHookeanParameters p;
  p.density = 2700.0;
  p.youngs_modulus = 70e9;
  p.poisson_ratio = 0.33;
  return std::make_shared<NeoHookean>("al", p);
}

// A block moving into a resting block, so that contact couples the bodies within a few steps.
otm::Model twoBlocks(const MaterialPtr& material) {
  otm::Model model;
  auto add = [&](const char* name, const geometry::Box& box, const Vec3& v) {
    const geometry::Discretisation disc = geometry::discretise(geometry::structuredBoxMesh(box, {3, 3, 2}));
    otm::addBody(model, name, material, disc, v);
  };
  add("plate", geometry::Box{Vec3(0, 0, -2e-3), Vec3(3e-3, 3e-3, 0)}, Vec3::Zero());
  add("flyer", geometry::Box{Vec3(0, 0, 0.2e-3), Vec3(3e-3, 3e-3, 2.2e-3)}, Vec3(0, 0, -500.0));
  otm::constrainNode(model, 0, 2);
  return model;
}

otm::Settings settings() {
  otm::Settings s;
  s.end_time = 1e-5;
  return s;
}

// OTM for a restored shared state, as the program's factory builds it (app/methods.cpp).
std::unique_ptr<Method> otmFor(ParticleState&& state) {
  otm::Model model;
  static_cast<ParticleState&>(model) = std::move(state);
  return std::make_unique<otm::OtmMethod>(std::move(model), settings());
}

const otm::OtmMethod& asOtm(const Method& method) {
  return dynamic_cast<const otm::OtmMethod&>(method);
}

// A method over two blocks, initialised and `steps` steps on.
std::unique_ptr<otm::OtmMethod> twoBlocksAfter(const MaterialPtr& material, int steps) {
  auto method = std::make_unique<otm::OtmMethod>(twoBlocks(material), settings());
  method->initialise();
  for (int i = 0; i < steps; ++i) method->step();
  return method;
}

template <class T>
long differing(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return static_cast<long>(std::max(a.size(), b.size()) + 1);
  long count = 0;
  for (std::size_t i = 0; i < a.size(); ++i) count += std::memcmp(&a[i], &b[i], sizeof(T)) != 0;
  return count;
}

long differences(const otm::Model& a, const otm::Model& b) {
  const PointStore &p = a.points, &q = b.points;
  const otm::NodeStore &m = a.nodes, &n = b.nodes;
  return differing(p.id, q.id) + differing(p.body, q.body) + differing(p.x, q.x) + differing(p.v, q.v) +
         differing(p.mass, q.mass) + differing(p.volume, q.volume) + differing(p.volume0, q.volume0) +
         differing(p.spacing0, q.spacing0) + differing(p.F, q.F) + differing(p.dF, q.dF) +
         differing(p.stress, q.stress) + differing(p.energy, q.energy) + differing(p.sound_speed, q.sound_speed) +
         differing(p.plastic_strain, q.plastic_strain) + differing(p.temperature, q.temperature) +
         differing(p.damage, q.damage) + differing(p.strain_energy, q.strain_energy) +
         differing(p.ductile_work, q.ductile_work) + differing(p.viscous_pressure, q.viscous_pressure) +
         differing(p.be, q.be) + differing(p.broken, q.broken) + differing(p.passes_through, q.passes_through) +
         differing(p.carrier, q.carrier) + differing(a.lme_lambda, b.lme_lambda) + differing(m.id, n.id) +
         differing(m.body, n.body) + differing(m.x, n.x) + differing(m.v, n.v) + differing(m.mass, n.mass) +
         differing(m.momentum, n.momentum) + differing(m.force, n.force) + differing(m.constrained, n.constrained) +
         differing(m.prescribed_v, n.prescribed_v) + differing(a.connectivity.offset, b.connectivity.offset) +
         differing(a.connectivity.node, b.connectivity.node) + differing(a.connectivity.N, b.connectivity.N) +
         differing(a.connectivity.dN, b.connectivity.dN) +
         differing(a.connectivity.node_offset, b.connectivity.node_offset) +
         differing(a.connectivity.node_slot, b.connectivity.node_slot);
}

class CheckpointTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           fmt::format("kessler_checkpoint_{}", ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
  MaterialPtr material_ = aluminium();
};

RunLoopState someLoopState(const Method& method) {
  RunLoopState loop;
  loop.next_output = 1.25e-6;
  loop.next_checkpoint = 3e-6;
  loop.wall_seconds = 12.5;
  loop.outputs = 2;
  const Clock clock = method.clock();
  loop.history.push_back({0, 0.0, 0.0, method.energies()});
  loop.history.push_back({clock.steps, clock.time, clock.dt_last, method.energies()});
  XdmfGrid grid{.name = "points_00000000", .time = 0.1, .vertices = 3, .geometry = {}, .attributes = {}};
  grid.geometry = xdmfItem<double>({3, 3}, "fields/fields_00000000.h5:/points/position");
  grid.attributes.push_back(
      {"eroded", "Scalar", xdmfItem<std::uint8_t>({3}, "fields/fields_00000000.h5:/points/eroded")});
  loop.point_grids = {grid};
  loop.node_grids = {grid, grid};
  return loop;
}

TEST_F(CheckpointTest, RestoresTheModelAndTheRunStateBitwise) {
  const std::unique_ptr<otm::OtmMethod> method = twoBlocksAfter(material_, 5);
  const otm::Model& model = method->model();
  const RunLoopState written = someLoopState(*method);
  writeCheckpoint(dir_ / "checkpoint.h5", *method, written);
  EXPECT_FALSE(fs::exists(dir_ / "checkpoint.h5.tmp"));

  const Restored read = readCheckpoint(dir_ / "checkpoint.h5", {material_}, otmFor);
  const otm::Model& restored = asOtm(*read.method).model();
  EXPECT_EQ(differences(model, restored), 0);
  ASSERT_EQ(restored.bodies.size(), 2u);
  EXPECT_EQ(restored.bodies[1].name, "flyer");
  EXPECT_EQ(restored.bodies[1].material, model.bodies[1].material);
  EXPECT_EQ(restored.points.body, model.points.body);
  EXPECT_EQ(restored.adjacency, model.adjacency);
  EXPECT_EQ(restored.adjacency_length0, model.adjacency_length0);
  // The blocks touch: each records the other (what its debris will pass through).
  EXPECT_EQ(model.bodies[0].touched, 0b11u);
  EXPECT_EQ(restored.bodies[0].touched, model.bodies[0].touched);
  EXPECT_EQ(restored.bodies[1].touched, model.bodies[1].touched);
  EXPECT_EQ(restored.materials.at(0), material_);
  EXPECT_EQ(read.method->clock().steps, 5);
  const otm::IntegratorState sw = method->integrator().state(), sr = asOtm(*read.method).integrator().state();
  EXPECT_EQ(std::memcmp(&sr, &sw, sizeof(otm::IntegratorState)), 0);
  EXPECT_EQ(read.loop.next_output, written.next_output);
  EXPECT_EQ(read.loop.next_checkpoint, written.next_checkpoint);
  EXPECT_EQ(read.loop.outputs, 2);
  ASSERT_EQ(read.loop.history.size(), 2u);
  EXPECT_EQ(read.loop.history[1].step, 5);
  EXPECT_EQ(std::memcmp(&read.loop.history[1].energies, &written.history[1].energies, sizeof(Energies)), 0);
  EXPECT_EQ(temporalPolyvertexXdmf("p", read.loop.point_grids), temporalPolyvertexXdmf("p", written.point_grids));
  EXPECT_EQ(read.loop.node_grids.size(), 2u);
}

// An open checkpoint file made to look like one of an older format: its format number, and no loose
// flags (new in format 7).
void asFormatBefore7(hid_t f, std::int64_t version) {
  const hid_t attr = H5Aopen(f, "kessler_checkpoint_format", H5P_DEFAULT);
  ASSERT_GE(attr, 0);
  ASSERT_GE(H5Awrite(attr, H5T_NATIVE_INT64, &version), 0);
  H5Aclose(attr);
  ASSERT_GE(H5Ldelete(f, "/points/loose", H5P_DEFAULT), 0);
}

// Format 5 stored the links by index in the store (which the Morton sort had reordered, so that
// indices and ids differ); the reader turns them into the points' ids.
TEST_F(CheckpointTest, ReadsTheLinksOfAFormat5CheckpointByIndex) {
  const std::unique_ptr<otm::OtmMethod> method = twoBlocksAfter(material_, 2);
  const otm::Model& model = method->model();
  const fs::path file = dir_ / "checkpoint.h5";
  writeCheckpoint(file, *method, someLoopState(*method));
  // A model's ids are its store order (solver/otm/morton_order.hpp), so the file gets other ids,
  // as a format-5 file of a sorted run had: then a link read as an id pair instead of an index
  // pair would name the wrong points.
  const auto n = static_cast<std::size_t>(model.points.size());
  std::vector<Index> ids(n);
  for (std::size_t p = 0; p < n; ++p) ids[p] = static_cast<Index>(1000 + 3 * (n - 1 - p));
  std::vector<LocalIndex> by_index;
  std::vector<std::array<Index, 2>> expected;
  const IdIndex index(model.points.id);
  for (const auto& [i, j] : model.adjacency) {
    const LocalIndex a = index.find(i), b = index.find(j);
    by_index.push_back(std::min(a, b));
    by_index.push_back(std::max(a, b));
    expected.push_back({std::min(ids[a], ids[b]), std::max(ids[a], ids[b])});
  }
  {
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    asFormatBefore7(f, 5);
    const hid_t id_set = H5Dopen2(f, "/points/id", H5P_DEFAULT);
    ASSERT_GE(H5Dwrite(id_set, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, ids.data()), 0);
    H5Dclose(id_set);
    ASSERT_GE(H5Ldelete(f, "/adjacency/pairs", H5P_DEFAULT), 0);
    const hsize_t dims[2] = {model.adjacency.size(), 2};
    const hid_t space = H5Screate_simple(2, dims, nullptr);
    const hid_t set = H5Dcreate2(f, "/adjacency/pairs", H5T_NATIVE_INT32, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(H5Dwrite(set, H5T_NATIVE_INT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, by_index.data()), 0);
    H5Dclose(set);
    H5Sclose(space);
    H5Fclose(f);
  }
  const Restored read = readCheckpoint(file, {material_}, otmFor);
  EXPECT_EQ(asOtm(*read.method).model().points.id, ids);
  EXPECT_EQ(asOtm(*read.method).model().adjacency, expected);
}

// Format 6 had no loose flags (PointStore::loose, new in format 7): its points read as none loose.
TEST_F(CheckpointTest, AFormat6CheckpointHasNoLoosePoints) {
  const std::unique_ptr<otm::OtmMethod> method = twoBlocksAfter(material_, 2);
  const fs::path file = dir_ / "checkpoint.h5";
  writeCheckpoint(file, *method, someLoopState(*method));
  {
    const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    asFormatBefore7(f, 6);
    H5Fclose(f);
  }
  const Restored read = readCheckpoint(file, {material_}, otmFor);
  const PointStore& points = asOtm(*read.method).model().points;
  EXPECT_EQ(points.loose, std::vector<std::uint8_t>(points.x.size(), 0));
  EXPECT_EQ(points.x, method->model().points.x);
}

TEST_F(CheckpointTest, ARestartedRunIsBitwiseTheUninterruptedRun) {
  const std::unique_ptr<otm::OtmMethod> straight = twoBlocksAfter(material_, 6);

  const std::unique_ptr<otm::OtmMethod> first = twoBlocksAfter(material_, 3);
  writeCheckpoint(dir_ / "checkpoint.h5", *first, someLoopState(*first));

  const Restored c = readCheckpoint(dir_ / "checkpoint.h5", {material_}, otmFor);
  for (int i = 0; i < 3; ++i) c.method->step();
  EXPECT_EQ(differences(straight->model(), asOtm(*c.method).model()), 0);
  const otm::IntegratorState sa = straight->integrator().state(), sr = asOtm(*c.method).integrator().state();
  EXPECT_EQ(std::memcmp(&sa, &sr, sizeof(otm::IntegratorState)), 0);
}

std::string errorOf(const fs::path& file, const std::vector<MaterialPtr>& materials) {
  try {
    readCheckpoint(file, materials, otmFor);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST_F(CheckpointTest, RefusesWhatIsNotACompleteCheckpointOfThisRun) {
  const std::unique_ptr<otm::OtmMethod> method = twoBlocksAfter(material_, 0);
  const otm::Model& model = method->model();
  const fs::path file = dir_ / "checkpoint.h5";
  writeCheckpoint(file, *method, someLoopState(*method));

  EXPECT_NE(errorOf(dir_ / "none.h5", {material_}).find("no such file"), std::string::npos);
  // A material the deck no longer has.
  NeoHookeanParameters p;
  p.density = 1000.0;
  p.youngs_modulus = 1e9;
  p.poisson_ratio = 0.3;
  EXPECT_NE(errorOf(file, {std::make_shared<NeoHookean>("rubber", p)}).find("material 'al' is not in the run's deck"),
            std::string::npos);
  // A field output is an HDF5 file, but not a checkpoint.
  FieldWriter(dir_).write(0, 0.0, model.nodes.cloud(), model.points);
  EXPECT_NE(errorOf(dir_ / "fields/fields_00000000.h5", {material_}).find("is not a Kessler checkpoint"),
            std::string::npos);
  // A file cut short, as a copy interrupted by a full disk would leave it.
  const std::uintmax_t size = fs::file_size(file);
  fs::copy_file(file, dir_ / "cut.h5");
  fs::resize_file(dir_ / "cut.h5", size / 2);
  EXPECT_NE(errorOf(dir_ / "cut.h5", {material_}).find("cut.h5"), std::string::npos);
  // Garbage.
  std::ofstream(dir_ / "garbage.h5") << "not hdf5 at all";
  EXPECT_NE(errorOf(dir_ / "garbage.h5", {material_}).find("cannot open the file"), std::string::npos);
}

TEST_F(CheckpointTest, AFailedWriteKeepsThePreviousCheckpoint) {
  const std::unique_ptr<otm::OtmMethod> method = twoBlocksAfter(material_, 0);
  const fs::path file = dir_ / "checkpoint.h5";
  writeCheckpoint(file, *method, someLoopState(*method));
  // A store whose fields disagree in length cannot be written; the old file must survive.
  otm::Model broken_model = method->model();
  broken_model.points.energy.pop_back();
  const otm::OtmMethod broken(std::move(broken_model), settings());
  EXPECT_THROW(writeCheckpoint(file, broken, someLoopState(*method)), Error);
  EXPECT_FALSE(fs::exists(dir_ / "checkpoint.h5.tmp"));
  Restored restored;
  EXPECT_NO_THROW(restored = readCheckpoint(file, {material_}, otmFor));
  ASSERT_TRUE(restored.method);
  EXPECT_EQ(differences(method->model(), asOtm(*restored.method).model()), 0);
}

}  // namespace
}  // namespace kessler::io
