// `kessler render RUN [--time T ...] [--every N] [--color FIELD] [--size W H] [--out DIR]`: 3-D
// pictures of a run with ParaView (tools/plots/paraview_view.py under pvbatch; docs/running.md).
#include "app/commands.hpp"
#include "app/scripts.hpp"
#include "core/error.hpp"
#include "core/log.hpp"

#include <fmt/format.h>

#include <sys/wait.h>
#include <chrono>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace kessler::app {

namespace {

namespace fs = std::filesystem;

struct RenderArguments {
  std::string run;
  std::vector<double> times;  // s
  int every = 0;
  std::string color = "body";
  std::vector<int> size = {1280, 960};
  std::string out;
};

void render(const RenderArguments& args) {
  if (!fs::is_regular_file(fs::path(args.run) / "points.xdmf"))
    throw InputError(
        fmt::format("kessler render {}: no points.xdmf there, so not a run folder with outputs", args.run));
  const std::optional<fs::path> pvbatch = findProgram("pvbatch");
  if (!pvbatch)
    throw InputError("kessler render: ParaView's pvbatch is not installed (Debian: apt-get install paraview)");
  // ParaView draws with OpenGL on an X display; without one, a virtual one (xvfb-run).
  std::string prefix;
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') {
    if (!findProgram("xvfb-run"))
      throw InputError(
          "kessler render: no display (DISPLAY is not set) and no xvfb-run to make one (Debian: apt-get install "
          "xvfb xauth)");
    // A 24-bit screen (the default is 8-bit); Xvfb's own messages go to its log.
    const fs::path pictures = args.out.empty() ? fs::path(args.run) / "pictures" : fs::path(args.out);
    std::error_code error;
    fs::create_directories(pictures, error);
    prefix =
        fmt::format("xvfb-run -a -e {} -s '-screen 0 1920x1200x24' ", shellQuoted((pictures / "xvfb.log").string()));
  }
  std::string command = fmt::format("{}{} {} render {} --color {} --size {} {}", prefix, shellQuoted(pvbatch->string()),
                                    shellQuoted((plotsDir() / "paraview_view.py").string()), shellQuoted(args.run),
                                    shellQuoted(args.color), args.size[0], args.size[1]);
  if (!args.times.empty()) {
    command += " --time";
    for (const double t : args.times) command += fmt::format(" {}", t);
  }
  if (args.every > 0) command += fmt::format(" --every {}", args.every);
  if (!args.out.empty()) command += " --out " + shellQuoted(args.out);
  int status = runOutsideMpi(command);
  // Under load, xvfb-run has been seen to hand pvbatch a display it could not reach ("bad X server
  // connection", an abort): 1 run in a full parallel test suite, and once both of two tries made a
  // second apart (2026-12-03, the suite beside other runs), where the second may have met the first's
  // server still on its way out. Two more tries, after 3 and 10 s, each with a fresh server. Exit
  // status 1 is the script's own refusal (a field the run does not have): not retried.
  const auto refused = [](int s) { return WIFEXITED(s) && WEXITSTATUS(s) == 1; };
  for (const int pause : {3, 10}) {
    if (status == 0 || refused(status) || prefix.empty()) break;
    log::info("kessler render: pvbatch failed under xvfb-run (exit status {}); trying again in {} s",
              WIFEXITED(status) ? WEXITSTATUS(status) : status, pause);
    std::this_thread::sleep_for(std::chrono::seconds(pause));
    status = runOutsideMpi(command);
  }
  if (status != 0) {
    log::info("kessler render: pvbatch failed (exit status {})", WIFEXITED(status) ? WEXITSTATUS(status) : status);
    setExitCode(1);
  }
}

}  // namespace

void addRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArguments>();
  CLI::App* cmd = app.add_subcommand("render", "3-D pictures of a run's material points with ParaView (pvbatch)");
  cmd->add_option("run", args->run, "The run folder")->required();
  cmd->add_option("--time", args->times, "Output times to draw, s (the nearest output each); default: the last");
  cmd->add_option("--every", args->every, "Draw every Nth output (and the last)")->check(CLI::PositiveNumber);
  cmd->add_option("--color", args->color, "body, or a point field: temperature, pressure, plastic_strain, ...")
      ->capture_default_str();
  cmd->add_option("--size", args->size, "Picture size in pixels, W H")->expected(2)->capture_default_str();
  cmd->add_option("--out", args->out, "Folder for the pictures (default: RUN/pictures)");
  cmd->callback([args] { render(*args); });
}

}  // namespace kessler::app
