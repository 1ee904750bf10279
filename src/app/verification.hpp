#pragma once
// Running the built-in verification problems (`kessler verify`, kessler.verify() in Python).
#include "verify/problem.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace kessler::app {

// The problems named (all of them if `names` is empty), in the registry's order. Throws
// InputError for a name that is not a problem, listing the known ones.
std::vector<const verify::Check*> selectProblems(const std::vector<std::string>& names);

// The method the problems run (solver.method). Throws InputError for one this build lacks.
void useVerifyMethod(const std::string& method);

// Runs one problem and times it. A problem whose run breaks down (or that the method cannot run)
// comes back failed, with the reason as its note, so that the others still run.
verify::Outcome runProblem(const verify::Check& check);

// One outcome as a JSON object (the lines of `kessler verify --json`).
nlohmann::json outcomeJson(const verify::Outcome& outcome);

}  // namespace kessler::app
