// The `kessler` command line: run, check, verify.
#include "app/commands.hpp"
#include "core/error.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <exception>

int main(int argc, char** argv) {
  CLI::App app{"Kessler: hypervelocity impact simulation with the Optimal Transportation Meshfree method"};
  app.require_subcommand(1);
  kessler::app::addCommands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const kessler::Error& e) {
    // One handler at the top: a one-line message, non-zero exit, never a stack trace.
    fmt::print(stderr, "kessler: error: {}\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    fmt::print(stderr, "kessler: internal error: {}\n", e.what());
    return 2;
  }
  return kessler::app::exitCode();
}
