// `kessler bench [NAME...] [--size tiny|small|full] [--threads N] [--steps N] [--set key=value ...] [--json FILE]`
// (docs/performance.md): runs benchmark problems and reports the cost per material-point step,
// the per-phase breakdown and the peak memory per material point.
// Each problem runs in a child process (this program again, with --single), so that the peak
// resident memory (getrusage ru_maxrss) is that problem's own, meshing included.
#include "app/bench_problems.hpp"
#include "app/commands.hpp"
#include "app/methods.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "core/timer.hpp"
#include "io/deck.hpp"
#include "io/fields_writer.hpp"
#include "parallel/communicator.hpp"
#include "solver/common/method.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <thread>

extern char** environ;

namespace kessler::app {

namespace {

struct BenchOptions {
  std::vector<std::string> names;
  std::string size = "full";
  int threads = 0;
  int steps = 0;
  std::string json;
  std::vector<std::string> overrides;  // deck settings changed from the problem's ("solver.otm.lme_gamma=4")
  bool single = false;                 // run one problem in this process (the child of a bench run)
};

// Peak resident set of this process, bytes (Linux reports ru_maxrss in KiB).
double peakResidentBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return 1024.0 * static_cast<double>(usage.ru_maxrss);
}

// Resident set now, bytes (second field of /proc/self/statm, in pages).
double residentBytes() {
  std::ifstream statm("/proc/self/statm");
  double size = 0.0, resident = 0.0;
  statm >> size >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE));
}

double loadAverage() {
  std::ifstream file("/proc/loadavg");
  double load = 0.0;
  file >> load;
  return load;
}

// OMP_WAIT_POLICY as the run sees it ("default" if unset): passive waiting costs a few per cent
// on two threads, so the figures say which it was.
std::string waitPolicy() {
  const char* policy = std::getenv("OMP_WAIT_POLICY");
  return policy != nullptr && *policy != '\0' ? std::string(policy) : std::string("default");
}

// The phases of the OTM step in the order of the breakdown; any other timer is added.
const std::vector<std::string> phase_order = {"search",      "shape functions", "assembly",
                                              "node update", "point update",    "constitutive",
                                              "erosion",     "time step",       "output"};

// One problem in this process; under mpirun (`ranks` of several), across the ranks, with rank 0
// writing the fields and reporting (docs/parallel.md).
nlohmann::json runOne(const BenchProblem& problem, BenchSize size, int steps_wanted,
                      const std::vector<std::string>& overrides,
                      const parallel::Communicator& ranks = parallel::Communicator::world()) {
  const double target = targetPoints(problem, size);
  const double h = meshSizeFor(problem, size, target);
  const int steps = steps_wanted > 0 ? steps_wanted : defaultSteps(problem, size);
  io::RunConfig config = io::parseDeckString(problem.deck(h, quarterModel(problem, size)),
                                             fmt::format("bench:{}", problem.name), overrides);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / fmt::format("kessler-bench-{}-{}", getpid(), problem.name);
  std::filesystem::remove_all(dir);

  const double resident_start = residentBytes();  // the program itself, before any model exists
  Stopwatch setup_watch;
  const std::unique_ptr<Method> method = buildMethod(config, &ranks);
  const double meshing = setup_watch.seconds();
  // Every rank has built the whole model; initialise() keeps its part.
  const LocalIndex whole_points = method->state().points.owned, whole_nodes = method->nodes().owned;
  method->initialise();
  const double setup = setup_watch.seconds();
  const std::map<std::string, double> before = method->timers().totals();
  std::optional<io::FieldWriter> writer;
  if (ranks.root()) writer.emplace(dir);
  auto write = [&] {
    std::unique_ptr<Method> gathered = method->gathered(false);
    const Method* whole = method->distributed() ? gathered.get() : method.get();
    if (!whole) return;
    const Clock clock = whole->clock();
    writer->write(clock.steps, clock.time, whole->nodes(), whole->state().points);
  };

  // Fields are written at the first and the last step, as a run stopped by max_steps does.
  double output = 0.0;
  Stopwatch watch;
  std::string status = "ok", message;
  try {
    {
      Stopwatch w;
      write();
      output += w.seconds();
    }
    for (int s = 0; s < steps && !method->finished(); ++s) method->step();
    Stopwatch w;
    write();
    output += w.seconds();
  } catch (const NumericalError& e) {
    status = "failed";
    message = e.what();
  }
  const double wall = watch.seconds();
  if (ranks.root()) std::filesystem::remove_all(dir);

  const int threads = omp_get_max_threads();
  const auto points = static_cast<double>(whole_points);
  const long steps_taken = method->clock().steps;
  const double point_steps = points * static_cast<double>(steps_taken);
  std::map<std::string, double> phases;
  for (const auto& [name, seconds] : method->timers().totals()) {
    const auto it = before.find(name);
    phases[name] = seconds - (it == before.end() ? 0.0 : it->second);
  }
  phases["output"] = output;
  nlohmann::json phase_json = nlohmann::json::object(), phase_us = nlohmann::json::object();
  double accounted = 0.0;
  for (const auto& [name, seconds] : phases) {
    phase_json[name] = seconds;
    phase_us[name] = point_steps > 0 ? 1e6 * seconds / point_steps : 0.0;
    accounted += seconds;
  }
  phase_json["other"] = std::max(wall - accounted, 0.0);
  const double us = point_steps > 0 ? 1e6 * wall / point_steps : 0.0;
  // Memory: the largest rank's, and all ranks' together per point.
  const double peak = ranks.max(peakResidentBytes());
  std::int64_t peak_sum = static_cast<std::int64_t>(peakResidentBytes());
  peak_sum = ranks.sum(peak_sum);
  const double model_peak = ranks.max(std::max(peakResidentBytes() - resident_start, 0.0));
  nlohmann::json j = {
      {"name", problem.name},
      {"size", sizeName(size)},
      {"status", status},
      {"mesh_size_m", h},
      {"points", whole_points},
      {"nodes", whole_nodes},
      {"steps", steps_taken},
      {"threads", threads},
      {"ranks", ranks.size()},
      {"setup_s", setup},
      {"meshing_s", meshing},
      {"wall_s", wall},
      {"us_per_point_step", us},
      {"core_us_per_point_step", us * threads * ranks.size()},
      {"phases_s", phase_json},
      {"phases_us_per_point_step", phase_us},
      {"peak_memory_bytes", peak},
      {"peak_memory_bytes_per_point", points > 0 ? static_cast<double>(peak_sum) / points : 0.0},
      {"peak_model_bytes_per_point", points > 0 ? model_peak * ranks.size() / points : 0.0},
      {"peak_memory_bytes_per_rank_point", points > 0 ? peak * ranks.size() / points : 0.0},
      {"quarter_model", quarterModel(problem, size)},
      {"resident_end_bytes_per_point", points > 0 ? residentBytes() / points : 0.0},
      {"load_average", loadAverage()},
      {"omp_wait_policy", waitPolicy()},
      {"overrides", overrides},
  };
  for (const auto& [name, value] : method->sizes()) j[name] = value;
  if (!message.empty()) j["message"] = message;
  return j;
}

