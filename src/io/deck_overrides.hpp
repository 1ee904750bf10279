#pragma once
// Command-line overrides of deck values ("--set solver.end_time=5 us"), applied to the YAML tree
// before it is parsed, so that a value set on the command line goes through every check a value in
// the deck does.
#include "io/yaml_reader.hpp"

#include <string>
#include <vector>

namespace kessler::io {

// Sets each "key.path=value" in `root` (a map), in order; a later override of the same key wins.
// Keys of maps may be new (the schema check then decides whether they are allowed there); indices
// into lists must exist. Records in `source` which subtree each override owns, so that errors in it
// are reported as coming from the command line.
void applyOverrides(YAML::Node root, const std::vector<std::string>& overrides, DeckSource& source);

}  // namespace kessler::io
