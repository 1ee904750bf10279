#include "io/checkpoint_meta.hpp"

#include "core/error.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>

namespace kessler::io {
namespace {

using nlohmann::json;

json itemJson(const XdmfDataItem& item) {
  return {
      {"dims", item.dims}, {"number_type", item.number_type}, {"precision", item.precision}, {"source", item.source}};
}

XdmfDataItem itemFrom(const json& j) {
  return {j.at("dims").get<std::vector<Index>>(), j.at("number_type").get<std::string>(), j.at("precision").get<int>(),
          j.at("source").get<std::string>()};
}

json gridsJson(const std::vector<XdmfGrid>& grids) {
  json all = json::array();
  for (const XdmfGrid& g : grids) {
    json attributes = json::array();
    for (const XdmfAttribute& a : g.attributes)
      attributes.push_back({{"name", a.name}, {"type", a.type}, {"data", itemJson(a.data)}});
    all.push_back({{"name", g.name},
                   {"time", g.time},
                   {"vertices", g.vertices},
                   {"geometry", itemJson(g.geometry)},
                   {"topology", itemJson(g.topology)},
                   {"attributes", attributes}});
  }
  return all;
}

std::vector<XdmfGrid> gridsFrom(const json& all) {
  std::vector<XdmfGrid> grids;
  for (const json& j : all) {
    XdmfGrid g{.name = j.at("name").get<std::string>(),
               .time = j.at("time").get<double>(),
               .vertices = j.at("vertices").get<Index>(),
               .geometry = itemFrom(j.at("geometry")),
               .attributes = {},
               // (absent in checkpoints written before the outputs named their vertex cells)
               .topology = j.contains("topology") ? itemFrom(j.at("topology")) : XdmfDataItem{}};
    for (const json& a : j.at("attributes"))
      g.attributes.push_back(
          {a.at("name").get<std::string>(), a.at("type").get<std::string>(), itemFrom(a.at("data"))});
    grids.push_back(std::move(g));
  }
  return grids;
}

}  // namespace

std::string checkpointMetaText(const std::string& method, const ParticleState& model, const RunLoopState& loop) {
  json bodies = json::array();
  for (const BodyInfo& b : model.bodies)
    bodies.push_back({{"name", b.name}, {"material", b.material}, {"touched", b.touched}});
  json materials = json::array();
  for (const MaterialPtr& m : model.materials) materials.push_back(m->name());
  const json meta = {{"method", method},
                     {"bodies", bodies},
                     {"materials", materials},
                     {"point_grids", gridsJson(loop.point_grids)},
                     {"node_grids", gridsJson(loop.node_grids)}};
  return meta.dump();
}

std::string readCheckpointMeta(const std::string& text, const std::filesystem::path& file,
                               const std::vector<MaterialPtr>& materials, ParticleState& model, RunLoopState& loop) {
  json meta;
  try {
    meta = json::parse(text);
    for (const json& name : meta.at("materials")) {
      const std::string wanted = name.get<std::string>();
      auto found =
          std::find_if(materials.begin(), materials.end(), [&](const MaterialPtr& m) { return m->name() == wanted; });
      if (found == materials.end())
        throw Error(fmt::format("checkpoint '{}': material '{}' is not in the run's deck", file.string(), wanted));
      model.materials.push_back(*found);
    }
    for (const json& b : meta.at("bodies")) {
      BodyInfo body{b.at("name").get<std::string>(), b.at("material").get<int>(), b.at("touched").get<std::uint64_t>()};
      if (body.material < 0 || static_cast<std::size_t>(body.material) >= model.materials.size())
        throw Error(fmt::format("checkpoint '{}': body '{}' names no stored material", file.string(), body.name));
      model.bodies.push_back(std::move(body));
    }
    loop.point_grids = gridsFrom(meta.at("point_grids"));
    loop.node_grids = gridsFrom(meta.at("node_grids"));
    return meta.contains("method") ? meta.at("method").get<std::string>() : std::string("otm");
  } catch (const json::exception& e) {
    throw Error(fmt::format("checkpoint '{}': damaged description of the run: {}", file.string(), e.what()));
  }
}

}  // namespace kessler::io
