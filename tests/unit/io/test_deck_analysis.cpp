// The deck's `analysis` section (defaults inferred from the bodies), projectiles given by mass, and
// the resolved deck carrying both.
#include "core/error.hpp"
#include "io/deck.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace kessler::io {
namespace {

const std::string whipple = R"(
materials:
  al: { library: Al6061-T6 }
bodies:
  - name: rear
    material: al
    shape: { box: { min: [-30 mm, -30 mm, -103.86 mm], max: [30 mm, 30 mm, -101.92 mm] } }
    mesh_size: 1.94 mm
  - name: ball
    material: al
    shape: { sphere: { center: [0, 0, 2.8 mm], mass: 0.1767 g } }
    velocity: [0, 0, -5.3 km/s]
    mesh_size: 1 mm
  - name: bumper
    material: al
    shape: { box: { min: [-12 mm, -12 mm, -1.92 mm], max: [12 mm, 12 mm, 0] } }
    mesh_size: 1 mm
  - name: side
    material: al
    shape: { box: { min: [50 mm, -12 mm, -1.92 mm], max: [60 mm, 12 mm, 0] } }
    mesh_size: 1 mm
solver: { end_time: 20 us }
)";

TEST(DeckAnalysis, InfersTheProjectileAndThePlatesInShotOrder) {
  const RunConfig c = parseDeckString(whipple, "deck.yaml");
  const AnalysisConfig& a = c.analysis;
  EXPECT_TRUE(a.enabled);
  ASSERT_EQ(a.projectiles.size(), 1u);
  EXPECT_EQ(a.projectiles[0], 1);
  // The side box is off the shot line: not a plate.
  ASSERT_EQ(a.plates.size(), 2u);
  EXPECT_EQ(a.plates[0], 2);
  EXPECT_EQ(a.plates[1], 0);
  EXPECT_DOUBLE_EQ(a.impact_speed, 5300.0);
  EXPECT_DOUBLE_EQ(a.shot_direction[2], -1.0);
  EXPECT_EQ(a.cloud_reference, 0);
  EXPECT_TRUE(a.plots);
}

TEST(DeckAnalysis, GivesASphereTheRadiusOfItsMass) {
  const RunConfig c = parseDeckString(whipple, "deck.yaml");
  const auto& sphere = std::get<geometry::Sphere>(c.bodies[1].mesh.shape);
  const double density = 2703.0;  // the library's Al 6061-T6
  EXPECT_NEAR(4.0 / 3.0 * std::numbers::pi * std::pow(sphere.radius, 3) * density, 0.1767e-3, 1e-12);
}

TEST(DeckAnalysis, GivesACylinderTheLengthOfItsMass) {
  const RunConfig c = parseDeckString(R"(
materials:
  cu: { library: OFHC-copper }
bodies:
  - name: slug
    material: cu
    shape: { cylinder: { base: [0, 0, 1 mm], axis: [0, 0, 5], radius: 3 mm, mass: 3 g } }
    mesh_size: 1 mm
solver: { end_time: 20 us }
)",
                                      "deck.yaml");
  const auto& cylinder = std::get<geometry::Cylinder>(c.bodies[0].mesh.shape);
  EXPECT_NEAR(cylinder.axis.norm(), 3e-3 / (8930.0 * std::numbers::pi * 9e-6), 1e-12);
  EXPECT_DOUBLE_EQ(cylinder.axis.normalized()[2], 1.0);
  EXPECT_FALSE(c.analysis.enabled);  // nothing moves
}

TEST(DeckAnalysis, TheDeckOverridesTheInferredChoices) {
  const RunConfig c = parseDeckString(whipple +
                                          "analysis: { plates: [bumper], plots: false, link_stretch: 3, "
                                          "rear_wall: { yield_stress: 300 MPa } }\n",
                                      "deck.yaml");
  ASSERT_EQ(c.analysis.plates.size(), 1u);
  EXPECT_EQ(c.analysis.plates[0], 2);
  EXPECT_FALSE(c.analysis.plots);
  EXPECT_DOUBLE_EQ(c.analysis.link_stretch, 3.0);
  EXPECT_DOUBLE_EQ(c.analysis.wall_yield_stress, 300e6);
  EXPECT_TRUE(c.analysis.wall_given);
  EXPECT_TRUE(parseDeckString(resolvedDeckText(c), "resolved.yaml").analysis.wall_given);
}

