// `kessler limit DECK --speeds 3 5 7 [--min 1] [--max 10] [--step 0.25] [--out DIR]`: a simulated
// ballistic-limit curve (docs/analysis.md §12). For each speed, the diameter of the deck's spherical
// projectile is bisected until the rear wall (the last plate) just fails, in the sense of the NASA
// damage scale (detached spall or perforation). Each trial is a whole run of the deck with the
// projectile scaled: its leading point and its direction stay, its mesh size scales with its
// diameter (as many cells across), and the end time scales with 1/speed (the debris travels as
// far). Writes DIR/limit.csv (one row per speed, with Christiansen's critical diameter beside it),
// DIR/trials.csv (every run) and, with matplotlib, DIR/limit.png.
#include "app/commands.hpp"
#include "app/impact_analysis.hpp"
#include "app/simulation.hpp"
#include "core/error.hpp"
#include "core/log.hpp"
#include "io/deck.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

namespace kessler::app {

namespace fs = std::filesystem;

namespace {

struct LimitArguments {
  std::string deck;
  std::string out = "limit";
  std::vector<double> speeds;                 // km/s
  double min = 1.0, max = 10.0, step = 0.25;  // mm
  int threads = 0;
  std::vector<std::string> sets;
};

struct Trial {
  double diameter = 0.0;  // m
  bool failed = false;
  std::string classification;
  double christiansen = 0.0;  // m, Christiansen's (or Cour-Palais's) critical diameter at this speed
  double obliquity = 0.0;     // deg, as the analysis measured it
  double seconds = 0.0;
};

// The deck's projectile: a sphere, the first of the analysis' projectiles.
struct Projectile {
  int body = -1;
  geometry::Sphere sphere;
  Vec3 direction = Vec3::Zero();
  double mesh_size = 0.0;
};

Projectile projectileOf(const io::RunConfig& config, const std::string& deck) {
  if (!config.analysis.enabled || config.analysis.projectiles.empty() || config.analysis.plates.empty())
    throw InputError(
        fmt::format("{}: kessler limit needs the impact analysis, with a projectile and a rear wall "
                    "(docs/analysis.md)",
                    deck));
  Projectile p;
  p.body = config.analysis.projectiles.front();
  const io::BodyConfig& body = config.bodies[static_cast<std::size_t>(p.body)];
  const auto* sphere = std::get_if<geometry::Sphere>(&body.mesh.shape);
  if (!sphere)
    throw InputError(
        fmt::format("{}: kessler limit scales a spherical projectile; '{}' is not a sphere", deck, body.name));
  if (!(body.velocity.norm() > 0.0))
    throw InputError(fmt::format("{}: the projectile '{}' does not move", deck, body.name));
  p.sphere = *sphere;
  p.direction = body.velocity.normalized();
  p.mesh_size = body.mesh.mesh_size;
  return p;
}

// One run of the deck with the projectile's diameter and speed changed.
Trial runTrial(const io::RunConfig& base, const Projectile& projectile, double speed, double diameter,
               const fs::path& dir, int threads) {
  io::RunConfig config = base;
  io::BodyConfig& body = config.bodies[static_cast<std::size_t>(projectile.body)];
  const double radius = 0.5 * diameter, radius0 = projectile.sphere.radius;
  // The leading point stays where the deck put it, so the gap to the first plate is the deck's.
  const Vec3 centre = projectile.sphere.center + (radius0 - radius) * projectile.direction;
  body.mesh.shape = geometry::Sphere{centre, radius};
  body.mesh.mesh_size = projectile.mesh_size * std::min(1.0, radius / radius0);
  const double speed0 = base.analysis.impact_speed > 0.0 ? base.analysis.impact_speed : body.velocity.norm();
  body.velocity = speed * projectile.direction;
  config.analysis.impact_speed = speed;
  config.solver.end_time = base.solver.end_time * speed0 / speed;
  config.analysis.plots = false;
  config.output.dir = dir.string();

  const auto start = std::chrono::steady_clock::now();
  // One line per trial from the caller instead of each run's report.
  const log::Level level = log::level();
  log::setLevel(log::Level::quiet);
  try {
    runSimulation(config, RunOptions{.threads = threads, .progress = false, .restart = false});
  } catch (...) {
    log::setLevel(level);
    throw;
  }
  log::setLevel(level);
  Trial t;
  t.diameter = diameter;
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ifstream in(dir / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  const nlohmann::json& analysis = summary.at("analysis");
  if (summary.at("status") != "completed" || !analysis.contains("rear_wall"))
    throw NumericalError(fmt::format("kessler limit: the run in {} did not complete with a rear-wall analysis ({})",
                                     dir.string(), summary.at("status").get<std::string>()));
  t.failed = analysis.at("rear_wall").at("failed").get<bool>();
  t.classification = analysis.at("rear_wall").at("classification").get<std::string>();
  if (analysis.contains("ballistic_limit")) {
    t.christiansen = analysis.at("ballistic_limit").at("critical_diameter_m").get<double>();
    t.obliquity = analysis.at("ballistic_limit").at("obliquity_deg").get<double>();
  }
  return t;
}

void runLimit(const LimitArguments& args) {
  if (args.speeds.empty()) throw InputError("kessler limit: give at least one speed (--speeds, km/s)");
  if (!(args.step > 0.0 && args.min > 0.0 && args.max > args.min))
    throw InputError(fmt::format("kessler limit: need 0 < --min < --max and --step > 0 (got {}, {}, {} mm)", args.min,
                                 args.max, args.step));
  const io::RunConfig base = io::parseDeck(args.deck, args.sets);
  const Projectile projectile = projectileOf(base, args.deck);
  const fs::path out = args.out;
  fs::create_directories(out);
  std::ofstream trials(out / "trials.csv"), limits(out / "limit.csv");
  trials << "speed_m_per_s,diameter_m,classification,failed,christiansen_m,wall_s\n";
  limits << "speed_m_per_s,critical_diameter_m,held_m,failed_m,runs,christiansen_m,note\n";
  const double mm = 1e-3, step = args.step * mm;
  double obliquity = 0.0;
  // log::info writes each line as it happens, also when the output goes to a file: a trial takes minutes.
  log::info("kessler limit: {} ('{}' scaled), {} speed(s), diameters {:.2f}-{:.2f} mm in steps of {:.2f} mm", args.deck,
            base.bodies[static_cast<std::size_t>(projectile.body)].name, args.speeds.size(), args.min, args.max,
            args.step);
  for (const double kms : args.speeds) {
    const double speed = kms * 1e3;
    int runs = 0;
    double christiansen = 0.0;
    auto trial = [&](double d) {
      const fs::path dir = out / fmt::format("v{:.2f}_d{:.2f}", kms, d / mm);
      const Trial t = runTrial(base, projectile, speed, d, dir, args.threads);
      ++runs;
      // A trial where nothing broke has no ballistic-limit verdict (analysis "debris": false).
      if (t.christiansen > 0.0) {
        christiansen = t.christiansen;
        obliquity = t.obliquity;
      }
      trials << fmt::format("{},{},{},{},{},{:.1f}\n", speed, d, t.classification, t.failed ? 1 : 0,
                            t.christiansen > 0.0 ? fmt::format("{}", t.christiansen) : "", t.seconds);
      trials.flush();
      log::info("  {:.2f} km/s, d = {:.2f} mm: rear wall {} ({}), {:.0f} s", kms, d / mm, t.classification,
                t.failed ? "fails" : "holds", t.seconds);
      return t.failed;
    };
    // The largest first: if the wall holds there, the limit lies beyond the range.
    double held = args.min * mm, failed = args.max * mm;
    std::string note;
    if (!trial(failed)) {
      note = "holds at the largest diameter";
      held = failed;
      failed = 0.0;
    } else if (trial(held)) {
      note = "fails at the smallest diameter";
      failed = held;
      held = 0.0;
    } else {
      // Halve the bracket until it is no wider than the step.
      while (failed - held > step * (1.0 + 1e-9)) {
        const double mid = 0.5 * (held + failed);
        (trial(mid) ? failed : held) = mid;
      }
    }
    const double critical = held > 0.0 && failed > 0.0 ? 0.5 * (held + failed) : 0.0;
    limits << fmt::format("{},{},{},{},{},{},{}\n", speed, critical, held, failed, runs, christiansen, note);
    limits.flush();
    if (critical > 0.0)
      log::info("  {:.2f} km/s: critical diameter {:.2f} mm (holds at {:.2f}, fails at {:.2f}); Christiansen {:.2f} mm",
                kms, critical / mm, held / mm, failed / mm, christiansen / mm);
    else
      log::info("  {:.2f} km/s: {} ({:.2f} mm); Christiansen {:.2f} mm", kms, note, (held > 0.0 ? held : failed) / mm,
                christiansen / mm);
  }
  log::info("kessler limit: obliquity {:.1f} deg; wrote {}", obliquity, (out / "limit.csv").string());
  drawPlots(out, {"limit.py"});
}

}  // namespace

void addLimitCommand(CLI::App& app) {
  auto args = std::make_shared<LimitArguments>();
  CLI::App* limit = app.add_subcommand(
      "limit", "Simulated ballistic limit: bisect the projectile's diameter until the rear wall just fails");
  limit->add_option("deck", args->deck, "YAML deck with a spherical projectile and a rear wall")
      ->required()
      ->check(CLI::ExistingFile);
  limit->add_option("--speeds", args->speeds, "Impact speeds, km/s")->required()->expected(1, 100);
  limit->add_option("--min", args->min, "Smallest diameter, mm (default 1)");
  limit->add_option("--max", args->max, "Largest diameter, mm (default 10)");
  limit->add_option("--step", args->step, "Resolution of the bisection, mm (default 0.25)");
  limit->add_option("--out", args->out, "Output folder (default: limit)");
  limit->add_option("--threads", args->threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  limit->add_option("--set", args->sets, "Override a deck value, as for run");
  limit->callback([args] { runLimit(*args); });
}

}  // namespace kessler::app
