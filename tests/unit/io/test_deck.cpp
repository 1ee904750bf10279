// Parsing of valid decks into SI values, defaults, file-level errors and the memory estimate.
#include "core/error.hpp"
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace kessler::io {
namespace {

namespace fs = std::filesystem;

const fs::path deck_dir = fs::path(KESSLER_TEST_DATA) / "decks";

void expectVec(const Vec3& actual, const Vec3& expected) {
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(actual[i], expected[i]) << "component " << i;
}

std::string errorOf(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parseDeckString(text, "deck.yaml", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Deck, ParsesTheImpactDeckIntoSIValues) {
  const RunConfig c = parseDeck(deck_dir / "good_impact.yaml");
  EXPECT_EQ(c.title, "Elastic aluminium sphere on a plate");
  EXPECT_EQ(c.deck_path, (deck_dir / "good_impact.yaml").string());
  ASSERT_EQ(c.materials.size(), 1u);
  EXPECT_EQ(c.materials[0].name, "al");
  EXPECT_EQ(c.materials[0].model, "neo-hookean");
  EXPECT_DOUBLE_EQ(c.materials[0].neo_hookean.density, 2700.0);
  EXPECT_DOUBLE_EQ(c.materials[0].neo_hookean.youngs_modulus, 70e9);
  EXPECT_DOUBLE_EQ(c.materials[0].neo_hookean.poisson_ratio, 0.33);

  ASSERT_EQ(c.bodies.size(), 2u);
  const BodyConfig& ball = c.bodies[0];
  EXPECT_EQ(ball.name, "projectile");
  EXPECT_EQ(ball.material, 0);
  const auto* sphere = std::get_if<geometry::Sphere>(&ball.mesh.shape);
  ASSERT_NE(sphere, nullptr);
  expectVec(sphere->center, Vec3(0, 0, 5.1e-3));
  EXPECT_DOUBLE_EQ(sphere->radius, 5e-3);
  expectVec(ball.velocity, Vec3(0, 0, -200));
  EXPECT_DOUBLE_EQ(ball.mesh.mesh_size, 5e-4);
  EXPECT_FALSE(ball.mesh.refine.has_value());
  EXPECT_EQ(ball.fixed, geometry::FixedNodes::none);
  EXPECT_EQ(ball.mesh.symmetry_axes, std::vector<int>{0});

  const BodyConfig& plate = c.bodies[1];
  const auto* box = std::get_if<geometry::Box>(&plate.mesh.shape);
  ASSERT_NE(box, nullptr);
  expectVec(box->min, Vec3(-0.02, -0.02, -0.002));
  expectVec(box->max, Vec3(0.02, 0.02, 0));
  expectVec(plate.velocity, Vec3::Zero());
  ASSERT_TRUE(plate.mesh.refine.has_value());
  expectVec(plate.mesh.refine->center, Vec3::Zero());
  EXPECT_DOUBLE_EQ(plate.mesh.refine->radius, 0.012);
  EXPECT_DOUBLE_EQ(plate.mesh.refine->size, 3e-4);
  EXPECT_EQ(plate.fixed, geometry::FixedNodes::lateral_faces);

  EXPECT_EQ(c.symmetry_axes, std::vector<int>{0});
  EXPECT_DOUBLE_EQ(c.solver.end_time, 20e-6);
  EXPECT_DOUBLE_EQ(c.solver.cfl, 0.3);
  EXPECT_DOUBLE_EQ(c.otm.lme_gamma, 1.8);
  EXPECT_DOUBLE_EQ(c.otm.lme_tolerance, 1e-6);
  EXPECT_EQ(c.otm.min_neighbours, 12);
  EXPECT_DOUBLE_EQ(c.output.every, 1e-6);
  EXPECT_EQ(c.output.dir, "out");
}

TEST(Deck, FillsDefaults) {
  const RunConfig c = parseDeck(deck_dir / "good_minimal.yaml");
  const SolverSettings defaults;
  const OtmOptions otm_defaults;
  EXPECT_EQ(c.title, "");
  EXPECT_EQ(c.materials[0].model, "neo-hookean");
  EXPECT_TRUE(c.symmetry_axes.empty());
  EXPECT_EQ(c.bodies[0].fixed, geometry::FixedNodes::none);
  EXPECT_DOUBLE_EQ(c.solver.end_time, 10e-6);
  EXPECT_DOUBLE_EQ(c.solver.cfl, defaults.cfl);
  EXPECT_DOUBLE_EQ(c.otm.lme_gamma, otm_defaults.lme_gamma);
  EXPECT_DOUBLE_EQ(c.otm.lme_tolerance, otm_defaults.lme_tolerance);
  EXPECT_EQ(c.otm.min_neighbours, otm_defaults.min_neighbours);
  EXPECT_EQ(c.solver.max_steps, defaults.max_steps);
  EXPECT_DOUBLE_EQ(c.otm.contact_distance, otm_defaults.contact_distance);
  EXPECT_DOUBLE_EQ(c.output.every, 10e-6 / 20);
  EXPECT_EQ(c.output.dir, "out");
}

TEST(Deck, AcceptsNumbersAndQuantitiesAlike) {
  const std::string text = R"(
materials:
  al: { density: 2700, youngs_modulus: 7e10, poisson_ratio: 0.33 }
bodies:
  - name: rod
    material: al
    shape: { cylinder: { base: [0, 0, 0], axis: [0, 0, 0.03], radius: "5 mm" } }
    velocity: [0.1 km/s, 0, 0]
    mesh_size: 0.001
solver: { end_time: 2e-5, max_steps: 1e3, contact_distance: 0 }
output: { every: 0 }
)";
  const RunConfig c = parseDeckString(text, "deck.yaml");
  EXPECT_DOUBLE_EQ(c.materials[0].neo_hookean.youngs_modulus, 7e10);
  const auto& rod = std::get<geometry::Cylinder>(c.bodies[0].mesh.shape);
  expectVec(rod.axis, Vec3(0, 0, 0.03));
  EXPECT_DOUBLE_EQ(rod.radius, 5e-3);
  expectVec(c.bodies[0].velocity, Vec3(100, 0, 0));
  EXPECT_EQ(c.solver.max_steps, 1000);
  EXPECT_DOUBLE_EQ(c.otm.contact_distance, 0.0);
  EXPECT_DOUBLE_EQ(c.output.every, 0.0);
}

// OTM's keys live in solver.otm; directly under solver (where they were before) they still work,
// but not both at once, and an unknown key in either place names the keys of that place.
TEST(Deck, TakesOtmKeysFromSolverOtmAndTheirOldPlace) {
  const std::string head = R"(
materials:
  al: { density: 2700, youngs_modulus: 7e10, poisson_ratio: 0.33 }
bodies:
  - { name: cube, material: al, shape: { box: { min: [0, 0, 0], max: [0.01, 0.01, 0.01] } }, mesh_size: 0.005 }
)";
  const RunConfig nested = parseDeckString(
      head + "solver: { end_time: 1 us, otm: { lme_gamma: 2, min_neighbours: 20, crack_visibility: true } }\n",
      "deck.yaml");
  EXPECT_DOUBLE_EQ(nested.otm.lme_gamma, 2.0);
  EXPECT_EQ(nested.otm.min_neighbours, 20);
  EXPECT_TRUE(nested.otm.crack_visibility);
  EXPECT_EQ(nested.otm.lme_tolerance, OtmOptions{}.lme_tolerance);
  const RunConfig old = parseDeckString(
      head + "solver: { end_time: 1 us, lme_gamma: 2, min_neighbours: 20, crack_visibility: true }\n", "deck.yaml");
  EXPECT_DOUBLE_EQ(old.otm.lme_gamma, 2.0);
  EXPECT_EQ(old.otm.min_neighbours, 20);
  EXPECT_TRUE(old.otm.crack_visibility);

  auto errorOf = [&](const std::string& solver) -> std::string {
    try {
      parseDeckString(head + solver, "deck.yaml");
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_NE(errorOf("solver: { end_time: 1 us, lme_gamma: 2, otm: { min_neighbours: 20 } }\n")
                .find("solver.lme_gamma: belongs in solver.otm, which this deck also has"),
            std::string::npos);
  EXPECT_NE(errorOf("solver: { end_time: 1 us, otm: { gamma: 2 } }\n")
                .find("solver.otm.gamma: unknown key (allowed: lme_gamma, lme_tolerance, min_neighbours, "
                      "contact_distance, crack_visibility, volume_averaging)"),
            std::string::npos);
  EXPECT_NE(errorOf("solver: { end_time: 1 us, otm: { lme_tolerance: 2 } }\n")
                .find("solver.otm.lme_tolerance: must lie in (0, 1)"),
            std::string::npos);
}

TEST(Deck, ResolvesMeshFilesAgainstTheDeckFolder) {
  const fs::path dir = fs::temp_directory_path() / "kessler_test_deck_mesh";
  fs::create_directories(dir / "meshes");
  std::ofstream(dir / "meshes" / "plate.msh") << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  std::ofstream(dir / "deck.yaml") << R"(
materials: { al: { density: 2700, youngs_modulus: 70 GPa, poisson_ratio: 0.3 } }
bodies:
  - { name: plate, material: al, shape: { mesh: { file: meshes/plate.msh, scale: 1 mm } }, mesh_size: 1 mm }
solver: { end_time: 1 us }
)";
  const RunConfig c = parseDeck(dir / "deck.yaml");
  const auto& mesh = std::get<geometry::MeshFile>(c.bodies[0].mesh.shape);
  EXPECT_EQ(fs::path(mesh.path), fs::absolute(dir / "meshes" / "plate.msh").lexically_normal());
  EXPECT_DOUBLE_EQ(mesh.scale, 1e-3);
  fs::remove_all(dir);
}

TEST(Deck, ReportsAFileThatCannotBeRead) {
  const std::string missing = (deck_dir / "no_such_deck.yaml").string();
  EXPECT_THROW(parseDeck(missing), InputError);
  try {
    parseDeck(missing);
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": cannot read the deck: no such file");
  }
  try {
    parseDeck(deck_dir);
    FAIL() << "a directory parsed as a deck";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("it is a directory"), std::string::npos) << e.what();
  }
}

