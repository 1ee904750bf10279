#include "app/run_folder.hpp"

#include "core/log.hpp"
#include "material/impact_material.hpp"
#include "material/neo_hookean.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <system_error>

namespace kessler::app {

std::vector<MaterialPtr> deckMaterials(const io::RunConfig& config) {
  std::vector<MaterialPtr> materials;
  for (const io::MaterialConfig& m : config.materials) {
    if (m.model == "impact")
      materials.push_back(std::make_shared<ImpactMaterial>(m.name, m.impact));
    else
      materials.push_back(std::make_shared<NeoHookean>(m.name, m.neo_hookean));
  }
  return materials;
}

void removeOutputsOutside(const std::filesystem::path& dir, const std::vector<io::XdmfGrid>& point_grids) {
  std::set<std::string> listed;
  for (const io::XdmfGrid& grid : point_grids) {
    const std::string& source = grid.geometry.source;  // "fields/fields_<step>.h5:/points/position"
    listed.insert(std::filesystem::path(source.substr(0, source.find(':'))).filename().string());
  }
  std::error_code error;
  std::vector<std::filesystem::path> stale;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "fields", error)) {
    const std::string name = entry.path().filename().string();
    const bool ours = name.starts_with("fields_") && (name.ends_with(".h5") || name.ends_with(".h5.tmp"));
    if (ours && !listed.contains(name)) stale.push_back(entry.path());
  }
  std::sort(stale.begin(), stale.end());
  for (const std::filesystem::path& file : stale) {
    std::filesystem::remove(file, error);
    log::info("removed {}: written after the checkpoint, it is recomputed", file.string());
  }
}

}  // namespace kessler::app
