#pragma once
// SPH's time step (docs/theory.md §10): an updated-Lagrangian, corrected and variationally
// consistent SPH for solids (Bonet & Lok, CMAME 180:97, 1999), leapfrog in time.
//   1. kick: v += dt_avg a (a from the last step's forces), prescribed components and walls;
//   2. deformation: each particle's velocity gradient L over its active pairs with the corrected
//      kernel gradient (an intact lattice particle away from a contact takes half of its deviator
//      from its reconstructed hexahedron: element_gradient.hpp), dF = (I - dt L/2)^-1 (I + dt L/2),
//      and the drift x += dt v;
//   3. the material update (the shared laws, from F, dF and the volume), heated by the viscosity and
//      the heat flux;
//   4. eigenerosion and the release of failed particles as debris (solver/common/);
//   5. pairs at the new positions, the kernel correction, the forces (pair_passes.cpp), the stable
//      step.
// The internal forces are those whose power is the stress power of the deformation of step 2,
// f_i = sum_j V_i V_j (sigma_i B_i^T + sigma_j B_j^T) grad_i W_ij (sigma less the hexahedra's share
// of its deviator, which acts through their nodes), so linear momentum is exact and the work of the
// forces is what the material books; Monaghan's viscosity and artificial stress, and an artificial
// heat flux (Price, J. Comput. Phys. 227:10040, 2008), are added pairwise.
#include "core/timer.hpp"
#include "solver/common/eigenerosion.hpp"
#include "solver/common/energies.hpp"
#include "solver/common/method.hpp"
#include "solver/common/release.hpp"
#include "solver/common/settings.hpp"
#include "solver/common/walls.hpp"
#include "solver/sph/distribution.hpp"
#include "solver/sph/element_gradient.hpp"
#include "solver/sph/model.hpp"
#include "solver/sph/pairs.hpp"
#include "solver/sph/reconstruction.hpp"

#include <span>
#include <utility>
#include <vector>

namespace kessler::sph {

struct Settings {
  SolverSettings solver;
  SphOptions sph;
  std::vector<RigidWall> walls;
  MirrorBox mirrors;  // the symmetry planes and rollers (solver/common/mirror.hpp)
};

class Integrator {
 public:
  // With `distribution`, this rank's part of a distributed run (docs/parallel.md, "SPH across ranks"):
  // initialise() and restore() split the model that every rank holds alike.
  Integrator(Model& model, const Settings& settings, Distribution* distribution = nullptr);
  // The first forces and time step of a new run.
  void initialise();
  // A restored run: the clock and the elements failed by distortion, then the nodes and forces of
  // the restored state (a pure function of it, so the run goes on as the one that wrote the
  // checkpoint).
  void restore(const Clock& clock, LocalIndex distorted, double stored);
  // A gathered copy of a distributed run (for output and checkpoints): the run's clock and count of
  // distorted elements, and the nodes of its particles' state; no pairs or forces.
  void adopt(const Clock& clock, LocalIndex distorted, double stored);
  void step();

  bool finished() const { return clock_.time >= settings_.solver.end_time * (1.0 - 1e-12); }
  const Clock& clock() const { return clock_; }
  const Settings& settings() const { return settings_; }
  const PhaseTimers& timers() const { return timers_; }
  Energies energies() const;
  // The smoothing length of particle p, m: `smoothing` times its current spacing, within a tenth and
  // twice its reference one (expanded debris does not widen every search; compressed matter keeps
  // its neighbours down to a thousandfold compression, beyond any shock's).
  double smoothingLength(LocalIndex p) const;
  double smoothingLength(LocalIndex p, double spacing) const;  // at a spacing known already
  // The mean pairs of a particle, over every rank (collective in a distributed run).
  double meanNeighbours() const;
  // Particles whose kernel correction was singular at the last search (too few neighbours), over
  // every rank: they took the plain kernel gradient.
  LocalIndex uncorrected() const { return uncorrected_; }
  // The reconstructed elements' nodes at the particles' current state (the step rebuilds them before
  // erosion and release change velocities: output takes them afresh).
  NodeCloud nodes() const {
    reconstruction_.rebuild(model_);
    return reconstruction_.cloud();
  }
  // Elements failed by their distortion so far.
  LocalIndex distorted() const { return distorted_; }
  // The energy SPH's stabilisations hold apart from the material so far, J, booked as the energies'
  // stabilisation so that the budget closes: the viscosity's heat in bodies whose law has no thermal
  // state (it takes none), less the work the artificial stress has done on the particles.
  double stored() const { return stored_; }

