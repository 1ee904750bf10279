#pragma once
// Debris that strikes as matter (docs/theory.md §9). Debris (failed material released from its
// body, solver/common/release.hpp) carries no stress and flies ballistically until it reaches the
// carriers of a body it may hit (OTM: its nodes; a particle method: its particles). Then a contact
// force between it and each carrier it overlaps pushes it
// back: a spring whose stiffness is the two materials' bulk moduli in series over the debris' face,
// so that a fragment striking a wall stops within about the time a wave takes to cross it and loads
// the nodes it meets with about the acoustic pressure rho c v, and a critically damped dashpot that
// makes the strike nearly inelastic (restitution e^-2), its dissipation heating the debris. The
// carrier takes the opposite force, so momentum is exact; the springs' energy is booked as stored energy. The
// contact only pushes: debris does not stick, and it does not pass through a wall it cannot perforate.
// It may not hit its own body, nor a body its body was in contact with when it was released: the
// debris of a projectile breaking up in a bumper passes through the bumper's hole, and the rear
// wall behind is struck by the debris cloud.
#include "search/cell_list.hpp"
#include "solver/common/contact.hpp"
#include "solver/common/own_sums.hpp"
#include "solver/common/particle_state.hpp"

#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

namespace kessler {

// What debris strikes: the carriers of the bodies' motion, and where their contact forces go.
struct Carriers {
  std::span<const Vec3> x;
  std::span<const Vec3> momentum;  // their velocity is momentum / mass
  std::span<const double> mass;
  std::span<const int> body;
  std::span<Vec3> force;                // the contact forces are added to these
  LocalIndex owned = 0;                 // how many there are
  std::span<const std::uint8_t> ghost;  // per carrier, 1 for a distributed run's ghost; empty: none
  // A distributed run's: a ghost carrier's count of pairs and kick from its owner, which holds all
  // the debris that strikes it (collective). Empty on one process.
  std::function<void(std::vector<int>&)> refresh_pairs;
  std::function<void(std::vector<Vec3>&)> refresh_kicks;
};

// Debris in flight that some body of the `bodies` may stop: it passes through its own body and those
// it touched when released (passes_through, 0 until markNewDebris), and strikes the others. Debris
// that passes through every body never strikes anything.
bool mayStrike(const PointStore& points, LocalIndex p, std::size_t bodies);

class DebrisContact {
 public:
  // Adds the contact forces of this step's configuration to carriers.force (after the assembly)
  // and gives each debris point in contact its velocity change dt_kick f / m and its dissipation
  // as heat. dt_kick: the kick's interval of the step (the carriers' leapfrog).
  // With `share` (a distributed run's own points and its ranks; collective), the bodies' constants,
  // the search cells and the stored energy are those of the whole run.
  void apply(ParticleState& state, const Carriers& carriers, double dt_kick, const Share& share = {});

  // The energy the contact springs store in the configuration apply() last saw, J.
  double storedEnergy() const { return stored_; }
  // The longest step the contact allows, before the integrator's cfl: the time a debris point takes
  // to cross its contact radius relative to a node it approaches, and 1/omega of each node's springs
  // together with its body's mass per node, counting the pairs that may touch within the next step
  // (each pair's spring and dashpot are implicit and need no bound of their own); infinity where no
  // debris is near a body it may hit.
  double stepBound() const { return step_bound_; }

 private:
  struct Pair {
    LocalIndex node = 0;
    Vec3 n = Vec3::Zero();             // unit vector from the node to the debris point
    double approach = 0.0;             // relative speed along -n at the start of the step
    double spring = 0.0;               // k times the overlap
    double k = 0.0, c = 0.0, m = 0.0;  // stiffness, damping coefficient, reduced mass
    double force = 0.0;                // spring plus dashpot, never pulling
  };
  struct Strike {
    LocalIndex debris = 0;
    std::size_t begin = 0, end = 0;  // its pairs in pairs_
    Vec3 dv = Vec3::Zero();          // the kick its pairs give it
  };
  CellList cells_;
  std::vector<Pair> pairs_;  // this step's debris-node pairs, by debris point
  std::vector<Strike> strikes_;
  // Found on the first call (bodies do not change during a run):
  std::vector<double> body_spacing_;    // mean reference spacing of each body's points
  std::vector<double> body_modulus_;    // rho0 c0^2 of each body's material
  std::vector<double> body_node_mass_;  // each body's mass over its number of nodes
  std::vector<int> node_pairs_;         // per node, its pairs this step (zero between steps)
  std::vector<Vec3> node_dv_;           // per node, the kick of its pairs (zero between steps)
  // Per node, the stiffness of its pairs that may touch within the step (zero outside touched_).
  std::vector<double> node_stiffness_;
  std::vector<LocalIndex> touched_;
  double stored_ = 0.0;
  double step_bound_ = std::numeric_limits<double>::infinity();
};

}  // namespace kessler
