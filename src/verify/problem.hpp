#pragma once
// Built-in verification problems (`kessler verify`, docs/validation.md): each check runs a small problem
// and compares one measured number with an analytic or published reference.
#include <functional>
#include <string>
#include <vector>

namespace kessler::verify {

enum class Comparison {
  relative,  // pass when |measured - reference| / |reference| <= tolerance
  absolute,  // pass when |measured - reference| <= tolerance (for references that are 0)
};

struct Outcome {
  std::string name;
  std::string quantity;  // what was measured, with its unit
  double measured = 0.0;
  double reference = 0.0;
  double error = 0.0;  // relative or absolute, as `comparison` says
  double tolerance = 0.0;
  Comparison comparison = Comparison::relative;
  bool passed = false;
  double seconds = 0.0;
  std::string note;  // how the reference was obtained, resolution, ...
};

struct Check {
  std::string name;
  std::string description;
  std::function<Outcome()> run;
};

// Fills error and passed from measured, reference and tolerance.
Outcome compare(Outcome outcome);

const std::vector<Check>& problems();

}  // namespace kessler::verify
