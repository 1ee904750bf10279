// `kessler verify [NAME ...] [--json]`: runs the built-in verification problems and prints,
// per problem, measured value, reference, error, tolerance and pass/fail.
#include "app/commands.hpp"
#include "core/error.hpp"
#include "core/timer.hpp"
#include "solver/methods.hpp"
#include "verify/fixtures.hpp"
#include "verify/problem.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include <limits>
#include <memory>

namespace kessler::app {

namespace {

struct VerifyOptions {
  std::vector<std::string> names;
  bool json = false;
  bool list = false;
  std::string method = "otm";
};

std::vector<const verify::Check*> select(const std::vector<std::string>& names) {
  std::vector<const verify::Check*> chosen;
  for (const verify::Check& p : verify::problems())
    if (names.empty() || std::find(names.begin(), names.end(), p.name) != names.end()) chosen.push_back(&p);
  for (const std::string& name : names) {
    const bool known = std::any_of(verify::problems().begin(), verify::problems().end(),
                                   [&](const verify::Check& p) { return p.name == name; });
    if (!known) {
      std::string all;
      for (const verify::Check& p : verify::problems()) all += (all.empty() ? "" : ", ") + p.name;
      throw InputError(fmt::format("unknown verification problem '{}' (known: {})", name, all));
    }
  }
  return chosen;
}

nlohmann::json toJson(const verify::Outcome& o) {
  return {{"name", o.name},
          {"quantity", o.quantity},
          {"measured", o.measured},
          {"reference", o.reference},
          {"error", o.error},
          {"error_kind", o.comparison == verify::Comparison::relative ? "relative" : "absolute"},
          {"tolerance", o.tolerance},
          {"passed", o.passed},
          {"seconds", o.seconds},
          {"note", o.note}};
}

void runVerify(const VerifyOptions& options) {
  if (options.list) {
    for (const verify::Check& p : verify::problems()) fmt::print("{:<20} {}\n", p.name, p.description);
    return;
  }
  const std::vector<std::string>& methods = methodNames();
  if (std::find(methods.begin(), methods.end(), options.method) == methods.end())
    throw InputError(
        fmt::format("--method {}: not a method of this Kessler (known: {})", options.method, fmt::join(methods, ", ")));
  verify::useMethod(options.method);
  const std::vector<const verify::Check*> chosen = select(options.names);
  if (!options.json)
    fmt::print("{:<20} {:>13} {:>13} {:>10} {:>9}  {:<6} {}\n", "problem", "measured", "reference", "error",
               "tolerance", "result", "quantity");
  int failed = 0;
  for (const verify::Check* p : chosen) {
    Stopwatch watch;
    verify::Outcome o;
    try {
      o = p->run();
    } catch (const Error& e) {
      // A problem whose run breaks down (or that the method cannot run) has failed; the others
      // still run and report.
      o.name = p->name;
      o.quantity = "run failed";
      o.measured = o.reference = o.error = o.tolerance = std::numeric_limits<double>::quiet_NaN();
      o.passed = false;
      o.note = e.what();
    }
    o.seconds = watch.seconds();
    failed += !o.passed;
    if (options.json) {
      fmt::print("{}\n", toJson(o).dump());
    } else {
      fmt::print("{:<20} {:>13.6g} {:>13.6g} {:>10.3g} {:>9.3g}  {:<6} {} [{:.1f} s; {}]\n", o.name, o.measured,
                 o.reference, o.error, o.tolerance, o.passed ? "pass" : "FAIL", o.quantity, o.seconds, o.note);
    }
    std::fflush(stdout);
  }
  if (!options.json) fmt::print("{} passed, {} failed\n", chosen.size() - static_cast<std::size_t>(failed), failed);
  setExitCode(failed > 0 ? 1 : 0);
}

}  // namespace

void addVerifyCommand(CLI::App& app) {
  auto options = std::make_shared<VerifyOptions>();
  CLI::App* cmd = app.add_subcommand("verify", "Run the built-in verification problems against analytic answers");
  cmd->add_option("names", options->names, "Problems to run (default: all)");
  cmd->add_flag("--json", options->json, "Print one JSON object per problem instead of a table");
  cmd->add_flag("--list", options->list, "List the problems and exit");
  cmd->add_option("--method", options->method, "The method the problems run (solver.method): otm, sph or rkpm")
      ->capture_default_str();
  cmd->callback([options] { runVerify(*options); });
}

}  // namespace kessler::app
