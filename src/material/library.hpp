#pragma once
// The material library: named, published parameter sets, each constant with its source (the
// sets, their papers and their known problems are tabulated in docs/materials.md). A deck uses one
// as `{ library: NAME }` and may override any key.
#include "material/impact_material.hpp"

#include <string>
#include <vector>

namespace kessler::library {

struct Entry {
  std::string name;  // e.g. "Al6061-T6"
  std::string description;
  ImpactMaterialParameters parameters;
  std::vector<std::string> sources;  // one line per parameter group: what, value, where from
  std::string notes;                 // known problems with the published set and the choice made
};

// All entries, in a fixed order.
const std::vector<Entry>& entries();

// The entry of that name (case-insensitive); throws kessler::InputError listing the known
// names if there is none.
const Entry& find(const std::string& name);

}  // namespace kessler::library
