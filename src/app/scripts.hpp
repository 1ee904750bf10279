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

// The program `name` in PATH, if there is one.
std::optional<std::filesystem::path> findProgram(const std::string& name);

// Writes dir/kessler.pvsm, a ParaView state that opens the run ready to look at (tools/plots/
// paraview_view.py with pvpython; log in dir/plots/paraview.log). Without pvpython it says so; a
// failure is a warning, never a failed run.
void writeParaViewState(const std::filesystem::path& dir);

}  // namespace kessler::app
