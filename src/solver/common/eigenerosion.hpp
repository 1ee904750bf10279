#pragma once
// Eigenerosion (Pandolfi & Ortiz, IJNME 92:694, 2012; in OTM: Li, Pandolfi & Ortiz, 2015), run
// after the constitutive update of each step (docs/theory.md §8). A material point p erodes,
// irreversibly, when the energy-release rate estimated over the ball B_eps(x_p) of intact points
// of its body reaches G_c:
//   G_p = (C_eps / m_p^eps) sum_{q in B_eps} m_q W_q,   m_p^eps = sum_{q in B_eps} m_q.
// C_eps is calibrated so that a straight crack front releases exactly G_c: averaging the
// mode-I near-tip energy density (plane stress) over a ball of radius eps centred on the front
// gives <W> = 3 (5 - 3 nu) K^2 / (64 E eps), hence C_eps = 64 eps / (3 (5 - 3 nu)) makes
// G_p = K^2 / E = G_c exactly at Griffith's load (docs/theory.md §8).
// A point that erodes fails: it loses its strength and its tension but keeps the pressure it is
// under, and leaves its body as debris once it bears none (solver/common/release.hpp).
#include "search/cell_list.hpp"
#include "solver/common/own_sums.hpp"
#include "solver/common/particle_state.hpp"

#include <vector>

namespace kessler {

// C_eps for a ball of radius eps and Poisson's ratio nu.
double erosionCalibration(double eps, double nu);

class Eigenerosion {
 public:
  // erosion_radius: the radius of the ball B_eps as a multiple of the point spacing.
  explicit Eigenerosion(double erosion_radius) : erosion_radius_(erosion_radius) {}
  // Evaluates G_p for every intact point of an eroding material and fails those with
  // G_p >= G_c (PointStore::fail, stress reduced to its compression). Decisions use the state
  // before this call, so the result does not depend on the thread count. Returns the number of
  // points that failed.
  // With `share` (a distributed run), the cells are agreed by every rank and only own points count.
  LocalIndex apply(ParticleState& model, const Share& share = {});
  bool active(const ParticleState& model) const;

 private:
  // G_p over the ball of radius eps (intact points of p's body).
  double releaseRate(const PointStore& points, LocalIndex p, double eps, double nu) const;
  double erosion_radius_;
  CellList cells_;                     // over the candidates only (candidate_x_)
  std::vector<Vec3> candidate_x_;      // intact points of eroding bodies ...
  std::vector<LocalIndex> candidate_;  // ... and their point indices, in point order
  std::vector<double> candidate_eps_;  // ... and their ball radii eps = erosion_radius h
  std::vector<double> cell_max_;       // largest W of the candidates in each cell
  std::vector<double> cell_bound_;     // ... and in the cells around it
  std::vector<std::uint8_t> erode_;
};

}  // namespace kessler
