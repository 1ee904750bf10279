#pragma once
// The step's volume change seen over each point's nodal patch (docs/theory.md §4, §5). One gather
// of each point's ln det(dF) to the nodes (mass-weighted, with the assembly's weights) and one
// interpolation back serve three things:
//   - the viscosity limiter of every point (PointStore::viscosity_limiter): Christensen's (1990)
//     monotonic limiter with the nodes of the point's support as its neighbours;
//   - volume averaging (OtmOptions::volume_averaging): each point's dF is scaled isotropically to the
//     patch average, which removes the point-wise volume noise of a 3-D shock on irregular points;
//   - the record of what averaging took away (PointStore::volume_defect), which the stabilisation
//     pressure pushes back on in the forces, so that the averaging has no zero-energy mode.
#include "particles/store.hpp"
#include "solver/common/own_sums.hpp"
#include "solver/common/viscosity_limiter.hpp"
#include "solver/otm/connectivity.hpp"

#include <array>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace kessler::otm {

class VolumePatch {
 public:
  // `j` holds det(dF) of every owned point that is not debris (its value for debris is ignored); with
  // `averaging` it is replaced by the patch average, and dF scaled to match. Returns the first half of
  // the work the stabilisation pressure (factor `alpha`) did over the step on what the averaging took
  // away, at the pressure before the step (closeStep() adds the second): energy the stabilisation
  // stores, kept apart from the material's so that it does not heat it.
  // With `relaxation` k > 0 the defect of an intact point first relaxes over the step `dt` with the
  // time constant of k wave transits of the point's spacing; the stored energy that frees is booked
  // as negative work (the compatible energy update gives it to the point as heat).
  // The work returned by it and closeStep() is summed over the points `share` counts.
  // `refresh_nodes`, if given, replaces the nodes' means where this process cannot sum them (a
  // distributed run's ghost nodes, whose points it does not all hold) before the points read them.
  using NodeMeans = std::vector<std::array<double, 2>>;
  double apply(const Connectivity& conn, LocalIndex owned_nodes, bool averaging, double alpha, double relaxation,
               double dt, PointStore& points, std::vector<double>& j, const Share& share = {},
               const std::function<void(NodeMeans&)>& refresh_nodes = {});
  // The rest of the step's stabilisation work, with the pressure after the material update (the one
  // the next step's forces carry): apply() books the step's defect at the old pressure's half. With
  // the relaxation on, also the change of an intact point's stored energy that the update's new
  // signal speed made at the same defect. Afterwards work() holds each point's whole share of the step.
  double closeStep(const PointStore& points, double alpha, const Share& share = {});
  // Per point, the stabilisation's work of the last step, J (both halves once closeStep() has run).
  const std::vector<double>& work() const { return work_; }
  // f(array) for each per-point array apply() leaves for closeStep() and work(): what a distributed
  // run refreshes for its ghosts.
  template <class F>
  void forEachPointArray(F&& f) {
    f(work_);
    f(defect_step_);
    f(signal2_);
  }

  // The stabilisation pressure of every owned point (0 for debris) in `s`, for the nodal forces: each
  // point's forces carry its own stress plus this pressure (docs/theory.md §4).
  void stabilisationPressures(const PointStore& points, double alpha, std::vector<double>& s) const;
  // The largest mean tension an intact point of each body bears (Material::tensileLimit, Pa; by body
  // index): its stabilisation pressure pulls it no harder than the rest of this (stabilisationPressure).
  void setTensileLimits(std::vector<double> limits) { limits_ = std::move(limits); }
  // The stabilisation pressure of point p with its body's tensile limit.
  double pressure(const PointStore& points, LocalIndex p, double alpha) const;

 private:
  // Relaxes one point's defect by exp(-dt c / (k h)) (`dt_per_transits` = dt / k); returns the stored
  // energy released, J.
  double relax(PointStore& points, LocalIndex p, double alpha, double dt_per_transits) const;

  // Per point, what the gathers read: m_p, m_p ln det(dF), m_p tr(dF - I) (zero for debris); per
  // node the mass-weighted means of the last two.
  std::vector<std::array<double, 3>> record_;
  NodeMeans node_;
  std::vector<double> work_;         // per point, the stabilisation's work of the step
  std::vector<double> defect_step_;  // per point, the step's growth of the volume defect
  std::vector<double> signal2_;      // per point, c^2 under which apply() booked the step's stored energy
  bool rebook_ = false;              // closeStep() books the stiffness's change (with the relaxation only)
  std::vector<double> limits_;       // per body, the tensile limit (none: no limit)
};

// The stabilisation pressure of a point, -alpha rho c^2 volume_defect (Pa): a point whose own volume
// change has run below its patch average pushes its nodes apart, one above it pulls them together
// (a failed point only pushes: it bears compression only), but never so hard that the point's mean
// stress, its own pressure (viscosity included) plus this, is a tension beyond `tensile_limit`: the
// stabilisation holds a mode down, it does not hold together material that could not hold itself.
double stabilisationPressure(const PointStore& points, LocalIndex p, double alpha,
                             double tensile_limit = std::numeric_limits<double>::infinity());

}  // namespace kessler::otm
