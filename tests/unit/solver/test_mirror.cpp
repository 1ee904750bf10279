// Mirror planes (solver/common/mirror.hpp): the images of a model between two rollers and beside a
// symmetry plane, against a brute-force list of the reflection group's elements.
#include "core/error.hpp"
#include "solver/common/mirror.hpp"
#include "solver/common/problem.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <vector>

namespace kessler {
namespace {

// One element of the group the planes x = 0 and x = w generate on an axis: x -> sign x + shift.
struct Element {
  double sign, shift;
};

std::vector<Element> hallOfMirrors(double w) {
  std::vector<Element> out;
  for (int k = -6; k <= 6; ++k) {
    out.push_back({1.0, 2.0 * k * w});   // translations by twice the gap
    out.push_back({-1.0, 2.0 * k * w});  // reflections across x = k w
  }
  return out;
}

TEST(Mirrors, ListEveryImageWithinReachOnce) {
  const double w = 1.0, reach = 2.3;
  MirrorBox box;
  box.lo[0] = 0.0;
  box.hi[0] = w;
  box.lo[2] = 0.0;  // a symmetry plane z = 0
  const Mirrors mirrors(box, reach);
  std::mt19937 random(4);
  std::uniform_real_distribution<double> in_x(0.0, w), in_y(-3.0, 3.0), in_z(0.0, 3.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 x(in_x(random), in_y(random), in_z(random)), y(in_x(random), in_y(random), in_z(random));
    // Brute force: the distinct images of y within the reach of x.
    std::vector<Vec3> expected;
    for (const Element& ex : hallOfMirrors(w))
      for (const double sz : {1.0, -1.0}) {
        const Vec3 image(ex.sign * y.x() + ex.shift, y.y(), sz * y.z());
        if ((x - image).norm() < reach) expected.push_back(image);
      }
    std::vector<Vec3> found;
    std::set<int> codes;
    mirrors.near(x, reach, [&](std::uint8_t c) {
      EXPECT_TRUE(codes.insert(c).second) << "image " << int(c) << " listed twice";
      const Vec3 image = mirrors.point(y, c);
      // What the image does to a vector is its linear part.
      const Vec3 v(0.3, -0.7, 1.1);
      EXPECT_LT((mirrors.vector(v, c) - (mirrors.point(v, c) - mirrors.point(Vec3::Zero(), c))).norm(), 1e-15);
      // The inverse undoes it.
      EXPECT_LT((mirrors.point(image, mirrors.inverse(c)) - y).norm(), 1e-12);
      EXPECT_EQ(mirrors.flips(mirrors.inverse(c)), mirrors.flips(c));
      if ((x - image).norm() < reach) found.push_back(image);
    });
    ASSERT_EQ(found.size(), expected.size()) << "trial " << trial;
    for (const Vec3& e : expected) {
      bool seen = false;
      for (const Vec3& f : found) seen = seen || (f - e).norm() < 1e-12;
      EXPECT_TRUE(seen) << "trial " << trial << " misses the image at " << e.transpose();
    }
  }
}

// Across symmetry planes alone the images come in the order of the axes' bits (as the methods
// summed them before rollers were mirrors).
TEST(Mirrors, SymmetryPlanesAloneAreReflections) {
  MirrorBox box;
  box.lo[1] = box.lo[2] = 0.0;
  const Mirrors mirrors(box, 1.0);
  ASSERT_EQ(mirrors.count(), 4u);
  const std::uint8_t flips[] = {0, 2, 4, 6};
  for (std::uint8_t c = 0; c < 4; ++c) {
    EXPECT_EQ(mirrors.flips(c), flips[c]);
    EXPECT_EQ(mirrors.inverse(c), c);
    EXPECT_EQ(mirrors.point(Vec3(1, 2, 3), c), reflect(Vec3(1, 2, 3), flips[c]));
  }
}

TEST(Mirrors, FoldBringsAPointIntoTheBox) {
  MirrorBox box;
  box.lo[0] = 1.0;
  box.hi[0] = 3.0;
  box.hi[1] = 0.5;
  const Mirrors mirrors(box, 1.0);
  EXPECT_EQ(mirrors.fold(Vec3(2.5, 0.2, 7.0)), Vec3(2.5, 0.2, 7.0));  // inside: unchanged
  EXPECT_NEAR(mirrors.fold(Vec3(0.4, 0, 0)).x(), 1.6, 1e-12);         // across x = 1
  EXPECT_NEAR(mirrors.fold(Vec3(3.5, 0, 0)).x(), 2.5, 1e-12);         // across x = 3
  EXPECT_NEAR(mirrors.fold(Vec3(5.5, 0, 0)).x(), 1.5, 1e-12);         // across 3, then 5: translated by -4
  EXPECT_NEAR(mirrors.fold(Vec3(0, 0.9, 0)).y(), 0.1, 1e-12);         // across y = 0.5
  std::mt19937 random(2);
  std::uniform_real_distribution<double> anywhere(-9.0, 9.0);
  for (int trial = 0; trial < 100; ++trial) {
    const Vec3 x(anywhere(random), anywhere(random), anywhere(random));
    const Vec3 f = mirrors.fold(x);
    EXPECT_GE(f.x(), 1.0);
    EXPECT_LE(f.x(), 3.0);
    EXPECT_LE(f.y(), 0.5);
    EXPECT_EQ(f.z(), x.z());
  }
}

TEST(Mirrors, RefuseTooManyImages) {
  MirrorBox box;
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = 0.0;
    box.hi[a] = 1e-3;
  }
  EXPECT_NO_THROW(Mirrors(box, 1e-3));
  EXPECT_THROW(Mirrors(box, 1e-2), Error);
  EXPECT_THROW(Mirrors(box, 1e300), Error);  // refused, not overflowed
  EXPECT_THROW(Mirrors(box, std::nan("")), Error);
}

TEST(Mirrors, ProblemPlanesMakeTheBox) {
  Problem problem;
  problem.symmetry_axes = {0};
  problem.rollers = {{.axis = 0, .offset = 4e-3, .side = -1}, {.axis = 1, .offset = -2e-3, .side = 1}};
  const MirrorBox box = mirrorBox(problem);
  EXPECT_EQ(box.lo[0], 0.0);
  EXPECT_EQ(box.hi[0], 4e-3);
  EXPECT_EQ(box.lo[1], -2e-3);
  EXPECT_FALSE(std::isfinite(box.hi[1]));
  EXPECT_FALSE(std::isfinite(box.lo[2]));
  problem.rollers.push_back({.axis = 0, .offset = 1e-3, .side = 1});  // a second lower plane on x
  EXPECT_THROW(mirrorBox(problem), Error);
}

}  // namespace
}  // namespace kessler
