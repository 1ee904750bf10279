#pragma once
// `kessler eos-table`: writes a SESAME table (201 + 301) from an analytic equation of state, so
// that users can check the tabular path or feed another code (docs/eos.md).
#include <CLI/CLI.hpp>

namespace kessler::app {

void addEosTableCommand(CLI::App& app);

}  // namespace kessler::app
