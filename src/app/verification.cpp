#include "app/verification.hpp"

#include "core/error.hpp"
#include "core/timer.hpp"
#include "solver/methods.hpp"
#include "verify/fixtures.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <limits>

namespace kessler::app {

std::vector<const verify::Check*> selectProblems(const std::vector<std::string>& names) {
  const std::vector<verify::Check>& all = verify::problems();
  for (const std::string& name : names) {
    const bool known = std::any_of(all.begin(), all.end(), [&](const verify::Check& p) { return p.name == name; });
    if (!known) {
      std::vector<std::string> known_names;
      for (const verify::Check& p : all) known_names.push_back(p.name);
      throw InputError(
          fmt::format("unknown verification problem '{}' (known: {})", name, fmt::join(known_names, ", ")));
    }
  }
  std::vector<const verify::Check*> chosen;
  for (const verify::Check& p : all)
    if (names.empty() || std::find(names.begin(), names.end(), p.name) != names.end()) chosen.push_back(&p);
  return chosen;
}

void useVerifyMethod(const std::string& method) {
  const std::vector<std::string>& methods = methodNames();
  if (std::find(methods.begin(), methods.end(), method) == methods.end())
    throw InputError(
        fmt::format("method '{}': not a method of this Kessler (known: {})", method, fmt::join(methods, ", ")));
  verify::useMethod(method);
}

verify::Outcome runProblem(const verify::Check& check) {
  Stopwatch watch;
  verify::Outcome o;
  try {
    o = check.run();
  } catch (const Error& e) {
    o.name = check.name;
    o.quantity = "run failed";
    o.measured = o.reference = o.error = o.tolerance = std::numeric_limits<double>::quiet_NaN();
    o.passed = false;
    o.note = e.what();
  }
  o.seconds = watch.seconds();
  return o;
}

nlohmann::json outcomeJson(const verify::Outcome& o) {
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

}  // namespace kessler::app
