// Command-line overrides ("--set key=value") of deck values, and their errors.
#include "core/error.hpp"
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace kessler::io {
namespace {

namespace fs = std::filesystem;

const fs::path impact_deck = fs::path(KESSLER_TEST_DATA) / "decks" / "good_impact.yaml";

std::string errorOf(const std::vector<std::string>& overrides) {
  try {
    parseDeck(impact_deck, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(DeckOverrides, ReplaceValuesAnywhereInTheTree) {
  const RunConfig c = parseDeck(
      impact_deck, {"solver.end_time=5 us", "bodies.0.velocity=[0, 0, -6.18 km/s]", "bodies[1].mesh_size=0.8 mm",
                    "materials.al.density=2.8 g/cm^3", "symmetry=[x, y]", "title=Another title"});
  EXPECT_DOUBLE_EQ(c.solver.end_time, 5e-6);
  EXPECT_DOUBLE_EQ(c.bodies[0].velocity[2], -6180.0);
  EXPECT_DOUBLE_EQ(c.bodies[1].mesh.mesh_size, 8e-4);
  EXPECT_DOUBLE_EQ(c.materials[0].neo_hookean.density, 2800.0);
  EXPECT_EQ(c.symmetry_axes, (std::vector<int>{0, 1}));
  EXPECT_EQ(c.bodies[0].mesh.symmetry_axes, (std::vector<int>{0, 1}));
  EXPECT_EQ(c.title, "Another title");
}

TEST(DeckOverrides, AddKeysTheDeckLeavesOut) {
  const RunConfig c = parseDeck(fs::path(KESSLER_TEST_DATA) / "decks" / "good_minimal.yaml",
                                {"output.dir=out2", "solver.max_steps=100", "bodies.0.fixed=none"});
  EXPECT_EQ(c.output.dir, "out2");
  EXPECT_DOUBLE_EQ(c.output.every, 10e-6 / 20);
  EXPECT_EQ(c.solver.max_steps, 100);
}

TEST(DeckOverrides, TheLastOneWins) {
  const RunConfig c = parseDeck(impact_deck, {"solver.cfl=0.5", "solver.cfl = 0.2"});
  EXPECT_DOUBLE_EQ(c.solver.cfl, 0.2);
}

TEST(DeckOverrides, UnknownKeysAreErrorsFromTheCommandLine) {
  EXPECT_EQ(errorOf({"solver.endtime=5 us"}),
            "command line (--set solver.endtime=5 us): solver.endtime: unknown key (allowed: method, "
            "end_time, cfl, max_steps, min_dt_fraction, max_energy_growth, debris_contact, contact, otm)");
  EXPECT_EQ(errorOf({"outptu.dir=x"}).rfind("command line (--set outptu.dir=x): outptu: unknown key", 0), 0u);
  EXPECT_EQ(errorOf({"bodies.0.shape.cone.radius=1 mm"})
                .rfind("command line (--set bodies.0.shape.cone.radius=1 mm): bodies[0].shape", 0),
            0u);
}

TEST(DeckOverrides, BadValuesAreErrorsFromTheCommandLine) {
  EXPECT_EQ(errorOf({"bodies.0.velocity=[0, 0]"}),
            "command line (--set bodies.0.velocity=[0, 0]): bodies[0].velocity: must have 3 components, not 2 "
            "(got '[0, 0]')");
  EXPECT_EQ(errorOf({"solver.end_time=5 kg"}),
            "command line (--set solver.end_time=5 kg): solver.end_time: '5 kg' has units of kg, expected s");
  EXPECT_EQ(errorOf({"bodies.0.refine={center: [0, 0, 5 mm], size: 0.2 mm}"}),
            "command line (--set bodies.0.refine={center: [0, 0, 5 mm], size: 0.2 mm}): bodies[0].refine: missing "
            "required key 'radius'");
}

TEST(DeckOverrides, MalformedOverridesAreErrors) {
  EXPECT_EQ(errorOf({"solver.end_time"}),
            "command line (--set solver.end_time): expected key=value, e.g. solver.end_time=5 us");
  EXPECT_EQ(errorOf({"bodies.2.mesh_size=1 mm"}),
            "command line (--set bodies.2.mesh_size=1 mm): bodies: index 2 is out of range: the list has 2 "
            "entries");
  EXPECT_EQ(errorOf({"bodies.first.mesh_size=1 mm"}),
            "command line (--set bodies.first.mesh_size=1 mm): bodies: 'first' is not an index into this list");
  EXPECT_EQ(errorOf({"solver.end_time.unit=us"}),
            "command line (--set solver.end_time.unit=us): solver.end_time: is a single value, so it has no 'unit' "
            "inside it");
  EXPECT_EQ(
      errorOf({"solver..cfl=0.2"}).rfind("command line (--set solver..cfl=0.2): 'solver..cfl' is not a key path", 0),
      0u);
  EXPECT_EQ(errorOf({"solver.cfl=[0.2"}).rfind("command line (--set solver.cfl=[0.2): the value is not valid YAML", 0),
            0u);
}

TEST(DeckOverrides, ErrorsElsewhereStillPointIntoTheFile) {
  // The override is fine; the deck's own plate now overlaps the moved projectile.
  const std::string message = errorOf({"bodies.0.shape.sphere.center=[0, 0, 2 mm]"});
  EXPECT_EQ(message.rfind("command line (--set bodies.0.shape.sphere.center=[0, 0, 2 mm])", 0), std::string::npos)
      << message;
  EXPECT_NE(message.find("overlaps body 'projectile'"), std::string::npos) << message;
  EXPECT_EQ(message.rfind(impact_deck.string() + ":", 0), 0u) << message;
}

}  // namespace
}  // namespace kessler::io
