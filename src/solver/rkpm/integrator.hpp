#pragma once
// RKPM's time step (docs/theory.md §12): a total-Lagrangian reproducing kernel particle method with
// stabilised conforming nodal integration, central differences in time.
//   1. kick: vhat += dt_avg f / m (the last step's forces, lumped masses), the walls' impulses on the
//      particles that meet them (solver/rkpm/wall_contact.hpp), then velocity collocation of the
//      prescribed components (solver/rkpm/collocation.hpp); between bodies, the sliding contact
//      on their surface particles (solver/rkpm/surface.hpp), its impulses reaching the
//      coefficients through the shape functions;
//   2. drift xhat += dt vhat; each particle's deformation gradient from the coefficients,
//      F_J = I + sum_I (xhat_I - X_I) (x) grad~ Psi_I(X_J), and dF = F F_old^-1;
//   3. the material update (the shared laws, from F, dF and the volume), with the laws' bulk
//      viscosity under Christensen's limiter;
//   4. eigenerosion and the release of failed particles as debris (solver/common/), after which a
//      kernel update lets new debris stand alone;
//   5. the particles' physical positions and velocities, sum_I Psi_I(X_K) (xhat_I, vhat_I);
//   6. the forces f_I = -sum_J V0_J P_J grad~ Psi_I(X_J) (P the first Piola-Kirchhoff stress), whose
//      power is the stress power the laws book, and the stable step.
#include "core/timer.hpp"
#include "solver/common/eigenerosion.hpp"
#include "solver/common/energies.hpp"
#include "solver/common/method.hpp"
#include "solver/common/release.hpp"
#include "solver/common/settings.hpp"
#include "solver/common/sliding_contact.hpp"
#include "solver/common/walls.hpp"
#include "solver/rkpm/collocation.hpp"
#include "solver/rkpm/kernels.hpp"
#include "solver/rkpm/model.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace kessler::rkpm {

struct Settings {
  SolverSettings solver;  // its contact's friction is the sliding contact's (RKPM has no seizing contact)
  RkpmOptions rkpm;
  std::vector<RigidWall> walls;
  MirrorBox mirrors;  // the symmetry planes and rollers (solver/common/mirror.hpp)
};

struct KernelUpdates {
  std::int64_t made = 0, refused = 0, retry_at = 0;
  double energy = 0.0;
};

class Integrator {
 public:
  Integrator(Model& model, const Settings& settings);
  // The kernels, the masses and the collocation of the reference configuration, the first forces
  // and time step of a new run.
  void initialise();
  // A restored run: the kernels of its reference configuration and the forces of its state.
  void restore(const Clock& clock, double contact_energy, const KernelUpdates& updates = {});
  void step();

  bool finished() const { return clock_.time >= settings_.solver.end_time * (1.0 - 1e-12); }
  const Clock& clock() const { return clock_; }
  const Settings& settings() const { return settings_; }
  const PhaseTimers& timers() const { return timers_; }
  // The budget with the coefficients' kinetic energy and momentum (the equations of motion's).
  Energies energies() const;
  // The length a particle's stable step is measured by: its spacing times its smallest stretch.
  double stepLength(LocalIndex p) const;
  const Kernels& kernels() const { return kernels_; }
  const std::vector<double>& masses() const { return mass_; }
  double meanNeighbours() const;
  // The kinetic energy the sliding contact has taken so far, J (booked apart, as stabilisation energy).
  double contactEnergy() const { return contact_energy_; }
  // The kernel updates so far: how many were made and refused, the kinetic energy they took, J, and
  // the step before which none is tried (after a refused one).
  KernelUpdates kernelUpdates() const { return {kernel_updates_, refused_updates_, retry_at_, update_energy_}; }
  // Why the last update this process tried was refused (empty if none was).
  const std::string& lastRefusal() const { return last_refusal_; }

 private:
  void prepare();
  void kick(double dt_kick, double dt);
  void slide(double dt, double dt_kick);
  void rebuildSurface();
  void deform(double dt);
  void updateMaterials(double dt);
  void place();
  void forces();
  void updateKernels();
  // Whether a debris particle is still in the kernels (not alone): a kernel update is then due.
  bool heldDebris() const;
  double coefficientKinetic() const;
  [[noreturn]] void failAtPoint(LocalIndex p, const std::string& what) const;

  Model& model_;
  Settings settings_;
  Clock clock_;
  PhaseTimers timers_;
  Kernels kernels_;
  Table<Vec3> transposed_;    // row I: the particles J and grad~ Psi_I(X_J)
  std::vector<double> mass_;  // the coefficients' lumped masses, sum_K m_K Psi_I(X_K)
  VelocityCollocation collocation_;
  Eigenerosion erosion_;
  DebrisRelease release_;
  std::vector<IndexRange> body_points_;
  std::vector<Vec3> acceleration_;
  std::vector<double> volume_rate_;  // ln det dF / dt of the last step
  std::vector<Mat3> piola_;          // V0_J P_J
  std::vector<Vec3> du_;             // the coefficients' move over the step
  std::vector<Vec3> displacement_;   // the coefficients' from the kernels' reference configuration
  // The sliding contact between bodies: its surface, each particle's gap (half its spacing: its
  // cell's reach beyond it), the energy it took in all; the surface
  // particles' velocities and moves a pass gives it, those before the pass, and a mark per particle
  // (the particles a pass moved; the lists put in index order), clear between uses.
  std::vector<Vec3> particle_v_, particle_du_, before_;
  std::vector<Vec3> coefficient_before_;  // the coefficients' velocities before the contact's passes
  std::vector<std::uint8_t> moved_mark_;
  ContactSurface surface_;
  SlidingContact contact_;
  std::vector<double> gap_;
  double contact_energy_ = 0.0;
  // Kernel updates: whether the last deformation asked for one, how many were made, and the kinetic
  // energy they took from the coefficients (the particles' velocities are kept; booked apart).
  bool update_due_ = false;
  std::int64_t kernel_updates_ = 0, refused_updates_ = 0, retry_at_ = 0;
  double update_energy_ = 0.0;
  std::string last_refusal_;
  // How many particles were debris when model_.surface was last built (-1: build it at the first step).
  LocalIndex surface_debris_ = -1;
  bool sliding_ = false, rebuilds_ = false;
};

}  // namespace kessler::rkpm
