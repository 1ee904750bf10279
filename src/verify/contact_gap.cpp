// contact-gap: seizing contact must not couple bodies across a visible gap (docs/theory.md §3). A
// cube moves at 200 m/s towards a block at rest, 3 cells away. The block's nodes may join a
// point's neighbourhood only when they lie within contact_distance * h of that point, and a
// point sits inside its own body, so the block must stay exactly at rest (every velocity
// bitwise zero) until the gap between the two node surfaces is at most contact_distance * h;
// and it must start to move before the surfaces cross (gap >= 0). Without the guard the LME
// support (about 2.8 h at gamma 1.8) would couple them at a gap of about 2.5 h.
// Measured: the gap at the first step that moves the block, over contact_distance * h_max;
// it must lie in [0, 1] (reference 0.5, absolute tolerance 0.5).
#include "solver/common/walls.hpp"
#include "solver/methods.hpp"
#include "verify/fixtures.hpp"
#include "verify/problems.hpp"

#include <algorithm>
#include <limits>

namespace kessler::verify {

Outcome contactGap() {
  const double c = 1e-3, speed = 200.0, gap0 = 3 * c;
  auto material = elasticAluminium();
  const int a = 0, b = 1;
  Problem problem;
  problem.bodies = {
      boxBody("cube", {Vec3(0, 0, 0), Vec3(4 * c, 4 * c, 4 * c)}, {4, 4, 4}, Vec3(speed, 0.0, 0.0), material),
      boxBody("block", {Vec3(4 * c + gap0, -c, -c), Vec3(10 * c + gap0, 5 * c, 5 * c)}, {6, 6, 6}, Vec3::Zero(),
              material)};
  problem.settings.solver.end_time = (gap0 + c) / speed;  // one cell past touching
  std::unique_ptr<Method> method = makeCheckMethod(problem);
  method->initialise();
  const PointStore& points = method->state().points;
  const NodeCloud nodes = method->nodes();

  double h_max = 0.0;
  for (LocalIndex p = 0; p < points.owned; ++p) h_max = std::max(h_max, points.spacing(p));
  const double coupling = problem.settings.otm.contact_distance * h_max;
  // Between the node surfaces; for particles (SPH, RKPM), between their cells, half a spacing beyond
  // their centres.
  auto surfaceGap = [&] {
    double front = -std::numeric_limits<double>::infinity(), back = std::numeric_limits<double>::infinity();
    for (LocalIndex n = 0; surfaceOnNodes(nodes) && n < nodes.owned; ++n) {
      if (nodes.body[n] == a) front = std::max(front, nodes.x[n][0]);
      if (nodes.body[n] == b) back = std::min(back, nodes.x[n][0]);
    }
    if (!surfaceOnNodes(nodes))
      for (LocalIndex p = 0; p < points.owned; ++p) {
        if (points.body[p] == a) front = std::max(front, points.x[p][0] + particle_reach * points.spacing(p));
        if (points.body[p] == b) back = std::min(back, points.x[p][0] - particle_reach * points.spacing(p));
      }
    return back - front;
  };
  auto blockMoves = [&] {
    for (LocalIndex p = 0; p < points.owned; ++p)
      if (points.body[p] == b && points.v[p] != Vec3::Zero()) return true;
    return false;
  };

  double gap_before = surfaceGap(), first_gap = std::numeric_limits<double>::infinity();
  while (!method->finished()) {
    method->step();
    if (blockMoves()) {
      first_gap = gap_before;  // the neighbourhoods of this step were built at the previous gap
      break;
    }
    gap_before = surfaceGap();
  }

  Outcome o;
  o.name = "contact-gap";
  o.quantity = "gap at first contact / (contact_distance h)";
  o.measured = first_gap / coupling;
  o.reference = 0.5;
  o.tolerance = 0.5;
  o.comparison = Comparison::absolute;
  o.note = fmt::format(
      "first interaction at step {} across a gap of {:.3f} mm (start {:.1f} mm); contact_distance h "
      "= {:.3f} mm",
      method->clock().steps, 1e3 * first_gap, 1e3 * gap0, 1e3 * coupling);
  return compare(o);
}

}  // namespace kessler::verify
