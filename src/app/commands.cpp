#include "app/commands.hpp"

#include "app/eos_table_command.hpp"

namespace kessler::app {

namespace {
int exit_code = 0;
}

void setExitCode(int code) {
  exit_code = code;
}
int exitCode() {
  return exit_code;
}

void addCommands(CLI::App& app) {
  addRunCommands(app);
  addVerifyCommand(app);
  addEosTableCommand(app);
  addBenchCommand(app);
  addLimitCommand(app);
  addRenderCommand(app);
}

}  // namespace kessler::app
