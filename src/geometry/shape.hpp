#pragma once
// Analytic shapes of bodies and an imported-mesh placeholder. All lengths in metres.
#include "core/types.hpp"

#include <string>
#include <variant>

namespace kessler::geometry {

struct Sphere {
  Vec3 center = Vec3::Zero();
  double radius = 0.0;
};

struct Box {
  Vec3 min = Vec3::Zero();
  Vec3 max = Vec3::Zero();
};

// A circular cylinder of any orientation: from `base` along `axis` (whose length is the
// cylinder's height).
struct Cylinder {
  Vec3 base = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  double radius = 0.0;
};

// A tetrahedral mesh in Gmsh .msh format, used as given (scaled by `scale` to metres).
struct MeshFile {
  std::string path;
  double scale = 1.0;
};

using Shape = std::variant<Sphere, Box, Cylinder, MeshFile>;

struct BoundingBox {
  Vec3 min = Vec3::Constant(0.0);
  Vec3 max = Vec3::Constant(0.0);
  bool empty() const { return (max.array() <= min.array()).any(); }
};

// Name of the shape kind ("sphere", "box", "cylinder", "mesh").
const char* kindName(const Shape& shape);

// Volume of an analytic shape; for a MeshFile, 0 (unknown before reading it).
double volume(const Shape& shape);

// Bounding box of an analytic shape; for a MeshFile an empty box.
BoundingBox bounds(const Shape& shape);

// True if x lies strictly inside an analytic shape by more than `margin`; always false for a
// MeshFile.
bool contains(const Shape& shape, const Vec3& x, double margin = 0.0);

// Volume common to two analytic shapes, estimated by sampling a grid of `samples`^3 points
// over the intersection of their bounding boxes (0 when either is a MeshFile).
double overlapVolume(const Shape& a, const Shape& b, int samples = 48);

}  // namespace kessler::geometry