TEST(DeckAnalysis, TheResolvedDeckReadsBackTheSame) {
  const RunConfig c = parseDeckString(whipple + "analysis: { cloud_reference: rear }\n", "deck.yaml");
  const RunConfig again = parseDeckString(resolvedDeckText(c), "resolved.yaml");
  EXPECT_EQ(again.analysis.projectiles, c.analysis.projectiles);
  EXPECT_EQ(again.analysis.plates, c.analysis.plates);
  EXPECT_EQ(again.analysis.cloud_reference, 1);
  EXPECT_EQ(again.analysis.shot_direction, c.analysis.shot_direction);
  EXPECT_EQ(again.analysis.plots, c.analysis.plots);
  // The wall's properties were not given: the read-back deck still has the defaults, as not given.
  EXPECT_FALSE(c.analysis.wall_given);
  EXPECT_FALSE(again.analysis.wall_given);
  EXPECT_EQ(std::get<geometry::Sphere>(again.bodies[1].mesh.shape).radius,
            std::get<geometry::Sphere>(c.bodies[1].mesh.shape).radius);
  EXPECT_EQ(again.materials[0].impact.fracture_energy, 100e3);
}

// Two satellites meeting head-on (the finite-element-reconstruction paper's sphere and cube): no
// plate, so the analysis is a collision's (fragments and the breakup model), at the relative speed.
const std::string collision = R"(
materials:
  al: { library: Al2024-T351, density: 200 kg/m^3 }
bodies:
  - name: sphere
    material: al
    shape: { sphere: { center: [-0.6, 0, 0], radius: 0.5 } }
    velocity: [7.6 km/s, 0, 0]
    mesh_size: 0.1
  - name: cube
    material: al
    shape: { box: { min: [0, -0.5, -0.5], max: [1, 0.5, 0.5] } }
    velocity: [-7.6 km/s, 0, 0]
    mesh_size: 0.1
solver: { end_time: 350 us }
)";

TEST(DeckAnalysis, ACollisionWithoutPlatesIsAnalysedAtTheRelativeSpeed) {
  const RunConfig c = parseDeckString(collision + "analysis: { projectile: sphere }\n", "deck.yaml");
  const AnalysisConfig& a = c.analysis;
  EXPECT_TRUE(a.enabled);
  ASSERT_EQ(a.projectiles, std::vector<int>{0});
  // The cube is a box on the shot line, but it moves: not a plate.
  EXPECT_TRUE(a.plates.empty());
  EXPECT_DOUBLE_EQ(a.impact_speed, 15200.0);
  EXPECT_DOUBLE_EQ(a.shot_direction[0], 1.0);
  const RunConfig again = parseDeckString(resolvedDeckText(c), "resolved.yaml");
  EXPECT_TRUE(again.analysis.enabled);
  EXPECT_EQ(again.analysis.projectiles, a.projectiles);
  EXPECT_TRUE(again.analysis.plates.empty());
  EXPECT_DOUBLE_EQ(again.analysis.impact_speed, 15200.0);
}

TEST(DeckAnalysis, BodiesThatAllMoveAreAllProjectilesWithoutATarget) {
  // Both bodies are as fast: both are the projectile, the analysis has fragments but no target.
  const AnalysisConfig a = parseDeckString(collision, "deck.yaml").analysis;
  EXPECT_TRUE(a.enabled);
  EXPECT_EQ(a.projectiles, (std::vector<int>{0, 1}));
  EXPECT_DOUBLE_EQ(a.impact_speed, 7600.0);
}

}  // namespace
}  // namespace kessler::io