TEST(Deck, NamesLineAndColumnOneBased) {
  const std::string text =
      "materials:\n"
      "  al: { density: 2700, youngs_modulus: 70 GPa, poisson_ratio: 0.33 }\n"
      "bodies:\n"
      "  - name: ball\n"
      "    material: al\n"
      "    shape: { sphere: { center: [0, 0, 0], radius: 5 mm } }\n"
      "    mesh_size:  -1 mm\n"
      "solver: { end_time: 1 us }\n";
  EXPECT_EQ(errorOf(text), "deck.yaml:7:17: bodies[0].mesh_size: must be positive (got '-1 mm')");
}

TEST(Deck, EstimatesMemoryFromVolumesAndMeshSizes) {
  RunConfig c;
  BodyConfig cube;
  cube.mesh.shape = geometry::Box{Vec3(-5e-3, -5e-3, -5e-3), Vec3(5e-3, 5e-3, 5e-3)};
  cube.mesh.mesh_size = 1e-3;
  c.bodies.push_back(cube);
  // 1e-6 m^3 / (0.1 * 1e-9 m^3) = 1e4 tetrahedra at 3 KiB each.
  const double whole = estimateMemoryBytes(c);
  EXPECT_NEAR(whole, 1e4 * 3072.0, 1e-6 * whole);

  c.symmetry_axes = {0, 2};
  EXPECT_NEAR(estimateMemoryBytes(c), whole / 4, 1e-6 * whole);

  c.symmetry_axes.clear();
  c.bodies[0].mesh.refine = geometry::Refinement{Vec3(5e-3, 5e-3, 5e-3), 1e-3, 0.1e-3};
  // A zone of 1/8 of a 1 mm ball at the corner, meshed 1000 times finer per volume.
  const double zone = std::acos(-1.0) / 6.0 * 1e-9;
  const double expected = (1e-6 - zone) / 1e-10 + zone / (0.1 * 1e-12);
  EXPECT_NEAR(estimateMemoryBytes(c), expected * 3072.0, 0.01 * expected * 3072.0);
}

}  // namespace
}  // namespace kessler::io
