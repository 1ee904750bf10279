// The modules every method calls (solver/common/): prescribed components and rigid walls, the
// stable step over points, and the seizing-contact filter with its contact records.
#include "core/error.hpp"
#include "solver/common/contact.hpp"
#include "solver/common/stable_step.hpp"
#include "solver/common/walls.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace kessler {
namespace {

TEST(Boundaries, PrescribedComponentsThenNoWallCrossed) {
  const std::vector<RigidWall> walls{{2, 0.0, 1}};  // stay at z >= 0
  Vec3 v(3.0, 4.0, -5.0);
  // x prescribed to 1; 0.2 above the wall, a step of 0.1 would carry it 0.3 below: it lands on the wall.
  imposeBoundaries(0b001, Vec3(1.0, 9.0, 9.0), walls, Vec3(0, 0, 0.2), 0.1, v);
  EXPECT_EQ(v[0], 1.0);
  EXPECT_EQ(v[1], 4.0);
  EXPECT_DOUBLE_EQ(v[2], -2.0);
  // Moving away, or not reaching the wall within the step: untouched.
  Vec3 away(0, 0, 5.0);
  imposeBoundaries(0, Vec3::Zero(), walls, Vec3(0, 0, 0.2), 0.1, away);
  EXPECT_EQ(away, Vec3(0, 0, 5.0));
  Vec3 short_of(0, 0, -1.0);
  imposeBoundaries(0, Vec3::Zero(), walls, Vec3(0, 0, 0.2), 0.1, short_of);
  EXPECT_EQ(short_of, Vec3(0, 0, -1.0));
}

TEST(Boundaries, AParticlesCellStopsAtTheWall) {
  // A particle's matter reaches `reach` beyond its centre: its centre stops that far from the wall.
  const std::vector<RigidWall> below{{2, 0.0, 1}}, above{{2, 1.0, -1}};  // z >= 0; z <= 1
  Vec3 down(0, 0, -5.0);
  imposeBoundaries(0, Vec3::Zero(), below, Vec3(0, 0, 0.3), 0.1, down, 0.1);
  EXPECT_DOUBLE_EQ(0.3 + 0.1 * down[2], 0.1);  // it ends the step 0.1 above the wall
  Vec3 up(0, 0, 5.0);
  imposeBoundaries(0, Vec3::Zero(), above, Vec3(0, 0, 0.7), 0.1, up, 0.1);
  EXPECT_DOUBLE_EQ(0.7 + 0.1 * up[2], 0.9);  // and 0.1 below this one
  // Farther than its reach after the step: untouched (with no reach it would be too).
  Vec3 slow(0, 0, -1.0);
  imposeBoundaries(0, Vec3::Zero(), below, Vec3(0, 0, 0.3), 0.1, slow, 0.1);
  EXPECT_EQ(slow, Vec3(0, 0, -1.0));
  // Already within its reach, at rest: pushed back out to it within the step.
  Vec3 rest = Vec3::Zero();
  imposeBoundaries(0, Vec3::Zero(), below, Vec3(0, 0, 0.05), 0.1, rest, 0.1);
  EXPECT_DOUBLE_EQ(rest[2], 0.5);
}

PointStore threePoints() {
  PointStore points;
  points.resize(3);
  points.sound_speed = {1000.0, 2000.0, 0.0};
  return points;
}

TEST(StableStep, IsCflTimesTheSmallestLengthOverSoundSpeedOrVolumeBound) {
  PointStore points = threePoints();
  const std::vector<double> lengths{1e-3, 1e-3, 1e-3};
  auto length = [&](LocalIndex p) { return lengths[static_cast<std::size_t>(p)]; };
  std::vector<double> rate{0.0, 0.0, 0.0};
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(stableStep(points, rate, inf, 0.3, length), 0.3 * 1e-3 / 2000.0);
  // A cold point (no sound speed) compressing fast: |div v| dt <= cfl / 3.
  rate[2] = -1e7;
  EXPECT_DOUBLE_EQ(stableStep(points, rate, inf, 0.3, length), 0.3 / 3e7);
  // Another part of the step's bound, and debris, which takes no part.
  EXPECT_DOUBLE_EQ(stableStep(points, rate, 1e-9, 0.3, length), 0.3e-9);
  points.fail(2);
  points.carrier[2] = -1;  // released: debris
  ASSERT_TRUE(points.debris(2));
  EXPECT_DOUBLE_EQ(stableStep(points, rate, inf, 0.3, length), 0.3 * 1e-3 / 2000.0);
}

TEST(StableStep, RefusesAProblemWithNothingToBoundIt) {
  PointStore points = threePoints();
  points.sound_speed = {0.0, 0.0, 0.0};
  const std::vector<double> rate{0.0, 0.0, 0.0};
  EXPECT_THROW(stableStep(points, rate, std::numeric_limits<double>::infinity(), 0.3, [](LocalIndex) { return 1.0; }),
               Error);
}

TEST(SmallestStretch, IsTheSmallestPrincipalStretch) {
  Mat3 F = Mat3::Identity();
  F(0, 0) = 0.6;
  F(1, 2) = 0.0;
  EXPECT_NEAR(smallestStretch(F), 0.6, 1e-12);
}

TEST(SeizingProbe, KeepsAnotherBodysCarriersOnlyWithinReachAndRecordsTheContact) {
  // Carriers 0-1 of body 0 (the point's own), 2-3 of body 1, 4 of body 2.
  const std::vector<std::int32_t> body{0, 0, 1, 1, 2};
  const std::vector<double> d2{0.0, 1.0, 0.5, 4.0, 9.0};
  SeizingProbe probe;
  probe.reset(3);
  probe.start();
  std::vector<LocalIndex> candidates{0, 1, 2, 3, 4};
  for (LocalIndex a : candidates) probe.see(0, body[static_cast<std::size_t>(a)], d2[static_cast<std::size_t>(a)]);
  probe.settle(candidates, body, 0, 1.0);  // body 1's nearest (0.5) is within reach, body 2's (9) is not
  EXPECT_EQ(candidates, (std::vector<LocalIndex>{0, 1, 2, 3}));

  ParticleState state;
  state.bodies.resize(3);
  std::vector<std::uint64_t> touching(3, 0);
  probe.addTouching(touching);
  recordContacts(state, touching);
  EXPECT_EQ(state.bodies[0].touched, 0b011u);
  EXPECT_EQ(state.bodies[1].touched, 0b011u);
  EXPECT_EQ(state.bodies[2].touched, 0b100u);
}

}  // namespace
}  // namespace kessler
