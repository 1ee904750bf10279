#pragma once
// The explicit OTM integrator (docs/theory.md §4; Li, Habbal & Ortiz, IJNME 83, 2010):
// nodal mass, momentum and force gathered from material points, the variable-step discrete
// Euler-Lagrange update of node positions, material points carried by the nodes' motion,
// constitutive update, new neighbourhoods and shape functions, CFL time step.
#include "core/timer.hpp"
#include "solver/common/debris_contact.hpp"
#include "solver/common/eigenerosion.hpp"
#include "solver/common/energies.hpp"
#include "solver/common/release.hpp"
#include "solver/common/sliding_contact.hpp"
#include "solver/common/stable_step.hpp"
#include "solver/otm/distribution.hpp"
#include "solver/otm/integrator_assembly.hpp"
#include "solver/otm/model.hpp"
#include "solver/otm/neighbourhoods.hpp"
#include "solver/otm/settings.hpp"
#include "solver/otm/volume_patch.hpp"

namespace kessler::otm {

// Each node's displacement and velocity increment of a step (FLIP-style transfer to points), side
// by side: the points' gather reads both for each of its nodes.
struct NodeIncrement {
  Vec3 du, dv;
};

}  // namespace kessler::otm

// Two vectors: sent as bytes to a distributed run's ghosts.
template <>
struct kessler::PlainValue<kessler::otm::NodeIncrement> : std::true_type {};

namespace kessler::otm {

// The length scale of point p for the stable step (solver/common/stable_step.hpp): h0 times the
// smallest principal stretch of F (a failed point: its current spacing). Where that is below `flattened` times the
// point's current spacing, the spread of its own support decides instead: the length is then at least `support_lengths`
// times the square root of the smallest eigenvalue of the support's covariance sum_a N_a (x_a - x_p)(x_a - x_p)^T, at
// most the spacing (docs/theory.md §4 step 7). The stable step is cfl times the smallest stepLength / c over the points
// that are not debris.
inline constexpr double flattened = 0.5;
inline constexpr double support_lengths = 4.0;
double stepLength(const Model& model, LocalIndex p);

// The integrator's own scalar state; with the Model (connectivity included) it is the complete
// state of a run, which is what a checkpoint holds.
struct IntegratorState {
  double time = 0.0;
  double dt_last = 0.0;
  double dt_next = 0.0;
  double dt_initial = 0.0;
  long steps = 0;
  double stabilisation_energy = 0.0;  // J, Energies::stabilisation
};

class Integrator {
 public:
  // With a `distribution`, this rank runs its part of the model (docs/parallel.md, "The distributed
  // step"); initialise() splits the model every rank built alike.
  Integrator(Model& model, const Settings& settings, Distribution* distribution = nullptr);

  // Builds shape functions, the initial material state and the first time step.
  void initialise();
  // Continues from a checkpoint instead of initialise(): the model (with its connectivity)
  // has been restored; the run then proceeds bitwise as it would have without interruption.
  // A distributed run restores the whole model on every rank, and this keeps the rank's part
  // (with the rows of the points it holds), whatever the ranks that wrote the checkpoint.
  void restore(const IntegratorState& state);
  IntegratorState state() const { return {time_, dt_last_, dt_next_, dt_initial_, steps_, stabilisation_energy_}; }
  // Advances one step of length nextStep() (clipped to end at settings.end_time). A numerical
  // failure throws NumericalError with a message that starts with the step and time.
  void step();

  bool finished() const { return time_ >= settings_.end_time * (1.0 - 1e-12); }
  double time() const { return time_; }
  long steps() const { return steps_; }
  LocalIndex erodedPoints() const { return eroded_; }
  // Intact points released because no neighbourhood enclosed them (torn from their body, since
  // this process started: not kept across a restart), and their mass.
  LocalIndex tornPoints() const { return neighbourhoods_.tornPoints(); }
  double tornMass() const { return neighbourhoods_.tornMass(); }
  // A distributed run: searches done again with a wider halo, and the search radius the last halo held.
  long searchesRepeated() const { return searches_repeated_; }
  // A sliding contact: the last step's contacts and the deepest slave left below a master surface.
  const SlidingReport& slidingReport() const { return sliding_report_; }
  double haloSupport() const { return halo_support_; }
  double lastStep() const { return dt_last_; }
  double nextStep() const { return dt_next_; }
  double initialStep() const { return dt_initial_; }
  Energies energies() const;
  const PhaseTimers& timers() const { return timers_; }
  const Model& model() const { return model_; }
  const Settings& settings() const { return settings_; }

