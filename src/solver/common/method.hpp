#pragma once
// A particle method as the run loop, the benchmark and the analysis see it (docs/architecture.md).
// The run loop (app/simulation.cpp) owns output, checkpoints, restart, signals, progress, history
// and the summary; a method owns its discretisation and advances the shared particle state.
// A new method implements this interface in its own folder beside solver/otm/ and is added to
// the factory (solver/methods.cpp).
#include "core/timer.hpp"
#include "particles/store.hpp"
#include "solver/common/energies.hpp"
#include "solver/common/node_cloud.hpp"
#include "solver/common/particle_state.hpp"
#include "solver/common/state_archive.hpp"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace kessler {

// What a gathered method (Method::gathered) reports for the distributed run it stands for: rank 0's
// timers, and the sizes and notes of the whole run.
struct GatheredReport {
  PhaseTimers timers;
  std::vector<std::pair<std::string, double>> sizes;
  std::vector<std::string> notes;
};

// Where a method stands in time.
struct Clock {
  double time = 0.0;        // s
  long steps = 0;           // steps taken
  double dt_last = 0.0;     // the step just taken (0 before the first)
  double dt_next = 0.0;     // the step about to be taken
  double dt_initial = 0.0;  // the run's first step

  // After a step of dt.
  void advance(double dt) {
    time += dt;
    dt_last = dt;
    ++steps;
  }
};

// A clock in a checkpoint, as `<prefix>time`, `<prefix>steps`, `<prefix>dt_last`, `<prefix>dt_next` and
// `<prefix>dt_initial` (SPH's "sph_", RKPM's "rkpm_").
inline void saveClock(StateWriter& out, const std::string& prefix, const Clock& c) {
  out.scalar(prefix + "time", c.time);
  out.scalar(prefix + "dt_last", c.dt_last);
  out.scalar(prefix + "dt_next", c.dt_next);
  out.scalar(prefix + "dt_initial", c.dt_initial);
  out.scalar(prefix + "steps", static_cast<std::int64_t>(c.steps));
}
inline Clock loadClock(const StateReader& in, const std::string& prefix) {
  return {in.doubleScalar(prefix + "time"), in.intScalar(prefix + "steps"), in.doubleScalar(prefix + "dt_last"),
          in.doubleScalar(prefix + "dt_next"), in.doubleScalar(prefix + "dt_initial")};
}

class Method {
 public:
  virtual ~Method() = default;

  // The deck's solver.method.
  virtual const char* name() const = 0;
  // A new run's first state: the first time step and whatever a step starts from. A restored
  // method is not initialised again.
  virtual void initialise() = 0;
  // One step. A numerical failure throws NumericalError naming the step, time, point and value.
  virtual void step() = 0;
  // The health checks after a step (non-finite or collapsing states, a time step that has
  // collapsed, energy grown beyond its limit over `initial_total_energy`); throws NumericalError.
  virtual void check(double initial_total_energy) = 0;

  virtual bool finished() const = 0;
  virtual double endTime() const = 0;
  virtual Clock clock() const = 0;
  virtual Energies energies() const = 0;
  virtual const PhaseTimers& timers() const = 0;

  // What analysis and output read.
  virtual const ParticleState& state() const = 0;
  // The method's own node cloud, written to nodes.xdmf beside the points (empty for a method
  // without nodes).
  virtual NodeCloud nodes() const = 0;
  // Figures of the problem's size beyond points and nodes, for summary.json (OTM: mean_neighbours);
  // collective on a distributed method (every rank calls it).
  virtual std::vector<std::pair<std::string, double>> sizes() const = 0;
  // Lines for the end-of-run report (OTM: points torn from their bodies); none if nothing to say.
  virtual std::vector<std::string> notes() const = 0;
  // The length by which the stable step measures point p (solver/common/stable_step.hpp): the
  // step is cfl times the smallest stepLength / c over the points that are not debris.
  virtual double stepLength(LocalIndex p) const = 0;
  // The pressure the method's forces add to point p's material pressure (OTM: the volume
  // stabilisation's, docs/theory.md §4), Pa; 0 for a method that adds none.
  virtual double addedPressure(LocalIndex /*p*/) const { return 0.0; }

  // The method's own part of a checkpoint: everything beyond the shared state that a restart
  // needs to continue bit for bit (its discretisation, its clock). load() runs on a method built
  // for the restored shared state, instead of initialise(), and refuses a part that does not fit
  // it (StateReader::fail).
  virtual void save(StateWriter& out) const = 0;
  virtual void load(const StateReader& in) = 0;

  // A distributed run (docs/parallel.md): whether this rank holds a part of the run only, and the
  // whole run as one process's method (collective): on rank 0 a method whose state, nodes, clock,
  // energies, sizes and notes are the whole run's, for output, analysis and the summary, and with
  // `for_checkpoint` its save() too (OTM then gathers its connectivity as well); nullptr on the
  // other ranks, and from a method that is whole already.
  virtual bool distributed() const { return false; }
  virtual std::unique_ptr<Method> gathered(bool /*for_checkpoint*/) const { return nullptr; }
};

}  // namespace kessler
