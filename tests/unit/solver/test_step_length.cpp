// The time step's length of a point (solver/otm/integrator.hpp, docs/theory.md §4 step 7): h0 times
// the smallest principal stretch of F; for a point flattened below half its spacing whose support is
// still spread as meshed, the spacing; for one whose support is flattened too, what that spread
// allows; for a failed point, its spacing.
#include "geometry/mesh.hpp"
#include "material/impact_material.hpp"
#include "material/library.hpp"
#include "solver/otm/integrator.hpp"
#include "solver/otm/neighbourhoods.hpp"
#include "solver/otm/setup.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace kessler::otm {
namespace {

Model block(double squash_z = 1.0) {
  geometry::MeshRequest request;
  request.shape = geometry::Box{Vec3::Zero(), Vec3(8e-3, 8e-3, 8e-3)};
  request.mesh_size = 1e-3;
  Model model;
  addBody(model, "block", std::make_shared<ImpactMaterial>("al", library::find("Al6061-T6").parameters),
          geometry::discretise(geometry::meshShape(request)), Vec3::Zero());
  for (Vec3& x : model.nodes.x) x[2] *= squash_z;
  for (Vec3& x : model.points.x) x[2] *= squash_z;
  Neighbourhoods(Settings{}).update(model);
  return model;
}

// The point nearest the block's centre.
LocalIndex central(const Model& model, const Vec3& centre) {
  LocalIndex best = 0;
  for (LocalIndex p = 1; p < model.points.owned; ++p)
    if ((model.points.x[p] - centre).norm() < (model.points.x[best] - centre).norm()) best = p;
  return best;
}

TEST(StepLength, IsTheSmallestStretchUntilAPointIsFlattenedBelowHalfItsSpacing) {
  Model model = block();
  const LocalIndex p = central(model, Vec3(4e-3, 4e-3, 4e-3));
  PointStore& points = model.points;
  const double h0 = points.spacing0[p];
  EXPECT_DOUBLE_EQ(stepLength(model, p), h0);  // undeformed
  // Stretched in x and y and squeezed in z at constant volume: 0.6 of the spacing is the stretch's.
  points.F[p] = Vec3(1.0 / std::sqrt(0.6), 1.0 / std::sqrt(0.6), 0.6).asDiagonal();
  EXPECT_NEAR(stepLength(model, p), 0.6 * h0, 1e-12 * h0);
  // Squeezed to 0.2 while its nodes are spread as meshed: the support's spread decides, and for a
  // meshed support that is the spacing.
  points.F[p] = Vec3(1.0 / std::sqrt(0.2), 1.0 / std::sqrt(0.2), 0.2).asDiagonal();
  EXPECT_DOUBLE_EQ(stepLength(model, p), points.spacing(p));
  // Failed: its spacing, whatever F says.
  points.broken[p] = 1;
  EXPECT_DOUBLE_EQ(stepLength(model, p), points.spacing(p));
}

TEST(StepLength, AFlattenedSupportShortensIt) {
  // The whole block squashed to a twentieth of its height, nodes and points alike, with F to match:
  // LME's gradients are N_a J^-1 (x_a - x_p), J the support's covariance, and the nodes, all within
  // 0.2 mm of the point across the squashed direction, leave J small there.
  Model model = block(0.05);
  const LocalIndex p = central(model, Vec3(4e-3, 4e-3, 0.2e-3));
  PointStore& points = model.points;
  points.F[p] = Vec3(1.0 / std::sqrt(0.05), 1.0 / std::sqrt(0.05), 0.05).asDiagonal();
  const double h0 = points.spacing0[p];
  const double length = stepLength(model, p);
  EXPECT_GT(length, 0.05 * h0);  // above the stretch's
  EXPECT_LT(length, 0.5 * h0);   // and far below the spacing
}

}  // namespace
}  // namespace kessler::otm
