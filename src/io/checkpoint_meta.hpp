#pragma once
// The small, structured part of a checkpoint as JSON text (part of io/checkpoint.cpp): the method
// that wrote it, the bodies, the materials by name, and the outputs the XDMF series lists. Doubles are written so
// that they read back exactly.
#include "io/checkpoint.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace kessler::io {

std::string checkpointMetaText(const std::string& method, const ParticleState& model, const RunLoopState& loop);

// Fills model.bodies and model.materials (each checkpoint material found by name among
// `materials`) and loop.point_grids / loop.node_grids; returns the method that wrote it (format 5,
// which did not record it: otm). Throws kessler::Error naming `file`.
std::string readCheckpointMeta(const std::string& text, const std::filesystem::path& file,
                               const std::vector<MaterialPtr>& materials, ParticleState& model, RunLoopState& loop);

}  // namespace kessler::io
