// The whole analysis on a small Whipple-like model: report, summary JSON, text and CSV files.
#include "analysis/report.hpp"
#include "material/neo_hookean.hpp"
#include "synthetic.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace kessler::analysis {
namespace {

constexpr double mm = 1e-3;

struct Whipple {
  otm::Model model;
  ImpactGeometry geometry;
  std::vector<double> lengths;
};

// A 1 mm bumper (front face z = 0), a 2 mm rear wall 10 mm behind it, and a 2 mm cube of
// projectile material between them; the bumper has a 3 mm hole.
Whipple whipple(bool holed = true) {
  Whipple w;
  const Vec3 down(0, 0, -1);
  const geometry::Box bumper{Vec3(-8 * mm, -8 * mm, -1 * mm), Vec3(8 * mm, 8 * mm, 0)};
  const geometry::Box wall{Vec3(-8 * mm, -8 * mm, -13 * mm), Vec3(8 * mm, 8 * mm, -11 * mm)};
  const int b = testing::addBlock(w.model, "bumper", bumper, {32, 32, 2});
  const int r = testing::addBlock(w.model, "wall", wall, {32, 32, 4});
  const int p =
      testing::addBlock(w.model, "projectile", {Vec3(-1 * mm, -1 * mm, -6 * mm), Vec3(1 * mm, 1 * mm, -4 * mm)},
                        {4, 4, 4}, testing::aluminium(), Vec3(0, 0, -5000.0));
  w.lengths = referenceLinkLengths(w.model);
  if (holed) testing::erodeWhere(w.model, b, [](const Vec3& x) { return x.head<2>().norm() < 1.5 * mm; });
  w.geometry.shot_direction = down;
  w.geometry.impact_speed = 5000.0;
  w.geometry.projectile_bodies = {p};
  w.geometry.plates = {plateFromBox(b, bumper, down), plateFromBox(r, wall, down)};
  return w;
}

TEST(Report, WhippleSummary) {
  const Whipple w = whipple();
  const Report report = analyse(w.model, w.geometry, w.lengths);
  EXPECT_TRUE(report.debris);
  ASSERT_EQ(report.holes.size(), 2u);
  EXPECT_TRUE(report.holes[0].found);
  EXPECT_NEAR(report.holes[0].ellipse.equivalent_diameter, 3 * mm, report.holes[0].cell);
  EXPECT_FALSE(report.holes[1].found);
  ASSERT_TRUE(report.rear_wall.has_value());
  EXPECT_EQ(report.rear_wall->classification, "none");
  EXPECT_EQ(report.fragments.fragments.size(), 3u);
  ASSERT_TRUE(report.breakup.has_value());
  EXPECT_NEAR(report.event->projectile_mass, 2700.0 * 8e-9, 1e-12 * 2700.0 * 8e-9);
  ASSERT_TRUE(report.shield.has_value());
  EXPECT_EQ(report.shield->model, "christiansen_whipple");
  EXPECT_NEAR(report.shield->spacing, 10 * mm, 1e-12);
  // A cube of 8 mm^3 is a sphere of diameter (6 * 8 / pi)^(1/3) = 2.481402 mm.
  EXPECT_NEAR(report.shield->projectile.diameter, 2.481402 * mm, 1e-6 * mm);
  EXPECT_EQ(report.shield->regime, "shatter");

  const nlohmann::json j = toJson(report);
  EXPECT_EQ(j.at("holes").size(), 2u);
  EXPECT_EQ(j.at("rear_wall").at("classification"), "none");
  EXPECT_DOUBLE_EQ(j.at("breakup_model").at("length_exponent").get<double>(), -1.71);
  EXPECT_EQ(j.at("debris_clouds").back().at("body"), "all");
  // The lowest projectile points sit a/4 = 0.125 mm above z = -6 mm, 4.875 mm behind z = -1 mm.
  EXPECT_NEAR(j.at("debris_clouds")[0].at("leading_edge_m").get<double>(), 4.875 * mm, 1e-12);
  EXPECT_EQ(j.at("ballistic_limit").at("simulated"), "none");
  EXPECT_EQ(j.at("fragments").at("count"), 3);

  const std::string text = formatReport(report);
  EXPECT_NE(text.find("hole in bumper"), std::string::npos) << text;
  EXPECT_NE(text.find("Christiansen"), std::string::npos) << text;
}

// Nothing broke (the bumper without its hole, every body one piece): no hole, cloud, back-splash
// or ballistic-limit verdict, and the text says "no debris". The rear wall is still classified.
TEST(Report, NothingBrokeReportsNoDebris) {
  const Whipple w = whipple(false);
  const Report report = analyse(w.model, w.geometry, w.lengths);
  EXPECT_FALSE(report.debris);
  EXPECT_TRUE(report.holes.empty());
  EXPECT_TRUE(report.clouds.empty());
  EXPECT_EQ(report.ejecta.points, 0);
  EXPECT_FALSE(report.shield.has_value());
  ASSERT_TRUE(report.rear_wall.has_value());
  EXPECT_EQ(report.rear_wall->classification, "none");
  const nlohmann::json j = toJson(report);
  EXPECT_FALSE(j.at("debris").get<bool>());
  EXPECT_FALSE(j.contains("ballistic_limit"));
  EXPECT_TRUE(j.at("debris_clouds").empty());
  const std::string text = formatReport(report);
  EXPECT_NE(text.find("no debris"), std::string::npos) << text;
  EXPECT_EQ(text.find("leading edge"), std::string::npos) << text;  // no cloud line
  EXPECT_EQ(text.find("hole in"), std::string::npos) << text;
  EXPECT_EQ(text.find("Christiansen"), std::string::npos) << text;

  // One point of the bumper eroded is debris.
  Whipple chipped = whipple(false);
  ASSERT_GT(testing::erodeWhere(chipped.model, 0, [](const Vec3& x) { return x.head<2>().norm() < 0.4 * mm; }), 0);
  EXPECT_TRUE(analyse(chipped.model, chipped.geometry, chipped.lengths).debris);
}

// The ballistic-limit equations are fits for aluminium walls: with the default (Al 6061-T6) wall
// properties and a wall of another density the comparison says so; given properties, or an
// aluminium wall, it does not.
TEST(Report, ADefaultAluminiumWallOnASteelPlateIsACaveat) {
  const Whipple w = whipple();
  EXPECT_TRUE(analyse(w.model, w.geometry, w.lengths).shield->caveat.empty());  // aluminium
  Whipple steel = whipple();
  NeoHookeanParameters p;
  p.density = 7800.0;
  p.youngs_modulus = 200e9;
  p.poisson_ratio = 0.29;
  steel.model.materials.push_back(std::make_shared<NeoHookean>("steel", p));
  steel.model.bodies[1].material = static_cast<int>(steel.model.materials.size()) - 1;
  const Report report = analyse(steel.model, steel.geometry, steel.lengths);
  ASSERT_TRUE(report.shield.has_value());
  EXPECT_NE(report.shield->caveat.find("7800 kg/m^3"), std::string::npos) << report.shield->caveat;
  EXPECT_NE(formatReport(report).find("caveat: the rear wall's properties are Al 6061-T6's defaults"),
            std::string::npos);
  EXPECT_EQ(toJson(report).at("ballistic_limit").at("caveat"), report.shield->caveat);
  const Report given = analyse(steel.model, steel.geometry, steel.lengths, WallProperties{.defaults = false});
  EXPECT_TRUE(given.shield->caveat.empty());
}

TEST(Report, FragmentFilesHaveUnitsAndOneRowPerFragment) {
  const Whipple w = whipple();
  const Report report = analyse(w.model, w.geometry, w.lengths);
  const auto dir = std::filesystem::temp_directory_path() / "kessler_analysis_report_test";
  std::filesystem::remove_all(dir);
  writeFragmentFiles(dir, report);
  std::ifstream csv(dir / "fragments.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("rank,body,material,points,copies,mass_kg,lc_m,", 0), 0u) << header;
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_EQ(rows, 3);
  std::ifstream cumulative(dir / "fragments_cumulative.csv");
  std::getline(cumulative, header);
  EXPECT_EQ(header, "lc_m,count_ge_lc,nasa_count_ge_lc");
  // One row per point: its id and its fragment's rank (0: broken), the same as the label.
  std::ifstream points(dir / "fragment_points.csv");
  std::getline(points, header);
  EXPECT_EQ(header, "id,fragment");
  std::size_t p = 0;
  for (std::string line; std::getline(points, line); ++p) {
    ASSERT_LT(p, report.fragments.label.size());
    EXPECT_EQ(line, fmt::format("{},{}", w.model.points.id[static_cast<LocalIndex>(p)], report.fragments.label[p] + 1));
  }
  EXPECT_EQ(p, report.fragments.label.size());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace kessler::analysis
