// The resolved deck: written with every default and in SI units, it parses back to the same config.
#include "io/deck.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace kessler::io {
namespace {

namespace fs = std::filesystem;

const fs::path deck_dir = fs::path(KESSLER_TEST_DATA) / "decks";

void expectSameShape(const geometry::Shape& a, const geometry::Shape& b) {
  ASSERT_EQ(a.index(), b.index());
  if (const auto* s = std::get_if<geometry::Sphere>(&a)) {
    EXPECT_EQ(s->center, std::get<geometry::Sphere>(b).center);
    EXPECT_EQ(s->radius, std::get<geometry::Sphere>(b).radius);
  } else if (const auto* x = std::get_if<geometry::Box>(&a)) {
    EXPECT_EQ(x->min, std::get<geometry::Box>(b).min);
    EXPECT_EQ(x->max, std::get<geometry::Box>(b).max);
  } else if (const auto* c = std::get_if<geometry::Cylinder>(&a)) {
    EXPECT_EQ(c->base, std::get<geometry::Cylinder>(b).base);
    EXPECT_EQ(c->axis, std::get<geometry::Cylinder>(b).axis);
    EXPECT_EQ(c->radius, std::get<geometry::Cylinder>(b).radius);
  } else {
    EXPECT_EQ(std::get<geometry::MeshFile>(a).path, std::get<geometry::MeshFile>(b).path);
    EXPECT_EQ(std::get<geometry::MeshFile>(a).scale, std::get<geometry::MeshFile>(b).scale);
  }
}

// Exact equality: the writer must print doubles that read back bit for bit.
void expectSameConfig(const RunConfig& a, const RunConfig& b) {
  EXPECT_EQ(a.title, b.title);
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (std::size_t i = 0; i < a.materials.size(); ++i) {
    EXPECT_EQ(a.materials[i].name, b.materials[i].name);
    EXPECT_EQ(a.materials[i].model, b.materials[i].model);
    EXPECT_EQ(a.materials[i].neo_hookean.density, b.materials[i].neo_hookean.density);
    EXPECT_EQ(a.materials[i].neo_hookean.youngs_modulus, b.materials[i].neo_hookean.youngs_modulus);
    EXPECT_EQ(a.materials[i].neo_hookean.poisson_ratio, b.materials[i].neo_hookean.poisson_ratio);
  }
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    const BodyConfig& x = a.bodies[i];
    const BodyConfig& y = b.bodies[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.material, y.material);
    expectSameShape(x.mesh.shape, y.mesh.shape);
    EXPECT_EQ(x.mesh.mesh_size, y.mesh.mesh_size);
    EXPECT_EQ(x.mesh.symmetry_axes, y.mesh.symmetry_axes);
    ASSERT_EQ(x.mesh.refine.has_value(), y.mesh.refine.has_value());
    if (x.mesh.refine) {
      EXPECT_EQ(x.mesh.refine->center, y.mesh.refine->center);
      EXPECT_EQ(x.mesh.refine->radius, y.mesh.refine->radius);
      EXPECT_EQ(x.mesh.refine->size, y.mesh.refine->size);
    }
    EXPECT_EQ(x.velocity, y.velocity);
    EXPECT_EQ(x.fixed, y.fixed);
  }
  EXPECT_EQ(a.symmetry_axes, b.symmetry_axes);
  EXPECT_EQ(a.solver.end_time, b.solver.end_time);
  EXPECT_EQ(a.solver.cfl, b.solver.cfl);
  EXPECT_EQ(a.otm.lme_gamma, b.otm.lme_gamma);
  EXPECT_EQ(a.otm.lme_tolerance, b.otm.lme_tolerance);
  EXPECT_EQ(a.otm.min_neighbours, b.otm.min_neighbours);
  EXPECT_EQ(a.solver.max_steps, b.solver.max_steps);
  EXPECT_EQ(a.otm.contact_distance, b.otm.contact_distance);
  EXPECT_EQ(a.otm.crack_visibility, b.otm.crack_visibility);
  EXPECT_EQ(a.otm.volume_averaging, b.otm.volume_averaging);
  EXPECT_EQ(a.solver.debris_contact, b.solver.debris_contact);
  EXPECT_EQ(a.solver.min_dt_fraction, b.solver.min_dt_fraction);
  EXPECT_EQ(a.solver.max_energy_growth, b.solver.max_energy_growth);
  EXPECT_EQ(a.output.every, b.output.every);
  EXPECT_EQ(a.output.dir, b.output.dir);
}

class ResolvedDeck : public ::testing::TestWithParam<const char*> {};

TEST_P(ResolvedDeck, ParsesBackToTheSameConfig) {
  const RunConfig original = parseDeck(deck_dir / GetParam());
  const fs::path file = fs::temp_directory_path() / fmt::format("kessler_resolved_{}", GetParam());
  writeResolvedDeck(original, file);
  const RunConfig again = parseDeck(file);
  expectSameConfig(original, again);
  // Writing is a fixed point: the resolved deck of the resolved deck is the same text.
  EXPECT_EQ(resolvedDeckText(again), resolvedDeckText(original));
  fs::remove(file);
}

INSTANTIATE_TEST_SUITE_P(GoodDecks, ResolvedDeck, ::testing::Values("good_impact.yaml", "good_minimal.yaml"));

TEST(ResolvedDeckText, IsInSIUnitsWithEveryDefault) {
  const std::string text = resolvedDeckText(parseDeck(deck_dir / "good_minimal.yaml"));
  for (const char* expected :
       {"density: 2700", "youngs_modulus: 70000000000", "radius: 0.005", "velocity: [0, 0, -200]", "mesh_size: 0.001",
        "fixed: none", "end_time: ", "cfl: 0.3", "lme_gamma: 4", "min_neighbours: 12", "max_steps: 0", "every: 5",
        "dir: out"})  // every = end_time / 20, within round-off
    EXPECT_NE(text.find(expected), std::string::npos) << "missing '" << expected << "' in\n" << text;
}

}  // namespace
}  // namespace kessler::io