void printResult(const nlohmann::json& r) {
  fmt::print(
      "{} ({}): {} points, {} nodes, {:.1f} neighbours per point, {} steps, {} thread(s){}, OpenMP wait policy {}\n",
      r["name"].get<std::string>(), r["size"].get<std::string>(), r["points"].get<long>(), r["nodes"].get<long>(),
      r["mean_neighbours"].get<double>(), r["steps"].get<long>(), r["threads"].get<int>(),
      r.value("ranks", 1) > 1 ? fmt::format(" on each of {} ranks", r.value("ranks", 1)) : std::string(),
      r.value("omp_wait_policy", std::string("default")));
  if (r.contains("overrides") && !r["overrides"].empty())
    fmt::print("  with --set {}\n", fmt::join(r["overrides"].get<std::vector<std::string>>(), " --set "));
  fmt::print("  {:.3f} s stepping ({:.2f} s setup): {:.3f} us per point-step wall, {:.3f} us core (x threads)\n",
             r["wall_s"].get<double>(), r["setup_s"].get<double>(), r["us_per_point_step"].get<double>(),
             r["core_us_per_point_step"].get<double>());
  const double wall = r["wall_s"].get<double>();
  const auto& phases = r["phases_s"];
  auto line = [&](const std::string& name) {
    const double s = phases[name].get<double>();
    fmt::print("    {:<16} {:9.4f} s {:5.1f}%  {:8.4f} us/point-step\n", name, s, wall > 0 ? 100.0 * s / wall : 0.0,
               r["phases_us_per_point_step"].contains(name) ? r["phases_us_per_point_step"][name].get<double>() : 0.0);
  };
  for (const std::string& name : phase_order)
    if (phases.contains(name)) line(name);
  for (const auto& [name, value] : phases.items())
    if (std::find(phase_order.begin(), phase_order.end(), name) == phase_order.end()) line(name);
  fmt::print(
      "  peak memory {:.1f} MB: {:.0f} bytes per material point, {:.0f} above the program's own; {:.0f} resident at "
      "the end; load {:.2f}\n",
      r["peak_memory_bytes"].get<double>() / 1e6, r["peak_memory_bytes_per_point"].get<double>(),
      r["peak_model_bytes_per_point"].get<double>(), r["resident_end_bytes_per_point"].get<double>(),
      r["load_average"].get<double>());
  if (r["status"] != "ok") fmt::print("  FAILED: {}\n", r.value("message", std::string()));
}

