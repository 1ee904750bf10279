#include "app/simulation.hpp"

#include "app/impact_analysis.hpp"
#include "app/methods.hpp"
#include "app/progress.hpp"
#include "app/run_folder.hpp"
#include "app/scripts.hpp"
#include "app/signals.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/timer.hpp"
#include "io/checkpoint.hpp"
#include "io/deck.hpp"
#include "io/fields_writer.hpp"
#include "io/summary.hpp"
#include "parallel/communicator.hpp"
#include "solver/common/method.hpp"

#include <omp.h>

#include <csignal>
#include <memory>
#include <optional>

namespace kessler::app {

namespace {

enum class Stop { none, max_steps, signal };

class Run {
 public:
  Run(const io::RunConfig& config, const RunOptions& options)
      : config_(config), options_(options), dir_(config.output.dir), checkpoint_file_(io::checkpointPath(dir_)) {}

  RunOutcome execute();

 private:
  void start();
  void resume();
  void advance();
  void fail(const NumericalError& e);
  void appendHistory() {
    const Clock clock = method_->clock();
    record_.history.push_back({clock.steps, clock.time, clock.dt_last, method_->energies()});
  }
  void output();
  // The whole run for output, analysis and (`for_checkpoint`) checkpoints: the method itself on one
  // process, or on rank 0 of a distributed run its gathered state (nullptr on the other ranks).
  // Every rank must call it alike (docs/parallel.md).
  const Method* whole(bool for_checkpoint = false) {
    if (!method_->distributed()) return method_.get();
    gathered_ = method_->gathered(for_checkpoint);
    return gathered_.get();
  }
  bool root() const { return world_.root(); }
  bool checkpointDue() const;
  void checkpoint();
  void check() { method_->check(record_.history.front().energies.total()); }
  long steps() const { return method_->clock().steps; }
  double time() const { return method_->clock().time; }
  double lastStep() const { return method_->clock().dt_last; }
  void finish() {
    record_.extra_timings["output"] = output_seconds_;
    record_.extra_timings["checkpoint"] = checkpoint_seconds_;
    record_.wall_seconds = previous_wall_seconds_ + wall_.seconds();
    const Method* run = whole();
    if (root()) io::writeSummary(dir_ / "summary.json", record_, *run);
  }
  void printSummary() const;
  bool report() const { return options_.on_progress({steps(), time(), config_.solver.end_time, lastStep()}); }
  // The impact measurements into the summary (before finish() writes it) and the pictures after.
  void analyse(const std::string& state) {
    const Method* run = whole();
    if (root()) record_.analysis = analyseImpact(config_, run->state(), dir_, state);
  }
  // The pictures of tools/plots and the ParaView state (analysis.plots switches both).
  void plots() const {
    if (!root() || !config_.analysis.plots) return;
    if (config_.analysis.enabled) drawPlots(dir_);
    writeParaViewState(dir_);
  }

