#pragma once
// Subcommands of the `kessler` program. Each registers itself on the CLI11 app; its callback
// runs the command and records the exit code.
#include <CLI/CLI.hpp>

namespace kessler::app {

void addCommands(CLI::App& app);
void addVerifyCommand(CLI::App& app);
void addRunCommands(CLI::App& app);  // run and check
void addBenchCommand(CLI::App& app);
void addLimitCommand(CLI::App& app);  // the simulated ballistic limit
void addRenderCommand(CLI::App& app);  // ParaView pictures of a run

void setExitCode(int code);
int exitCode();

}  // namespace kessler::app
