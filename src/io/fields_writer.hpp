#pragma once
// Field output for ParaView: one HDF5 file per output time (dir/fields/fields_<step>.h5) and two
// XDMF time series that list every output written so far, dir/points.xdmf (material points) and
// dir/nodes.xdmf (nodes). Every file is replaced atomically, so a run killed mid-write leaves
// all earlier outputs readable and both XDMF files consistent with the HDF5 files on disk.
#include "io/xdmf.hpp"
#include "particles/store.hpp"
#include "solver/common/node_cloud.hpp"

#include <filesystem>
#include <vector>

namespace kessler::io {

class FieldWriter {
 public:
  // Creates `dir` and dir/fields/ if needed.
  explicit FieldWriter(std::filesystem::path dir);

  // Writes the owned points [0, points.owned) and nodes [0, nodes.owned) at `time` (s) and
  // rewrites both XDMF files. Writing a step already written replaces that output.
  void write(long step, double time, const NodeCloud& nodes, const PointStore& points);

  const std::filesystem::path& directory() const { return dir_; }

  // The outputs the XDMF files list, for a checkpoint; restoreSeries() takes them back after a
  // restart and rewrites both XDMF files, so that the series continues where the checkpoint was.
  const std::vector<XdmfGrid>& pointGrids() const { return point_grids_; }
  const std::vector<XdmfGrid>& nodeGrids() const { return node_grids_; }
  void restoreSeries(std::vector<XdmfGrid> point_grids, std::vector<XdmfGrid> node_grids);

 private:
  std::filesystem::path dir_;
  std::vector<XdmfGrid> point_grids_;
  std::vector<XdmfGrid> node_grids_;
};

}  // namespace kessler::io
