#pragma once
// What a run builds from its deck and keeps in its folder, shared by a new run and a restart.
#include "io/config.hpp"
#include "io/xdmf.hpp"
#include "material/material.hpp"

#include <filesystem>
#include <vector>

namespace kessler::app {

// One material per entry of config.materials, in that order.
std::vector<MaterialPtr> deckMaterials(const io::RunConfig& config);

// Removes the field files in dir/fields/ that `point_grids` does not name (outputs written after
// a checkpoint, or the extra output of a failed or stopped run) and stray temporaries, so that a
// restarted run folder holds exactly the outputs its XDMF series lists.
void removeOutputsOutside(const std::filesystem::path& dir, const std::vector<io::XdmfGrid>& point_grids);

}  // namespace kessler::app
