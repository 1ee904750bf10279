#pragma once
// The pieces of the deck parser, shared between its source files (not part of the io interface).
#include "io/config.hpp"
#include "io/yaml_reader.hpp"

#include <filesystem>
#include <optional>
#include <vector>

namespace kessler::io {

// Parses the `materials` map: neo-Hookean solids and impact materials (library entries, overrides and
// explicit eos/strength/failure/thermal/viscosity blocks; docs/deck.md). Tabular EOS files are
// resolved relative to `base_dir`.
std::vector<MaterialConfig> parseMaterials(const Field& materials, const std::filesystem::path& base_dir);

// Parses the `bodies` list and checks each body on its own (shape, sizes, refinement zone, fixed
// faces, the part kept by the symmetry planes) and that names are unique. Mesh files are resolved
// relative to `base_dir`.
std::vector<BodyConfig> parseBodies(const Field& bodies, const std::vector<MaterialConfig>& materials,
                                    const std::vector<int>& symmetry_axes,
                                    const std::filesystem::path& base_dir);

// Volume of the part of an analytic shape on the kept (>= 0) side of the symmetry planes; 0 for a
// mesh file.
double keptVolume(const geometry::Shape& shape, const std::vector<int>& symmetry_axes);

// Whole-deck checks: no two bodies overlap (beyond 1e-3 of the smaller one's volume), and the
// run's memory estimate fits in this machine's physical memory. `bodies` is the deck's list.
void checkOverlaps(const std::vector<BodyConfig>& bodies, const Field& bodies_field);
void checkMemory(const RunConfig& config, const Field& bodies_field);

// Parses the optional `analysis` section, inferring what it leaves out from the bodies (the
// projectile: the bodies moving at least half as fast as the fastest; the plates: the box bodies
// ahead of it that its shot line crosses, in order). Analysis is off when nothing moves or no
// plate is found. `bodies_field` is the deck's list, for errors about inferred choices.
AnalysisConfig parseAnalysis(const std::optional<Field>& field, const std::vector<BodyConfig>& bodies,
                             const Field& bodies_field);

}  // namespace kessler::io