 private:
  // Which particles count and the ranks to reduce over (every particle, no ranks, on one process).
  Share share() const { return distribution_ ? distribution_->share() : Share{}; }
  // A distributed run's split of the model every rank holds (initialise, restore), and the halo for
  // the next search.
  void split();
  void rebuildHalo();
  // Per particle held, how far a distributed run's halo sends it for the reconstruction's sake
  // (Reconstruction::latticeReach, over as many rings of elements as the elements' share reads);
  // `whole` while every rank holds the whole model (split).
  std::vector<double> latticeReach(bool whole) const;
  void search();
  void forces();
  void deform(double dt);
  Mat3 gradientOf(LocalIndex i, std::span<const Vec3> u) const;
  void switchViscosity(LocalIndex i, const Mat3& L, double dt);
  void updateMaterials(double dt);
  double stableStep() const;
  [[noreturn]] void failAtPoint(LocalIndex p, const std::string& what) const;

  Model& model_;
  Settings settings_;
  Distribution* distribution_ = nullptr;
  Clock clock_;
  PhaseTimers timers_;
  Pairs pairs_;
  mutable Reconstruction reconstruction_;  // its nodes are a function of the particles (nodes())
  ElementGradient elements_;               // the elements' share of the deviator
  LocalIndex distorted_ = 0;
  double stored_ = 0.0;
  Eigenerosion erosion_;
  DebrisRelease release_;
  std::vector<IndexRange> body_points_;
  std::vector<double> h_;            // smoothing lengths at the last search
  std::vector<double> spacing_;      // and spacings
  std::vector<Mat3> correction_;     // B_i: the inverse of sum_j V_j (x_j - x_i) (x) grad_i W_ij
  std::vector<Vec3> acceleration_;   // of the last forces
  std::vector<Vec3> element_force_;  // the elements' share of them, N (forces())
  std::vector<double> heating_;      // the viscosity's heat and the heat flux into each particle, W
  // The artificial stress's share of each particle's last forces, N (forces()), and its work over the
  // kick of each particle, J (step()).
  std::vector<Vec3> artificial_force_;
  std::vector<double> artificial_work_;
  // Per thread, the artificial forces of the pairs its particles list, by pair, for the other ends.
  std::vector<std::vector<std::pair<Index, Vec3>>> artificial_reactions_;
  std::vector<double> signal_;         // the largest viscous signal speed mu of each particle, m/s
  std::vector<double> volume_rate_;    // ln J / dt of the last step
  std::vector<double> lattice_reach_;  // a distributed run's: Reconstruction::latticeReach
  std::vector<double> heat_;
  // Per pair (forces()): its force on its listing particle, the viscosity's heating of each end and
  // its viscous signal speed.
  struct PairShare {
    Vec3 force;
    double power, signal;
    double heat;  // the heat flux's power into the listing particle (its other end takes -heat)
  };
  std::vector<PairShare> pair_share_;
  // Per particle (forces()): what a pair reads of either end, packed.
  struct PairEnd {
    Mat3 stress_b;  // sigma B^T
    Vec3 x, v;
    double volume, mass, density, sound, alpha, h, spacing, energy;
    int body;
    std::uint8_t broken, tensile;
  };
  std::vector<PairEnd> ends_;
  std::vector<Mat3> artificial_;  // the artificial stress R of each particle (forces())
  std::vector<int> struck_;       // the body each debris particle met at the last search, -1 none
  // The bodies each particle touches at the last search (bit b % 32 for body b; search()).
  std::vector<std::uint32_t> touches_;
  LocalIndex uncorrected_ = 0;
};

}  // namespace kessler::sph
