#pragma once
// The helper programs a run calls: the scripts of tools/plots (matplotlib with /usr/bin/python3,
// ParaView with pvpython and pvbatch) and how to find and call them.
#include <filesystem>
#include <optional>
#include <string>

namespace kessler::app {

// "kessler: warning: MESSAGE" on stderr: what the end of a run could not do, which never fails it.
void warn(const std::string& message);

// The tools/plots folder: $KESSLER_PLOTS_DIR, else the source tree's.
std::filesystem::path plotsDir();

// `text` single-quoted for the shell.
std::string shellQuoted(const std::string& text);

// Runs `command` with std::system, outside the MPI job this process may belong to: the launcher's
// variables (OMPI_*, PMIX_*, PMI_*, OPAL_*, PRTE_*, HYDRA_*, MPIR_*) are taken from its
// environment. A tool linked with MPI (ParaView's pvpython and pvbatch are) otherwise calls MPI_Init
// as a member of the job, aborts, and leaves the job's ranks waiting in MPI_Finalize: a 3-rank run
// hung so. Returns std::system's status.
int runOutsideMpi(const std::string& command);

// The program `name` in PATH, if there is one.
std::optional<std::filesystem::path> findProgram(const std::string& name);

// Writes dir/kessler.pvsm, a ParaView state that opens the run ready to look at (tools/plots/
// paraview_view.py with pvpython; log in dir/plots/paraview.log). Without pvpython it says so; a
// failure is a warning, never a failed run.
void writeParaViewState(const std::filesystem::path& dir);

}  // namespace kessler::app
