#pragma once
// XDMF 3 descriptions of point clouds stored in HDF5 files, for ParaView and VisIt: a temporal
// collection with one Polyvertex grid (one vertex per point, attributes centred on the vertices)
// per output time. The XDMF file holds only metadata; the heavy data stays in the HDF5 files,
// referenced by paths relative to the XDMF file so that a run folder can be moved.
#include "core/types.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace kessler::io {

// One array in an HDF5 file as XDMF names it.
struct XdmfDataItem {
  std::vector<Index> dims;  // e.g. {n} for a scalar field, {n, 3} for a vector
  std::string number_type;  // "Float", "Int", "UInt", "UChar"
  int precision = 8;        // bytes per value
  std::string source;       // "relative/file.h5:/group/dataset"
};

struct XdmfAttribute {
  std::string name;
  std::string type;  // "Scalar" or "Vector"
  XdmfDataItem data;
};

// One output time of one point cloud.
struct XdmfGrid {
  std::string name;
  double time = 0.0;
  Index vertices = 0;
  XdmfDataItem geometry;  // {vertices, 3} positions
  std::vector<XdmfAttribute> attributes;
  // {vertices} indices 0..n-1: one vertex cell per point. ParaView's Xdmf3 readers make no cells
  // (so draw nothing) from a Polyvertex topology without them. Empty in outputs of runs written
  // before it existed (then the XDMF names none, as before).
  XdmfDataItem topology;
};

// The XDMF number type and precision of a C++ value type.
template <class T>
XdmfDataItem xdmfItem(std::vector<Index> dims, std::string source) {
  static_assert(std::is_arithmetic_v<T>);
  std::string number_type;
  if constexpr (std::is_floating_point_v<T>)
    number_type = "Float";
  else if constexpr (sizeof(T) == 1 && std::is_unsigned_v<T>)
    number_type = "UChar";
  else if constexpr (sizeof(T) == 1)
    number_type = "Char";
  else if constexpr (std::is_unsigned_v<T>)
    number_type = "UInt";
  else
    number_type = "Int";
  return {std::move(dims), std::move(number_type), static_cast<int>(sizeof(T)), std::move(source)};
}

// The whole XDMF document: a temporal collection named `name` holding `grids` in order.
std::string temporalPolyvertexXdmf(std::string_view name, const std::vector<XdmfGrid>& grids);

}  // namespace kessler::io
