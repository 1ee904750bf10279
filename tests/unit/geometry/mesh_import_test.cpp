// Import of Gmsh .msh files: hand-written, written by Gmsh, round trip, and bad files.
#include "core/error.hpp"
#include "geometry/mesh.hpp"
#include "mesh_checks.hpp"

#include <fmt/format.h>
#include <gmsh.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

namespace kessler::geometry {
namespace {

namespace fs = std::filesystem;
using testing::expectWellFormed;
using testing::meshRequest;
using testing::totalVolume;

class MeshImport : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / fmt::format("kessler_geometry_{}_{}", info->name(), ::getpid());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) const {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path.string();
  }

  // Runs meshShape on the file and expects an InputError whose message names the file and
  // contains `why`.
  void expectRefused(const std::string& path, const std::string& why, std::vector<int> axes = {}) const {
    try {
      meshShape(meshRequest(MeshFile{path, 1.0}, 0.0, std::move(axes)));
      ADD_FAILURE() << "no error for " << path;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(path), std::string::npos) << message;
      EXPECT_NE(message.find(why), std::string::npos) << message;
    }
  }

  fs::path dir_;
};

// MSH 2.2 with the given node lines ("tag x y z") and element lines.
std::string msh2(const std::vector<std::string>& nodes, const std::vector<std::string>& elements) {
  std::string text = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" + std::to_string(nodes.size()) + "\n";
  for (const auto& n : nodes) text += n + "\n";
  text += "$EndNodes\n$Elements\n" + std::to_string(elements.size()) + "\n";
  for (const auto& e : elements) text += e + "\n";
  return text + "$EndElements\n";
}

const std::vector<std::string> corner_nodes{"1 0 0 0", "2 1 0 0", "3 0 1 0", "4 0 0 1",
                                            "5 1 1 1", "6 1 1 0", "9 5 5 5"};

TEST_F(MeshImport, HandWrittenMshIsScaledOrientedAndCompacted) {
  // A surface triangle (ignored), a positive tet, an inverted one; nodes 6 and 9 are used by no tet.
  const std::string path = write(
      "two_tets.msh", msh2(corner_nodes, {"1 2 2 0 1 1 2 3", "2 4 2 0 1 1 2 3 4", "3 4 2 0 1 2 4 3 5"}));
  const TetMesh mesh = meshShape(meshRequest(MeshFile{path, 1e-3}, 0.0));
  expectWellFormed(mesh);
  ASSERT_EQ(mesh.vertices.size(), 5u);
  ASSERT_EQ(mesh.tets.size(), 2u);
  EXPECT_TRUE(mesh.vertices[4].isApprox(Vec3(1e-3, 1e-3, 1e-3)));
  EXPECT_NEAR(totalVolume(mesh), (1.0 / 6.0 + 1.0 / 3.0) * 1e-9, 1e-24);
}

TEST_F(MeshImport, RoundTripOfAGeneratedMesh) {
  const TetMesh original = meshShape(meshRequest(Box{Vec3(0, 0, 0), Vec3(3e-3, 2e-3, 1e-3)}, 1e-3));
  std::vector<std::string> nodes;
  std::vector<std::string> elements;
  for (std::size_t v = 0; v < original.vertices.size(); ++v) {
    const Vec3& x = original.vertices[v];
    nodes.push_back(fmt::format("{} {:.17g} {:.17g} {:.17g}", v + 1, x.x(), x.y(), x.z()));
  }
  for (std::size_t e = 0; e < original.tets.size(); ++e) {
    const auto& t = original.tets[e];
    elements.push_back(fmt::format("{} 4 2 0 1 {} {} {} {}", e + 1, t[0] + 1, t[1] + 1, t[2] + 1, t[3] + 1));
  }
  const std::string path = write("geometry_round_trip.msh", msh2(nodes, elements));
  const TetMesh copy = meshShape(meshRequest(MeshFile{path, 1.0}, 0.0, {0, 1, 2}));
  ASSERT_EQ(copy.vertices.size(), original.vertices.size());
  for (std::size_t v = 0; v < copy.vertices.size(); ++v) EXPECT_EQ(copy.vertices[v], original.vertices[v]);
  EXPECT_EQ(copy.tets, original.tets);
}

TEST_F(MeshImport, ReadsMsh4WrittenByGmsh) {
  const fs::path path = dir_ / "gmsh_box.msh";
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::model::add("box");
  gmsh::model::occ::addBox(0, 0, 0, 2, 3, 4);  // millimetres
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", 1.0);
  gmsh::model::mesh::generate(3);
  gmsh::write(path.string());
  gmsh::finalize();

  const TetMesh mesh = meshShape(meshRequest(MeshFile{path.string(), 1e-3}, 0.0, {2}));
  expectWellFormed(mesh);
  EXPECT_NEAR(totalVolume(mesh), 24e-9, 1e-12 * 24e-9);
}

TEST_F(MeshImport, SnapsRoundOffOntoTheSymmetryPlane) {
  const std::string path =
      write("round_off.msh", msh2({"1 -1e-12 0 0", "2 1 0 0", "3 0 1 0", "4 0 0 1"}, {"1 4 2 0 1 1 2 3 4"}));
  const TetMesh mesh = meshShape(meshRequest(MeshFile{path, 1.0}, 0.0, {0}));
  EXPECT_EQ(mesh.vertices[0].x(), 0.0);
}

TEST_F(MeshImport, RefusesMissingAndUnreadableFiles) {
  expectRefused((dir_ / "does_not_exist.msh").string(), "cannot open");
  expectRefused(write("garbage.msh", "garbage blah\nfoo 1 2 3\n"), "not a Gmsh .msh file");
  expectRefused(write("empty.msh", ""), "not a Gmsh .msh file");
  expectRefused(write("truncated.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 2 1\n"),
                "Gmsh cannot read");
  expectRefused(write("broken.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\nmany\n"),
                "Gmsh cannot read");
  expectRefused(dir_.string(), "");
}

TEST_F(MeshImport, RefusesMeshesKesslerCannotUse) {
  expectRefused(write("surface.msh", msh2(corner_nodes, {"1 2 2 0 1 1 2 3"})), "no tetrahedra");
  expectRefused(write("flat.msh", msh2(corner_nodes, {"1 4 2 0 1 1 2 3 6"})), "degenerate");
  expectRefused(
      write("negative.msh", msh2({"1 -0.5 0 0", "2 1 0 0", "3 0 1 0", "4 0 0 1"}, {"1 4 2 0 1 1 2 3 4"})),
      "negative side of the symmetry plane x=0", {0});
  const std::vector<std::string> quadratic_nodes{"1 0 0 0",     "2 1 0 0",     "3 0 1 0",   "4 0 0 1",
                                                 "5 0.5 0 0",   "6 0.5 0.5 0", "7 0 0.5 0", "8 0 0 0.5",
                                                 "9 0 0.5 0.5", "10 0.5 0 0.5"};
  expectRefused(write("quadratic.msh", msh2(quadratic_nodes, {"1 11 2 0 1 1 2 3 4 5 6 7 8 9 10"})),
                "linear 4-node tetrahedra");
}

}  // namespace
}  // namespace kessler::geometry