void writeJson(const std::string& file, const nlohmann::json& j) {
  std::ofstream out(file);
  KESSLER_VERIFY(out.good(), "cannot write '{}'", file);
  out << j.dump(2) << "\n";
  KESSLER_VERIFY(out.good(), "cannot write '{}'", file);
}

// Runs `kessler bench NAME --single ...` as a child process; returns its JSON result.
nlohmann::json runChild(const std::string& name, const BenchOptions& options) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / fmt::format("kessler-bench-{}-{}.json", getpid(), name);
  std::vector<std::string> args = {"/proc/self/exe", "bench",      name,     "--single",
                                   "--size",         options.size, "--json", file.string()};
  if (options.threads > 0) args.insert(args.end(), {"--threads", std::to_string(options.threads)});
  if (options.steps > 0) args.insert(args.end(), {"--steps", std::to_string(options.steps)});
  for (const std::string& o : options.overrides) args.insert(args.end(), {"--set", o});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, "/proc/self/exe", nullptr, nullptr, argv.data(), environ);
  KESSLER_VERIFY(spawned == 0, "bench: cannot start a child process ({})", std::strerror(spawned));
  int wstatus = 0;
  waitpid(pid, &wstatus, 0);
  if (!WIFEXITED(wstatus) || WEXITSTATUS(wstatus) != 0 || !std::filesystem::exists(file)) {
    std::filesystem::remove(file);
    throw Error(fmt::format("bench {}: the benchmark process failed (status {})", name, wstatus));
  }
  std::ifstream in(file);
  nlohmann::json j = nlohmann::json::parse(in);
  std::filesystem::remove(file);
  return j;
}

void runBench(const BenchOptions& options) {
  const BenchSize size = parseBenchSize(options.size);
  std::vector<std::string> names = options.names;
  if (names.empty())
    for (const BenchProblem& p : benchProblems()) names.push_back(p.name);
  for (const std::string& name : names) benchProblem(name);  // unknown names fail before any run
  if (options.threads > 0) omp_set_num_threads(options.threads);

  // Under mpirun every rank runs each problem together, in this process.
  const parallel::Communicator& world = parallel::Communicator::world();
  if (world.size() > 1) {
    nlohmann::json all = {{"size", options.size}, {"ranks", world.size()}, {"problems", nlohmann::json::array()}};
    for (const std::string& name : names) {
      nlohmann::json r = runOne(benchProblem(name), size, options.steps, options.overrides, world);
      if (world.root()) printResult(r);
      all["problems"].push_back(std::move(r));
    }
    if (world.root() && !options.json.empty()) writeJson(options.json, all);
    return;
  }
  if (options.single) {
    KESSLER_VERIFY(names.size() == 1, "bench --single runs exactly one problem");
    log::setLevel(log::Level::quiet);
    const nlohmann::json r = runOne(benchProblem(names.front()), size, options.steps, options.overrides);
    if (!options.json.empty()) writeJson(options.json, r);
    return;
  }
  nlohmann::json all = {{"size", options.size},
                        {"threads", options.threads > 0 ? options.threads : omp_get_max_threads()},
                        {"hardware_threads", std::thread::hardware_concurrency()},
                        {"problems", nlohmann::json::array()}};
  bool failed = false;
  for (const std::string& name : names) {
    nlohmann::json r = runChild(name, options);
    printResult(r);
    failed = failed || r["status"] != "ok";
    all["problems"].push_back(std::move(r));
  }
  if (!options.json.empty()) writeJson(options.json, all);
  if (failed) setExitCode(1);
}

}  // namespace

void addBenchCommand(CLI::App& app) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* bench = app.add_subcommand("bench", "Run benchmark problems and report the cost per material-point step");
  bench->add_option("names", options->names, "Problems (default: all): hvi-100k, hvi-1m, pysph-impact3d");
  bench->add_option("--size", options->size, "tiny (CI: ~3k points, 10 steps), small (a tenth) or full")
      ->check(CLI::IsMember({"tiny", "small", "full"}));
  bench->add_option("--threads", options->threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  bench->add_option("--steps", options->steps, "Steps per problem (default: 10 tiny, 30 or 10 full)")
      ->check(CLI::PositiveNumber);
  bench->add_option("--json", options->json, "Write the results as JSON to this file");
  bench->add_option("--set", options->overrides,
                    "Change a setting of the problem's deck, as for run (e.g. --set solver.otm.lme_gamma=4)");
  bench->add_flag("--single", options->single, "Run one problem in this process (used by bench itself)")->group("");
  bench->callback([options] { runBench(*options); });
}

}  // namespace kessler::app