 private:
  void advance(double dt);  // the body of step()
  void assembleNodes();
  void updateNodes(double dt, double dt_average);
  // A sliding contact's surfaces now (Model::faces whose one side is intact), and its corrections
  // of the step's node displacements and velocities (solver/common/sliding_contact.hpp).
  void buildSurface();
  void slide();
  bool sliding() const { return settings_.contact.sliding(); }
  void requireFacesInOrder() const;
  void updatePoints();
  void initialVolumeRates();
  void updateMaterials(double dt);
  void balanceEnergy();
  double stableStep() const;
  void findBodyRanges();
  // The neighbourhoods and shape functions (Neighbourhoods::update); a distributed run fetches its
  // halos first, for searches up to `support`, and again wider while a search reaches beyond them.
  void search();
  // The halos' search radius for the next search: the widest of the last step's searches or the
  // widest cut-off now, with a quarter to spare, and at least `reach`.
  double haloRadius(double reach) const;
  void rebuildHalos(double support);
  // restore() on several ranks: the split, the halos and the held points' rows.
  void distributeRestored();
  // What sums and minima over points count: all (one process) or this rank's own, over every rank.
  Share share() const { return distribution_ ? distribution_->pointShare() : Share{}; }
  // Stops a distributed run whose debris flies beyond the halo's contact reach in this kick.
  void requireContactReach(double dt_kick) const;
  double debrisSpeed() const;
  [[noreturn]] void failAtPoint(LocalIndex p, const std::string& what) const;

  Model& model_;
  Settings settings_;
  Distribution* distribution_ = nullptr;
  double contact_spacing_ = 0.0;  // a distributed run: the largest reference spacing of a point, m
  double contact_reach_ = 0.0;    // and the debris contact reach its halo holds (rebuildHalos), m
  double refresh_seconds_ = 0.0;  // the ghost points' refresh within the point update
  long searches_repeated_ = 0;    // searches done again with a wider halo (search())
  double halo_support_ = 0.0;     // the search radius the last halo held, m
  Neighbourhoods neighbourhoods_;
  Eigenerosion erosion_;
  DebrisRelease release_;
  DebrisContact contact_;
  SlidingContact sliding_;
  ContactSurface surface_;
  SlidingReport sliding_report_;          // the last step's
  std::vector<Vec3> slide_du_, slide_v_;  // slide()'s copies of the nodes' displacements and velocities
  std::vector<NodeIncrement> increment_;
  std::vector<double> j_point_;  // det(dF) per point (after averaging)
  // J per point, heat to add: before the material update the kinetic energy the step's transfer took,
  // after it the compatible energy update's balance (balanceEnergy).
  std::vector<double> transfer_heat_;
  std::vector<double> volume_rate_;  // ln det(dF) / dt of each point's last step, 1/s (time step)
  VolumePatch patch_;
  std::vector<double> stabilisation_pressure_;  // per point, VolumePatch::stabilisationPressures
  // Per point, the work its forces did over the step (updatePoints), then plus its energy before the
  // material update: what balanceEnergy() compares the updated energy with, J.
  std::vector<double> force_work_;
  std::vector<PointLoad> loads_;  // assembly scratch, one record per point
  double dt_step_ = 0.0;          // length of the step in progress
  double dt_average_ = 0.0;       // the kick's interval of the step in progress (updateNodes)
  PhaseTimers timers_;
  double time_ = 0.0;
  double dt_last_ = 0.0;  // dt_k: the step just taken (0 before the first)
  double dt_next_ = 0.0;  // dt_k+1
  double dt_initial_ = 0.0;
  long steps_ = 0;
  double stabilisation_energy_ = 0.0;
  LocalIndex eroded_ = 0;                // points eigenerosion has failed so far
  std::vector<IndexRange> body_points_;  // each body's owned points (findBodyRanges)
};

}  // namespace kessler::otm
