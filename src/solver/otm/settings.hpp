#pragma once
// Settings of the OTM integrator, filled from the deck (or by a verification problem).
namespace kessler::otm {

struct Settings {
  double end_time = 0.0;        // s
  double cfl = 0.3;             // factor on the CFL time step
  double lme_gamma = 1.8;       // LME locality, beta = gamma / h^2
  double lme_tolerance = 1e-6;  // shape functions below this are cut off: r = h sqrt(-ln tol / gamma)
  int min_neighbours = 12;      // enlarge the search radius until at least this many nodes
  long max_steps = 0;           // 0: no limit
  // Seizing contact (DESIGN.md §1): the nodes of another body join a point's neighbourhood
  // only when that body's nearest node lies within contact_distance * h of the point. A point
  // sits about h/4 inside its own surface, so 1.0 couples across a gap of roughly h/2.
  double contact_distance = 1.0;
};

}  // namespace kessler::otm