  const io::RunConfig& config_;
  RunOptions options_;
  std::filesystem::path dir_, checkpoint_file_;
  Stopwatch wall_, since_checkpoint_, since_report_;
  const parallel::Communicator& world_ = parallel::Communicator::world();
  std::unique_ptr<Method> method_;
  std::unique_ptr<Method> gathered_;  // a distributed run's whole state, on rank 0 (whole())
  long points_ = 0;                   // material points of the whole run
  std::unique_ptr<io::FieldWriter> writer_;
  io::RunRecord record_;
  double next_output_ = 0.0, next_checkpoint_ = 0.0;
  double previous_wall_seconds_ = 0.0, output_seconds_ = 0.0, checkpoint_seconds_ = 0.0;
  long checkpoint_step_ = -1;  // step of the checkpoint on disk for this run, -1: none yet
  Stop stop_ = Stop::none;
};

RunOutcome Run::execute() {
  const StopSignals signals;
  if (options_.restart && !std::filesystem::exists(checkpoint_file_))
    throw InputError(
        fmt::format("--restart {}: no checkpoint.h5 there (the run stopped before its first "
                    "checkpoint): start it again from its deck",
                    dir_.string()));
  // Rank 0 writes the run folder; a distributed run's other ranks only compute. A restart's ranks
  // have all read its resolved deck before rank 0 writes it again.
  if (options_.restart) world_.any(false);
  if (root()) {
    std::filesystem::create_directories(dir_);
    io::writeResolvedDeck(config_, dir_ / "deck.resolved.yaml");
  }
  record_.title = config_.title;
  record_.deck = config_.deck_path;
  record_.threads = omp_get_max_threads();
  record_.ranks = world_.size();
  log::info("kessler: {} ({})", config_.title.empty() ? "untitled run" : config_.title, config_.deck_path);
  if (root()) writer_ = std::make_unique<io::FieldWriter>(dir_);
  if (options_.restart) resume();  // before the try: a bad checkpoint leaves the run folder alone
  std::optional<Progress> progress;
  bool caller_stop = false;
  try {
    if (!options_.restart) start();
    progress.emplace(config_.solver.end_time, points_, options_.progress && root());
    while (!method_->finished()) {
      if (config_.solver.max_steps > 0 && steps() >= config_.solver.max_steps) {
        stop_ = Stop::max_steps;
        break;
      }
      // mpirun passes a signal to every rank, not at the same step: they stop together.
      if (world_.any(StopSignals::received() != 0 || caller_stop)) {
        stop_ = Stop::signal;
        break;
      }
      advance();
      progress->update(steps(), time(), lastStep());
      if (options_.on_progress && root() && since_report_.seconds() >= options_.report_interval) {
        caller_stop = !report();
        since_report_.restart();
      }
    }
  } catch (const NumericalError& e) {
    if (progress) progress->finish(steps(), time(), lastStep());
    fail(e);
  }
  progress->finish(steps(), time(), lastStep());
  if (options_.on_progress && root() && stop_ == Stop::none && method_) report();

  // The checkpoint comes before any extra output, so that a restart continues exactly as the run
  // would have gone on (with the history and output series it would have had).
  if (checkpoint_step_ != steps()) checkpoint();
  const std::string restart_hint = fmt::format("kessler run --restart {}", dir_.string());
  if (stop_ == Stop::signal) {
    const int signal = StopSignals::received() != 0 ? StopSignals::received() : SIGINT;
    const bool by_caller = caller_stop && StopSignals::received() == 0;
    record_.status = "interrupted";
    record_.message =
        fmt::format("stopped by {} at step {}, t = {:.6g} s; a checkpoint is in {}",
                    by_caller ? "the caller" : signalName(signal), steps(), time(), checkpoint_file_.string());
    finish();
    log::info("kessler: {}; continue with: {}", record_.message, restart_hint);
    return {dir_, 128 + signal, by_caller};
  }
  if (record_.history.back().step != steps()) {
    appendHistory();
    output();
  }
  if (stop_ == Stop::max_steps) {
    record_.status = "stopped";
    record_.message = fmt::format("stopped at solver.max_steps = {} (t = {:.6g} s)", config_.solver.max_steps, time());
    log::info("kessler: {}; continue with: {} --set solver.max_steps=0", record_.message, restart_hint);
  }
  // A run stopped at max_steps is unfinished, like one stopped by a signal: no analysis.
  if (stop_ == Stop::none) analyse("final");
  finish();
  printSummary();
  if (stop_ == Stop::none) plots();
  return {dir_, 0};
}

// A new run: mesh, initial state, the first output.
void Run::start() {
  Stopwatch meshing;
  log::info("meshing {} bodies", config_.bodies.size());
  method_ = buildMethod(config_, &world_);
  record_.extra_timings["meshing"] = meshing.seconds();
  // Every rank has built the whole model; initialise() splits it.
  points_ = method_->state().points.owned;
  if (world_.size() > 1)
    log::info("model: {} material points, {} nodes; {} ranks of {} threads", points_, method_->nodes().owned,
              world_.size(), record_.threads);
  else
    log::info("model: {} material points, {} nodes; {} threads", points_, method_->nodes().owned, record_.threads);
  method_->initialise();
  appendHistory();
  check();
  output();
  next_output_ = config_.output.every > 0.0 ? config_.output.every : config_.solver.end_time;
  next_checkpoint_ = config_.checkpoint.every;
}

// A restart: the model, the integrator and the run's bookkeeping from the checkpoint.
void Run::resume() {
  Stopwatch restoring;
  RestoredRun restored = restoreMethod(config_, checkpoint_file_, &world_);
  method_ = std::move(restored.method);
  points_ = restored.points;
  const io::RunLoopState& loop = restored.loop;
  record_.history = loop.history;
  record_.outputs = loop.outputs;
  KESSLER_VERIFY(!record_.history.empty(), "checkpoint '{}' holds no history", checkpoint_file_.string());
  next_output_ = loop.next_output;
  next_checkpoint_ = loop.next_checkpoint;
  previous_wall_seconds_ = loop.wall_seconds;
  checkpoint_step_ = steps();
  // Outputs written after the checkpoint belong to a future this run recomputes.
  if (root()) {
    removeOutputsOutside(dir_, loop.point_grids);
    writer_->restoreSeries(loop.point_grids, loop.node_grids);
    io::writeHistory(dir_ / "history.csv", record_.history);
  }
  record_.extra_timings["restore"] = restoring.seconds();
  if (world_.size() > 1)
    log::info("restarting from {}: step {}, t = {:.6g} s; {} material points; {} ranks of {} threads",
              checkpoint_file_.string(), steps(), time(), points_, world_.size(), record_.threads);
  else
    log::info("restarting from {}: step {}, t = {:.6g} s; {} material points, {} nodes; {} threads",
              checkpoint_file_.string(), steps(), time(), points_, method_->nodes().owned, record_.threads);
}

// One step, with its checks, and the output and checkpoint that fall due after it.
void Run::advance() {
  method_->step();  // a numerical failure names its step and time
  check();
  if (time() >= next_output_ * (1.0 - 1e-9) || method_->finished()) {
    appendHistory();
    output();
    const double every = config_.output.every > 0.0 ? config_.output.every : config_.solver.end_time;
    while (next_output_ <= time() * (1.0 + 1e-9)) next_output_ += every;
  }
  if (!method_->finished() && checkpointDue()) checkpoint();
}

void Run::output() {
  Stopwatch watch;
  const Method* run = whole();
  if (root()) {
    writer_->write(steps(), time(), run->nodes(), run->state().points);
    io::writeHistory(dir_ / "history.csv", record_.history);
  }
  ++record_.outputs;
  output_seconds_ += watch.seconds();
}

bool Run::checkpointDue() const {
  const io::CheckpointConfig& c = config_.checkpoint;
  return (c.every > 0.0 && time() >= next_checkpoint_ * (1.0 - 1e-9)) ||
         (c.wall_interval > 0.0 && since_checkpoint_.seconds() >= c.wall_interval);
}

void Run::checkpoint() {
  Stopwatch watch;
  const double every = config_.checkpoint.every;
  if (every > 0.0)
    while (next_checkpoint_ <= time() * (1.0 + 1e-9)) next_checkpoint_ += every;
  const Method* run = whole(true);
  if (root()) {
    const io::RunLoopState loop{next_output_,        next_checkpoint_, previous_wall_seconds_ + wall_.seconds(),
                                record_.outputs,     record_.history,  writer_->pointGrids(),
                                writer_->nodeGrids()};
    io::writeCheckpoint(checkpoint_file_, *run, loop);
  }
  checkpoint_step_ = steps();
  since_checkpoint_.restart();
  checkpoint_seconds_ += watch.seconds();
}

// Keeps what the run had computed: the state at the failure as the last output, for inspection
// in ParaView. The last checkpoint stays as it was (the last good state to restart from).
void Run::fail(const NumericalError& e) {
  record_.status = "failed";
  record_.message = e.what();
  std::string where = fmt::format("the state at the failure is the last output in {}", dir_.string());
  if (method_) {
    appendHistory();
    output();
    analyse("at the failure");
    finish();
    plots();
  } else {
    where = "no state was written";
  }
  const std::string last = checkpoint_step_ >= 0 ? fmt::format("the last checkpoint (step {}) is {}", checkpoint_step_,
                                                               checkpoint_file_.string())
                                                 : std::string("no checkpoint was written");
  throw NumericalError(fmt::format("{}; {}; {}", e.what(), where, last));
}

void Run::printSummary() const {
  if (!root()) return;
  const Energies& e0 = record_.history.front().energies;
  const Energies& e1 = record_.history.back().energies;
  const double point_steps = static_cast<double>(steps()) * static_cast<double>(points_);
  log::info("{} steps to t = {:.4g} s in {:.1f} s wall ({:.3g} us per material-point step, {} threads)", steps(),
            time(), record_.wall_seconds, point_steps > 0 ? 1e6 * record_.wall_seconds / point_steps : 0.0,
            record_.threads);
  // (The stabilisation's share where a method keeps one: docs/theory.md §4 and §10.)
  const std::string stored = e0.stabilisation != 0.0 || e1.stabilisation != 0.0
                                 ? fmt::format(", stabilisation {:.6g} -> {:.6g} J", e0.stabilisation, e1.stabilisation)
                                 : std::string();
  log::info("energy: kinetic {:.6g} -> {:.6g} J, internal {:.6g} -> {:.6g} J{}, total {:.6g} -> {:.6g} J", e0.kinetic,
            e1.kinetic, e0.internal, e1.internal, stored, e0.total(), e1.total());
  log::info("momentum: ({:.6g}, {:.6g}, {:.6g}) -> ({:.6g}, {:.6g}, {:.6g}) kg m/s", e0.momentum[0], e0.momentum[1],
            e0.momentum[2], e1.momentum[0], e1.momentum[1], e1.momentum[2]);
  // (A distributed run's notes are those of the whole run, gathered by finish().)
  for (const std::string& note : (gathered_ ? gathered_ : method_)->notes()) log::info("{}", note);
  log::info("results in {}/ (points.xdmf and nodes.xdmf open in ParaView; summary.json, history.csv)", dir_.string());
}

}  // namespace

RunOutcome runSimulation(const io::RunConfig& config, const RunOptions& options) {
  if (options.threads > 0) omp_set_num_threads(options.threads);
  Run run(config, options);
  return run.execute();
}

}  // namespace kessler::app
