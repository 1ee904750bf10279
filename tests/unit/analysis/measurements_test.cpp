// Holes, debris clouds, back-splash and rear-wall damage on synthetic models with known answers.
#include "analysis/measurements.hpp"
#include "synthetic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

namespace kessler::analysis {
namespace {

using testing::addBlock;
using testing::addCloud;
using testing::erodeWhere;

constexpr double mm = 1e-3;
constexpr double deg = std::numbers::pi / 180.0;
const Vec3 down(0, 0, -1);

// A 30 x 30 x 2 mm plate (front face z = 0, rear face z = -2 mm) of 0.5 mm cubes, hit along -z.
struct PlateModel {
  otm::Model model;
  ImpactGeometry geometry;
  int plate = 0;
};

PlateModel plateModel(double x_min = -15 * mm) {
  PlateModel m;
  const geometry::Box box{Vec3(x_min, -15 * mm, -2 * mm), Vec3(15 * mm, 15 * mm, 0)};
  const auto cells = std::array<int, 3>{static_cast<int>(std::lround((15 * mm - x_min) / (0.5 * mm))), 60, 4};
  m.plate = addBlock(m.model, "plate", box, cells);
  m.geometry.shot_direction = down;
  m.geometry.plates = {plateFromBox(m.plate, box, down)};
  return m;
}

TEST(PlateSpec, FromBoxFacesTheShot) {
  const geometry::Box box{Vec3(-10, -10, -2), Vec3(10, 10, 0)};
  const PlateSpec plate = plateFromBox(3, box, down);
  EXPECT_EQ(plate.normal, Vec3(0, 0, -1));
  EXPECT_DOUBLE_EQ(plate.rear_face, 2.0);  // n . x on z = -2
  EXPECT_DOUBLE_EQ(plate.thickness, 2.0);
  EXPECT_DOUBLE_EQ(plate.frontFace(), 0.0);
  EXPECT_EQ(plateFromBox(0, box, Vec3(0.1, 0, 1)).normal, Vec3(0, 0, 1));
}

TEST(Hole, CylindricalHoleDiameterWithinOneCell) {
  PlateModel m = plateModel();
  const Vec3 centre(0.3 * mm, -0.2 * mm, 0);
  m.geometry.impact_point = centre;
  const double radius = 5 * mm;
  erodeWhere(m.model, m.plate, [&](const Vec3& x) { return (x - centre).head<2>().norm() < radius; });
  const HoleMeasurement hole = measureHole(m.model, m.geometry, 0);
  ASSERT_TRUE(hole.found);
  EXPECT_FALSE(hole.open);
  EXPECT_NEAR(hole.cell, 0.5 * mm * (3 + 2 * std::sqrt(2.0) + std::sqrt(3.0)) / 6, 1e-12);
  std::cout << "cylindrical hole D = 10 mm: diameter " << hole.ellipse.equivalent_diameter / mm << " mm, axes "
            << hole.ellipse.major / mm << " x " << hole.ellipse.minor / mm << " mm, cell " << hole.cell / mm << " mm\n";
  EXPECT_NEAR(hole.ellipse.equivalent_diameter, 2 * radius, hole.cell);
  EXPECT_NEAR(hole.ellipse.major, 2 * radius, hole.cell);
  EXPECT_NEAR(hole.ellipse.minor, 2 * radius, hole.cell);
  EXPECT_NEAR((hole.centre - Vec3(centre[0], centre[1], -1 * mm)).norm(), 0.0, 0.5 * hole.cell);
  // Nothing covers the hole at any depth: all of it is clear.
  EXPECT_DOUBLE_EQ(hole.through_area, hole.ellipse.area);
}

TEST(Hole, EllipticalHoleAxesAndDirection) {
  PlateModel m = plateModel();
  const Vec3 major_dir(std::cos(30 * deg), std::sin(30 * deg), 0);
  const Vec3 minor_dir(-std::sin(30 * deg), std::cos(30 * deg), 0);
  erodeWhere(m.model, m.plate, [&](const Vec3& x) {
    const double u = x.dot(major_dir) / (6 * mm);
    const double w = x.dot(minor_dir) / (3 * mm);
    return u * u + w * w < 1.0;
  });
  const HoleMeasurement hole = measureHole(m.model, m.geometry, 0);
  ASSERT_TRUE(hole.found);
  std::cout << "elliptical hole 12 x 6 mm: axes " << hole.ellipse.major / mm << " x " << hole.ellipse.minor / mm
            << " mm\n";
  EXPECT_NEAR(hole.ellipse.major, 12 * mm, hole.cell);
  EXPECT_NEAR(hole.ellipse.minor, 6 * mm, hole.cell);
  EXPECT_NEAR(hole.ellipse.equivalent_diameter, 2 * std::sqrt(6.0 * 3.0) * mm, hole.cell);
  EXPECT_GT(std::abs(hole.major_direction.dot(major_dir)), std::cos(3 * deg));
}

TEST(Hole, IntactPlateHasNone) {
  PlateModel m = plateModel();
  const HoleMeasurement hole = measureHole(m.model, m.geometry, 0);
  EXPECT_FALSE(hole.found);
  EXPECT_EQ(hole.ellipse.equivalent_diameter, 0.0);
}

TEST(Hole, HalfModelMeasuresTheWholeHole) {
  PlateModel m = plateModel(0.0);
  m.geometry.symmetry_axes = {0};
  const Vec3 centre(0, 0.4 * mm, 0);
  m.geometry.impact_point = centre;
  erodeWhere(m.model, m.plate, [&](const Vec3& x) { return (x - centre).head<2>().norm() < 4 * mm; });
  const HoleMeasurement hole = measureHole(m.model, m.geometry, 0);
  ASSERT_TRUE(hole.found);
  EXPECT_NEAR(hole.ellipse.equivalent_diameter, 8 * mm, hole.cell);
  EXPECT_NEAR(hole.centre[0], 0.0, 0.05 * hole.cell);  // the raster is symmetric up to its cell phase
}

TEST(Hole, BulgeLeavesTheSlabButIsNotThrough) {
  // A smooth bulge, 3 mm deep at the centre: the middle leaves the original slab (a "hole" by
  // the slab definition) but nothing is open, and the wall holds together.
  PlateModel m = plateModel();
  for (Vec3& x : m.model.points.x) {
    const double r2 = x.head<2>().squaredNorm() / (6 * mm * 6 * mm);
    if (r2 < 1.0) x[2] -= 3 * mm * (1.0 - r2);
  }
  const HoleMeasurement hole = measureHole(m.model, m.geometry, 0);
  ASSERT_TRUE(hole.found);
  EXPECT_DOUBLE_EQ(hole.through_area, 0.0);
  const RearWallDamage wall = measureRearWall(m.model, findFragments(m.model, {}, {}), m.geometry);
  EXPECT_EQ(wall.perforations, 0);
  EXPECT_EQ(wall.classification, "bulge");
  EXPECT_FALSE(wall.failed());
  // The rear face's points start a fraction of a spacing inside it.
  EXPECT_NEAR(wall.bulge, 3 * mm, measureHole(m.model, m.geometry, 0).cell);
  // 2 mm over the mean edge of a 0.5 mm cube's Kuhn tets: three edges of 0.5 mm, two face
  // diagonals and a body diagonal.
  const double mean_edge = 0.5 * mm * (3.0 + 2.0 * std::sqrt(2.0) + std::sqrt(3.0)) / 6.0;
  EXPECT_NEAR(wall.spacings_through, 2 * mm / mean_edge, 1e-9);
}

TEST(RearWall, FailedMaterialNearTheRearFaceIsIncipientSpallNearTheFrontACrater) {
  // The shot goes down: the 2 mm plate's rear face is z = -2 mm. Failed points (still in the wall)
  // in a 3 mm disc, first in the rear half, then, in another plate bulged 3 mm, in the front half.
  PlateModel rear = plateModel();
  for (LocalIndex p = 0; p < rear.model.points.size(); ++p)
    if (rear.model.points.x[p].head<2>().norm() < 3 * mm && rear.model.points.x[p][2] < -1.5 * mm)
      rear.model.points.fail(p);
  const RearWallDamage spall = measureRearWall(rear.model, findFragments(rear.model, {}, {}), rear.geometry);
  EXPECT_EQ(spall.classification, "incipient_spall");
  EXPECT_FALSE(spall.failed());
  EXPECT_GT(spall.incipient_mass, 0.0);

  PlateModel front = plateModel();
  for (LocalIndex p = 0; p < front.model.points.size(); ++p) {
    Vec3& x = front.model.points.x[p];
    const bool crater = x.head<2>().norm() < 3 * mm && x[2] > -0.5 * mm;
    const double r2 = x.head<2>().squaredNorm() / (6 * mm * 6 * mm);
    if (r2 < 1.0) x[2] -= 3 * mm * (1.0 - r2);
    if (crater) front.model.points.fail(p);
  }
  const RearWallDamage crater = measureRearWall(front.model, findFragments(front.model, {}, {}), front.geometry);
  EXPECT_EQ(crater.incipient_mass, 0.0) << "a crater in the front face of a bulged wall is not spall";
  EXPECT_EQ(crater.classification, "bulge");
}

TEST(Hole, RefusesAnInconsistentGeometry) {
  PlateModel m = plateModel();
  m.geometry.plates[0].normal = Vec3(0, 0, 1);  // pointing up-range
  EXPECT_THROW(measureHole(m.model, m.geometry, 0), InputError);
  m = plateModel();
  m.geometry.plates[0].body = 7;
  EXPECT_THROW(measureHole(m.model, m.geometry, 0), InputError);
}

TEST(Cloud, LeadingEdgeRadiusAndRatioAreExact) {
  PlateModel m = plateModel();
  const int debris = addCloud(
      m.model, "projectile",
      {Vec3(0, 0, -12 * mm), Vec3(3 * mm, 0, -5 * mm), Vec3(0, -4 * mm, -6 * mm), Vec3(1 * mm, 1 * mm, 0.5 * mm)},
      1e-9);
  m.geometry.projectile_bodies = {debris};
  const auto clouds = measureClouds(m.model, m.geometry);
  ASSERT_EQ(clouds.size(), 3u);  // projectile, plate, all
  const CloudMeasurement& c = clouds[0];
  EXPECT_EQ(c.name, "projectile");
  EXPECT_EQ(c.points, 3);  // the point in front of the rear face is not in the cloud
  EXPECT_NEAR(c.leading_edge, 10 * mm, 1e-15);
  EXPECT_NEAR(c.max_radius, 4 * mm, 1e-15);
  EXPECT_NEAR(c.length, 7 * mm, 1e-15);
  EXPECT_NEAR(c.length_to_width, 7.0 / 8.0, 1e-12);
  EXPECT_NEAR(c.front_deflection, 0.0, 1e-12);
  EXPECT_EQ(clouds[1].points, 0);  // the intact plate has nothing behind its rear face
  EXPECT_EQ(clouds[2].points, 3);
}

// The bulk measures take 95 % of the mass: one far outlier sets the extremes but not them.
TEST(Cloud, BulkMeasuresIgnoreAFewFastPoints) {
  PlateModel m = plateModel();
  std::vector<Vec3> x;
  for (int k = 1; k <= 109; ++k) x.emplace_back(0.1 * k * mm, 0, -2 * mm - k * mm);  // xi = k mm, r = k/10 mm
  x.emplace_back(300 * mm, 0, -502 * mm);                                            // xi = 500 mm, r = 300 mm
  const int debris = addCloud(m.model, "projectile", x, 1e-9);
  m.geometry.projectile_bodies = {debris};
  const CloudMeasurement c = measureClouds(m.model, m.geometry)[0];
  EXPECT_NEAR(c.leading_edge, 500 * mm, 1e-12);
  EXPECT_NEAR(c.max_radius, 300 * mm, 1e-12);
  // 110 equal masses: 95 % of the mass is reached at the 105th value (104.5), 5 % at the 6th (5.5).
  EXPECT_NEAR(c.bulk_leading_edge, 105 * mm, 1e-12);
  EXPECT_NEAR(c.bulk_radius, 10.5 * mm, 1e-12);
  EXPECT_NEAR(c.bulk_length_to_width, (105.0 - 6.0) / (2 * 10.5), 1e-9);
}

// A cloud expanding about a centre moving along the shot line: point k at radius r_k moves with
// the centre's speed u plus w r_k / R along the radius, so the speeds are known point by point.
// The quarter model with its mirror images gives the same speeds as the full one.
TEST(Cloud, SpeedsAreMassQuantilesOfTheVelocities) {
  const double u = 4000.0, w = 1000.0, R = 20 * mm;
  for (const bool quarter : {false, true}) {
    PlateModel m = plateModel();
    std::vector<Vec3> x, v;
    for (int k = 1; k <= 110; ++k) {
      const double r = R * k / 110.0, phi = quarter ? 0.01 * k : 0.7 * k;  // quarter: x, y > 0
      const Vec3 radial(std::cos(phi), std::sin(phi), 0.0);
      x.push_back(Vec3(0, 0, -12 * mm) + r * radial);
      v.push_back(u * down + (w * r / R) * radial);
    }
    const int debris = addCloud(m.model, "projectile", x, 1e-9);
    const IndexRange body = bodyRanges(m.model.points.body, m.model.points.size(), m.model.bodies.size())[debris];
    for (LocalIndex p = body.begin; p < body.end; ++p) m.model.points.v[p] = v[p - body.begin];
    m.geometry.projectile_bodies = {debris};
    if (quarter) m.geometry.symmetry_axes = {0, 1};
    const CloudMeasurement c = measureClouds(m.model, m.geometry)[0];
    EXPECT_NEAR(c.mean_axial_speed, u, 1e-9) << "quarter " << quarter;
    EXPECT_NEAR(c.bulk_axial_speed, u, 1e-9) << "quarter " << quarter;
    // 110 equal masses (4 images each in the quarter model): 95 % is reached at the 105th radius.
    EXPECT_NEAR(c.bulk_radial_speed, w * 105.0 / 110.0, 1e-9) << "quarter " << quarter;
  }
  // A fast point along the shot line: the mean moves with it, the 95 % front does not.
  PlateModel m = plateModel();
  std::vector<Vec3> x(40, Vec3(0, 0, -10 * mm));
  const int debris = addCloud(m.model, "projectile", x, 1e-9, testing::aluminium(), u * down);
  m.model.points.v[bodyRanges(m.model.points.body, m.model.points.size(), m.model.bodies.size())[debris].begin] =
      3 * u * down;
  m.geometry.projectile_bodies = {debris};
  const CloudMeasurement c = measureClouds(m.model, m.geometry)[0];
  EXPECT_NEAR(c.mean_axial_speed, u * (39.0 + 3.0) / 40.0, 1e-9);
  EXPECT_NEAR(c.bulk_axial_speed, u, 1e-9);
  EXPECT_NEAR(c.bulk_radial_speed, 0.0, 1e-12);
}

TEST(Cloud, ObliqueFrontDeflection) {
  PlateModel m = plateModel();
  const Vec3 shot(std::sin(30 * deg), 0, -std::cos(30 * deg));
  m.geometry.shot_direction = shot;
  const Vec3 exit(2 * mm * std::tan(30 * deg), 0, -2 * mm);  // the shot line on the rear face
  // Front 10 degrees from the shot line towards the plate normal; a slower point behind it.
  const Vec3 front_dir(std::sin(20 * deg), 0, -std::cos(20 * deg));
  const int debris = addCloud(m.model, "projectile", {exit + 20 * mm * front_dir, exit + 5 * mm * shot}, 1e-9);
  m.geometry.projectile_bodies = {debris};
  const CloudMeasurement c = measureClouds(m.model, m.geometry)[0];
  EXPECT_NEAR(c.front_deflection, 10 * deg, 1e-9);
  EXPECT_NEAR(c.front_normal_angle, 20 * deg, 1e-9);
  EXPECT_NEAR(c.leading_edge, 20 * mm * std::cos(10 * deg), 1e-12);
}

TEST(Ejecta, HeightAndConeAngles) {
  PlateModel m = plateModel();
  addCloud(m.model, "splash", {Vec3(0, 0, 3 * mm), Vec3(4 * mm, 0, 4 * mm)}, 1e-9, testing::aluminium(),
           Vec3(0, 0, 500.0));
  addCloud(m.model, "incoming", {Vec3(0, 0, 5 * mm)}, 1e-9, testing::aluminium(), Vec3(0, 0, -5000.0));
  const EjectaMeasurement e = measureEjecta(m.model, m.geometry);
  EXPECT_EQ(e.points, 2);
  EXPECT_NEAR(e.height, 4 * mm, 1e-15);
  EXPECT_NEAR(e.inner_angle, 0.0, 1e-12);
  EXPECT_NEAR(e.outer_angle, 45 * deg, 1e-12);
  EXPECT_NEAR(e.axis_tilt, 22.5 * deg, 1e-12);
}

TEST(RearWall, PerforationSpallAndNone) {
  {
    PlateModel m = plateModel();
    erodeWhere(m.model, m.plate, [](const Vec3& x) { return x.head<2>().norm() < 3 * mm; });
    // Debris of another body: three points whose last strike was on the wall, one that last struck
    // another body, and one that has struck nothing.
    const int cloud = addCloud(m.model, "debris",
                               {Vec3(5 * mm, 0, -1 * mm), Vec3(6 * mm, 0, -1 * mm), Vec3(7 * mm, 0, -1 * mm),
                                Vec3(8 * mm, 0, 1 * mm), Vec3(9 * mm, 0, 1 * mm)},
                               1e-9);
    PointStore& points = m.model.points;
    double struck = 0.0;
    const IndexRange debris = bodyRanges(points.body, points.size(), m.model.bodies.size())[cloud];
    for (LocalIndex p = debris.begin; p < debris.end; ++p) {
      const LocalIndex k = p - debris.begin;
      points.broken[p] = 1;
      points.carrier[p] = -1;
      if (k < 3) points.strike(p, m.plate);
      if (k == 3) points.strike(p, cloud + 1);
      struck += k < 3 ? points.mass[p] : 0.0;
    }
    const RearWallDamage d = measureRearWall(m.model, findFragments(m.model, {}, {}), m.geometry);
    EXPECT_DOUBLE_EQ(d.debris_struck, struck);
    EXPECT_EQ(d.classification, "perforation");
    ASSERT_EQ(d.perforations, 1);
    EXPECT_NEAR(d.perforation_diameters[0], 6 * mm, measureHole(m.model, m.geometry, 0).cell);
  }
  {
    // The wall and a detached piece 1 mm behind its rear face, in one body.
    otm::Model model;
    const geometry::Box wall{Vec3(-5 * mm, -5 * mm, -2 * mm), Vec3(5 * mm, 5 * mm, 0)};
    geometry::TetMesh mesh = geometry::structuredBoxMesh(wall, {20, 20, 4});
    const geometry::TetMesh piece =
        geometry::structuredBoxMesh({Vec3(-1 * mm, -1 * mm, -4 * mm), Vec3(1 * mm, 1 * mm, -3 * mm)}, {4, 4, 2});
    const auto offset = static_cast<LocalIndex>(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), piece.vertices.begin(), piece.vertices.end());
    for (auto tet : piece.tets) {
      for (LocalIndex& v : tet) v += offset;
      mesh.tets.push_back(tet);
    }
    const int body = otm::addBody(model, "wall", testing::aluminium(), geometry::discretise(mesh), Vec3::Zero());
    ImpactGeometry geometry;
    geometry.shot_direction = down;
    geometry.plates = {plateFromBox(body, wall, down)};
    const RearWallDamage d = measureRearWall(model, findFragments(model, {}, {}), geometry);
    EXPECT_EQ(d.classification, "detached_spall");
    EXPECT_TRUE(d.failed());
    EXPECT_EQ(d.perforations, 0);
    EXPECT_EQ(d.spall_fragments, 1);
    EXPECT_NEAR(d.spall_mass, 2700.0 * 2 * 2 * 1 * 1e-9, 1e-15);
  }
  {
    PlateModel m = plateModel();
    const RearWallDamage d = measureRearWall(m.model, findFragments(m.model, {}, {}), m.geometry);
    EXPECT_EQ(d.classification, "none");
    EXPECT_EQ(d.perforations, 0);
    EXPECT_EQ(d.spall_fragments, 0);
    EXPECT_EQ(d.debris_struck, 0.0);
  }
}

}  // namespace
}  // namespace kessler::analysis
