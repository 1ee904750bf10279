#pragma once
// The YAML deck (reference in docs/deck.md) parsed into a typed RunConfig.
// Every problem in a deck is a kessler::InputError with one line that says where and why:
//   deck.yaml:7:13: bodies[0].mesh_size: must be positive (got '-1 mm')
// Values set on the command line are reported as such:
//   command line (--set solver.endtime=5 us): solver.endtime: unknown key (allowed: ...)
#include "io/config.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace kessler::io {

// Reads and checks a deck. `overrides` are "key=value" settings from the command line: a dotted
// path into the YAML tree ("solver.end_time=5 us", "bodies.0.velocity=[0, 0, -200]",
// "output.dir=out2"; "bodies[0]" works as well as "bodies.0"), the value parsed as YAML. An override
// may add a key the deck leaves out, but only where the deck schema allows that key.
// Mesh files are resolved relative to the deck's folder.
RunConfig parseDeck(const std::filesystem::path& deck, const std::vector<std::string>& overrides = {});

// Same for a deck held in memory; `name_for_errors` starts every error message, and its folder (if
// it names one) is where relative mesh-file paths are resolved, as for a file of that name.
RunConfig parseDeckString(const std::string& yaml_text, const std::string& name_for_errors,
                          const std::vector<std::string>& overrides = {});

// Writes the fully resolved configuration (every default filled in, every value in SI units, mesh
// files as absolute paths) as YAML that parseDeck accepts again. Throws kessler::Error if the file
// cannot be written.
void writeResolvedDeck(const RunConfig& config, const std::filesystem::path& file);

// The same text as writeResolvedDeck writes.
std::string resolvedDeckText(const RunConfig& config);

// Rough estimate of the memory a run needs, in bytes: about 3 KiB per tetrahedron, with
// volume / (0.1 h^3) tetrahedra per body (h its mesh size, the refinement zone counted at its own
// size, only the part on the kept side of the symmetry planes). parseDeck refuses a deck whose
// estimate exceeds the machine's physical memory.
double estimateMemoryBytes(const RunConfig& config);

}  // namespace kessler::io
