#include "geometry/shape.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>  // cross products; core/types.hpp has only Core and LU

#include <cmath>
#include <numbers>

namespace kessler::geometry {
namespace {

constexpr double pi = std::numbers::pi;

TEST(Shape, KindNames) {
  EXPECT_STREQ(kindName(Sphere{}), "sphere");
  EXPECT_STREQ(kindName(Box{}), "box");
  EXPECT_STREQ(kindName(Cylinder{}), "cylinder");
  EXPECT_STREQ(kindName(MeshFile{}), "mesh");
}

TEST(Shape, VolumesMatchFormulas) {
  EXPECT_DOUBLE_EQ(volume(Sphere{Vec3(1, 2, 3), 0.5}), 4.0 / 3.0 * pi * 0.125);
  EXPECT_DOUBLE_EQ(volume(Box{Vec3(-1, 0, 2), Vec3(1, 3, 2.5)}), 2.0 * 3.0 * 0.5);
  // Height is the axis length, whatever its direction: |(3, 4, 12)| = 13.
  EXPECT_DOUBLE_EQ(volume(Cylinder{Vec3(1, 1, 1), Vec3(3, 4, 12), 2.0}), pi * 4.0 * 13.0);
  EXPECT_EQ(volume(MeshFile{"any.msh", 1.0}), 0.0);
}

TEST(Shape, BoundsOfSphereAndBox) {
  const BoundingBox s = bounds(Sphere{Vec3(1, 2, 3), 0.5});
  EXPECT_TRUE(s.min.isApprox(Vec3(0.5, 1.5, 2.5)));
  EXPECT_TRUE(s.max.isApprox(Vec3(1.5, 2.5, 3.5)));
  const Box box{Vec3(-1, 0, 2), Vec3(1, 3, 2.5)};
  EXPECT_EQ(bounds(box).min, box.min);
  EXPECT_EQ(bounds(box).max, box.max);
  EXPECT_TRUE(bounds(MeshFile{"any.msh", 1.0}).empty());
}

TEST(Shape, BoundsOfObliqueCylinderAreTightOverItsRims) {
  const Cylinder c{Vec3(1, -2, 0.5), Vec3(3, 4, 12), 2.0};
  const BoundingBox box = bounds(c);
  // Sample both rim circles densely; the box must contain them and be touched by them.
  const Vec3 n = c.axis.normalized();
  const Vec3 u = n.unitOrthogonal();
  const Vec3 v = n.cross(u);
  Vec3 lo = Vec3::Constant(1e300);
  Vec3 hi = Vec3::Constant(-1e300);
  for (int k = 0; k < 20000; ++k) {
    const double phi = 2.0 * pi * k / 20000.0;
    for (const Vec3& centre : {c.base, Vec3(c.base + c.axis)}) {
      const Vec3 x = centre + c.radius * (std::cos(phi) * u + std::sin(phi) * v);
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
  }
  EXPECT_LT((box.min - lo).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT((box.max - hi).cwiseAbs().maxCoeff(), 1e-6);
  // An axis-aligned cylinder has the obvious box.
  const BoundingBox z = bounds(Cylinder{Vec3(0, 0, -1), Vec3(0, 0, 3), 0.5});
  EXPECT_TRUE(z.min.isApprox(Vec3(-0.5, -0.5, -1)));
  EXPECT_TRUE(z.max.isApprox(Vec3(0.5, 0.5, 2)));
}

TEST(Shape, ContainsIsStrictAndHonoursTheMargin) {
  const Sphere s{Vec3(0, 0, 0), 1.0};
  EXPECT_TRUE(contains(s, Vec3(0.99, 0, 0)));
  EXPECT_FALSE(contains(s, Vec3(1.0, 0, 0)));
  EXPECT_FALSE(contains(s, Vec3(0.95, 0, 0), 0.1));
  EXPECT_TRUE(contains(s, Vec3(0.85, 0, 0), 0.1));

  const Box b{Vec3(0, 0, 0), Vec3(2, 1, 1)};
  EXPECT_TRUE(contains(b, Vec3(1.9, 0.5, 0.5)));
  EXPECT_FALSE(contains(b, Vec3(2.0, 0.5, 0.5)));
  EXPECT_FALSE(contains(b, Vec3(1.0, 0.5, 0.05), 0.1));
  EXPECT_TRUE(contains(b, Vec3(1.0, 0.5, 0.15), 0.1));

  const Cylinder c{Vec3(0, 0, 0), Vec3(0, 0, 2), 0.5};
  EXPECT_TRUE(contains(c, Vec3(0.4, 0, 1)));
  EXPECT_FALSE(contains(c, Vec3(0.4, 0.4, 1)));  // radius 0.57
  EXPECT_FALSE(contains(c, Vec3(0, 0, 2.0)));
  EXPECT_FALSE(contains(c, Vec3(0, 0, 1.95), 0.1));
  // Oblique: points along and across the axis.
  const Cylinder o{Vec3(1, 1, 1), Vec3(1, 1, 0), 0.2};
  EXPECT_TRUE(contains(o, Vec3(1.5, 1.5, 1.1)));
  EXPECT_FALSE(contains(o, Vec3(1.5, 1.5, 1.25)));
  EXPECT_FALSE(contains(o, Vec3(2.1, 2.1, 1.0)));
  EXPECT_FALSE(contains(MeshFile{"any.msh", 1.0}, Vec3::Zero()));
}

// Volume of the lens common to two spheres of radii r1, r2 whose centres are d apart.
double lensVolume(double r1, double r2, double d) {
  return pi * std::pow(r1 + r2 - d, 2) *
         (d * d + 2 * d * r2 - 3 * r2 * r2 + 2 * d * r1 + 6 * r1 * r2 - 3 * r1 * r1) / (12 * d);
}

TEST(Shape, OverlapOfTwoSpheresIsTheLens) {
  const Sphere a{Vec3(0, 0, 0), 1.0};
  const Sphere b{Vec3(1.2, 0.3, -0.4), 0.8};
  const double exact = lensVolume(1.0, 0.8, std::sqrt(1.44 + 0.09 + 0.16));
  // Midpoint sampling of an indicator: error ~ surface cells / all cells, a few % at 48^3.
  EXPECT_NEAR(overlapVolume(a, b), exact, 0.03 * exact);
  EXPECT_NEAR(overlapVolume(a, b, 96), exact, 0.01 * exact);
  EXPECT_DOUBLE_EQ(overlapVolume(a, b), overlapVolume(b, a));
}

TEST(Shape, OverlapOfNestedAndCrossingShapes) {
  const Box plate{Vec3(-2, -2, -0.5), Vec3(2, 2, 0)};
  const Sphere inside{Vec3(0, 0, -0.25), 0.2};
  EXPECT_NEAR(overlapVolume(plate, inside), volume(inside), 0.03 * volume(inside));
  // A cylinder through the plate: the overlap is a disc of the plate's thickness.
  const Cylinder rod{Vec3(0.3, 0, -3), Vec3(0, 0, 6), 0.5};
  const double disc = pi * 0.25 * 0.5;
  EXPECT_NEAR(overlapVolume(plate, rod), disc, 0.03 * disc);
}

TEST(Shape, TouchingOrSeparatedBodiesDoNotOverlap) {
  // A sphere resting on a plate, a plate on a plate, spheres touching at a point.
  EXPECT_EQ(overlapVolume(Sphere{Vec3(0, 0, 1), 1.0}, Box{Vec3(-2, -2, -1), Vec3(2, 2, 0)}), 0.0);
  EXPECT_EQ(overlapVolume(Box{Vec3(0, 0, 0), Vec3(1, 1, 1)}, Box{Vec3(0, 0, 1), Vec3(1, 1, 2)}), 0.0);
  EXPECT_EQ(overlapVolume(Sphere{Vec3(0, 0, 0), 1.0}, Sphere{Vec3(2, 0, 0), 1.0}), 0.0);
  // Diagonal neighbours whose bounding boxes overlap but the bodies do not.
  EXPECT_EQ(overlapVolume(Sphere{Vec3(0, 0, 0), 1.0}, Sphere{Vec3(1.5, 1.5, 0), 1.0}), 0.0);
  EXPECT_EQ(overlapVolume(Sphere{Vec3(0, 0, 0), 1.0}, MeshFile{"any.msh", 1.0}), 0.0);
}

}  // namespace
}  // namespace kessler::geometry
