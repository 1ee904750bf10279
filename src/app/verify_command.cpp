// `kessler verify [NAME ...] [--json]`: runs the built-in verification problems and prints,
// per problem, measured value, reference, error, tolerance and pass/fail.
#include "app/commands.hpp"
#include "app/verification.hpp"

#include <fmt/format.h>

#include <memory>

namespace kessler::app {

namespace {

struct VerifyOptions {
  std::vector<std::string> names;
  bool json = false;
  bool list = false;
  std::string method = "otm";
};

void runVerify(const VerifyOptions& options) {
  if (options.list) {
    for (const verify::Check& p : verify::problems()) fmt::print("{:<20} {}\n", p.name, p.description);
    return;
  }
  useVerifyMethod(options.method);
  const std::vector<const verify::Check*> chosen = selectProblems(options.names);
  if (!options.json)
    fmt::print("{:<20} {:>13} {:>13} {:>10} {:>9}  {:<6} {}\n", "problem", "measured", "reference", "error",
               "tolerance", "result", "quantity");
  int failed = 0;
  for (const verify::Check* p : chosen) {
    const verify::Outcome o = runProblem(*p);
    failed += !o.passed;
    if (options.json) {
      fmt::print("{}\n", outcomeJson(o).dump());
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
