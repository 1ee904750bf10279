#include "io/xdmf.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <iterator>

namespace kessler::io {
namespace {

void appendDataItem(std::string& out, const XdmfDataItem& item, int indent) {
  fmt::format_to(std::back_inserter(out),
                 "{:{}}<DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"{}\" Format=\"HDF\">{}</DataItem>\n",
                 "", indent, fmt::join(item.dims, " "), item.number_type, item.precision, item.source);
}

void appendGrid(std::string& out, const XdmfGrid& grid) {
  auto line = std::back_inserter(out);
  fmt::format_to(line, "      <Grid Name=\"{}\" GridType=\"Uniform\">\n", grid.name);
  // The shortest representation that reads back to the same double.
  fmt::format_to(line, "        <Time Value=\"{}\"/>\n", grid.time);
  fmt::format_to(line,
                 "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"{}\" NodesPerElement=\"1\"{}>\n",
                 grid.vertices, grid.topology.source.empty() ? "/" : "");
  if (!grid.topology.source.empty()) {
    appendDataItem(out, grid.topology, 10);
    out += "        </Topology>\n";
  }
  out += "        <Geometry GeometryType=\"XYZ\">\n";
  appendDataItem(out, grid.geometry, 10);
  out += "        </Geometry>\n";
  for (const XdmfAttribute& attribute : grid.attributes) {
    fmt::format_to(line, "        <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"Node\">\n", attribute.name,
                   attribute.type);
    appendDataItem(out, attribute.data, 10);
    out += "        </Attribute>\n";
  }
  out += "      </Grid>\n";
}

}  // namespace

std::string temporalPolyvertexXdmf(std::string_view name, const std::vector<XdmfGrid>& grids) {
  std::string out = "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n  <Domain>\n";
  fmt::format_to(std::back_inserter(out),
                 "    <Grid Name=\"{}\" GridType=\"Collection\" CollectionType=\"Temporal\">\n", name);
  for (const XdmfGrid& grid : grids) appendGrid(out, grid);
  out += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return out;
}

}  // namespace kessler::io
