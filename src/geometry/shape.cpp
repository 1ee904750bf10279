#include "geometry/shape.hpp"

#include "core/error.hpp"
#include "core/overloaded.hpp"

#include <cmath>
#include <numbers>

namespace kessler::geometry {

namespace {

bool cylinderContains(const Cylinder& c, const Vec3& x, double margin) {
  const double height = c.axis.norm();
  if (height <= 0.0) return false;
  const Vec3 unit_axis = c.axis / height;
  const Vec3 d = x - c.base;
  const double along = d.dot(unit_axis);
  if (along <= margin || along >= height - margin) return false;
  const double radial = (d - along * unit_axis).norm();
  return radial < c.radius - margin;
}

}  // namespace

const char* kindName(const Shape& shape) {
  return std::visit(Overloaded{
                        [](const Sphere&) { return "sphere"; },
                        [](const Box&) { return "box"; },
                        [](const Cylinder&) { return "cylinder"; },
                        [](const MeshFile&) { return "mesh"; },
                    },
                    shape);
}

double volume(const Shape& shape) {
  return std::visit(
      Overloaded{
          [](const Sphere& s) { return 4.0 / 3.0 * std::numbers::pi * std::pow(s.radius, 3); },
          [](const Box& b) { return (b.max - b.min).prod(); },
          [](const Cylinder& c) { return std::numbers::pi * c.radius * c.radius * c.axis.norm(); },
          [](const MeshFile&) { return 0.0; },
      },
      shape);
}

BoundingBox bounds(const Shape& shape) {
  return std::visit(Overloaded{
                        [](const Sphere& s) {
                          const Vec3 r = Vec3::Constant(s.radius);
                          return BoundingBox{s.center - r, s.center + r};
                        },
                        [](const Box& b) {
                          return BoundingBox{b.min, b.max};
                        },
                        [](const Cylinder& c) {
                          // The end discs: a disc of radius r with unit normal n reaches
                          // r * sqrt(1 - n_i^2) beyond its centre along coordinate i.
                          const double height = c.axis.norm();
                          const Vec3 n = height > 0.0 ? Vec3(c.axis / height) : Vec3::Zero();
                          const Vec3 reach = c.radius * (1.0 - n.array().square()).max(0.0).sqrt();
                          const Vec3 top = c.base + c.axis;
                          return BoundingBox{c.base.cwiseMin(top) - reach, c.base.cwiseMax(top) + reach};
                        },
                        [](const MeshFile&) { return BoundingBox{}; },
                    },
                    shape);
}

bool contains(const Shape& shape, const Vec3& x, double margin) {
  return std::visit(Overloaded{
                        [&](const Sphere& s) { return (x - s.center).norm() < s.radius - margin; },
                        [&](const Box& b) {
                          return (x.array() > b.min.array() + margin).all() &&
                                 (x.array() < b.max.array() - margin).all();
                        },
                        [&](const Cylinder& c) { return cylinderContains(c, x, margin); },
                        [](const MeshFile&) { return false; },
                    },
                    shape);
}

double overlapVolume(const Shape& a, const Shape& b, int samples) {
  KESSLER_VERIFY(samples > 0, "overlapVolume needs a positive sample count, got {}", samples);
  if (std::holds_alternative<MeshFile>(a) || std::holds_alternative<MeshFile>(b)) return 0.0;
  const BoundingBox box_a = bounds(a);
  const BoundingBox box_b = bounds(b);
  const BoundingBox common{box_a.min.cwiseMax(box_b.min), box_a.max.cwiseMin(box_b.max)};
  if (common.empty()) return 0.0;

  const Vec3 cell = (common.max - common.min) / samples;
  long long inside = 0;
  for (int i = 0; i < samples; ++i) {
    for (int j = 0; j < samples; ++j) {
      for (int k = 0; k < samples; ++k) {
        const Vec3 x = common.min + Vec3(i + 0.5, j + 0.5, k + 0.5).cwiseProduct(cell);
        if (contains(a, x) && contains(b, x)) ++inside;
      }
    }
  }
  return static_cast<double>(inside) * cell.prod();
}

}  // namespace kessler::geometry
