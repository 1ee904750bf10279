#include "app/scripts.hpp"

#include "core/log.hpp"

#include <fmt/format.h>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace kessler::app {

namespace fs = std::filesystem;

void warn(const std::string& message) {
  fmt::print(stderr, "kessler: warning: {}\n", message);
  std::fflush(stderr);
}

fs::path plotsDir() {
  if (const char* env = std::getenv("KESSLER_PLOTS_DIR"); env != nullptr && *env != '\0') return env;
  return KESSLER_SOURCE_PLOTS_DIR;
}

std::string shellQuoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::optional<fs::path> findProgram(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::istringstream folders(path != nullptr ? path : "/usr/bin:/bin");
  std::error_code error;
  for (std::string folder; std::getline(folders, folder, ':');) {
    if (folder.empty()) continue;
    const fs::path candidate = fs::path(folder) / name;
    if (fs::is_regular_file(candidate, error) &&
        (fs::status(candidate, error).permissions() & fs::perms::owner_exec) != fs::perms::none)
      return candidate;
  }
  return std::nullopt;
}

int runOutsideMpi(const std::string& command) {
  static constexpr const char* prefixes[] = {"OMPI_", "PMIX_", "PMI_", "OPAL_", "PRTE_", "HYDRA_", "MPIR_"};
  std::string unset;
  for (char** e = environ; e != nullptr && *e != nullptr; ++e) {
    const std::string entry = *e;
    const std::string name = entry.substr(0, entry.find('='));
    for (const char* prefix : prefixes)
      if (name.rfind(prefix, 0) == 0) {
        unset += " -u " + shellQuoted(name);
        break;
      }
  }
  if (unset.empty()) return std::system(command.c_str());
  return std::system(fmt::format("env{} /bin/sh -c {}", unset, shellQuoted(command)).c_str());
}

void writeParaViewState(const fs::path& dir) {
  const std::optional<fs::path> pvpython = findProgram("pvpython");
  if (!pvpython) {
    log::info("no ParaView state (kessler.pvsm): pvpython not found (Debian: apt-get install paraview)");
    return;
  }
  std::error_code error;
  fs::create_directories(dir / "plots", error);
  const fs::path log_file = dir / "plots" / "paraview.log";
  const std::string command = fmt::format("{} {} state {} >>{} 2>&1", shellQuoted(pvpython->string()),
                                          shellQuoted((plotsDir() / "paraview_view.py").string()),
                                          shellQuoted(dir.string()), shellQuoted(log_file.string()));
  if (runOutsideMpi(command) != 0) {
    warn(fmt::format("the ParaView state was not written (see {})", log_file.string()));
    return;
  }
  log::info("ParaView: File > Load State > {}", (dir / "kessler.pvsm").string());
}

}  // namespace kessler::app
