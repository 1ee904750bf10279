// A numerical failure inside ImpactMaterial::update's parallel loop (here the Mie-Gruneisen EOS
// beyond the limit of its linear Us-up fit) must leave the loop as a PointError that names the first
// failing point by index, not end the program; the solver turns it into a diagnosis with the point's
// identity and place.
#include "core/error.hpp"
#include "material/impact_material.hpp"
#include "material/library.hpp"

#include <gtest/gtest.h>

#include <string>

namespace kessler {
namespace {

TEST(MaterialUpdate, ReportsTheFirstFailingPointByIndex) {
  ImpactMaterial material{"al", library::find("Al6061-T6").parameters};
  PointStore points;
  const LocalIndex n = 5000;
  points.resize(static_cast<std::size_t>(n));
  const double volume0 = 1e-9;
  for (LocalIndex p = 0; p < n; ++p) {
    points.body[p] = 0;
    points.mass[p] = material.referenceDensity() * volume0;
    points.volume[p] = points.volume0[p] = volume0;
    points.spacing0[p] = 1e-3;
  }
  material.initialise(points, 0, n);
  // Every point a little compressed; two of them to four times their density, past the limit
  // s/(s - 1) = 3.5 of aluminium's fit.
  for (LocalIndex p = 0; p < n; ++p) {
    const double j = p == 3001 || p == 4500 ? 0.25 : 0.99;
    points.dF[p] = std::cbrt(j) * Mat3::Identity();
    points.F[p] = points.dF[p];
    points.volume[p] = j * volume0;
  }
  try {
    material.update(points, 0, n, 1e-8);
    FAIL() << "the update accepted a state beyond the EOS's limit";
  } catch (const PointError& e) {
    EXPECT_EQ(e.point(), 3001);
    EXPECT_NE(std::string(e.what()).find("Hugoniot limit"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace kessler
