#include "io/deck_parts.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <optional>

namespace kessler::io {

namespace {

namespace fs = std::filesystem;

constexpr const char* axis_names[] = {"x", "y", "z"};

// The reference density of a material: a projectile may be given by its mass.
double materialDensity(const MaterialConfig& material) {
  return material.model == "impact" ? eos::referenceDensity(material.impact.eos) : material.neo_hookean.density;
}

// Exactly one of `size_key` and "mass" (the whole projectile's mass, even in a half model).
std::optional<double> massInstead(const MapField& map, std::string_view size_key) {
  std::optional<Field> mass = map.find("mass");
  if (!mass) return std::nullopt;
  if (std::optional<Field> size = map.find(size_key))
    size->failBare(fmt::format("give either {} or mass, not both", size_key));
  return mass->positive(units::mass);
}

geometry::Sphere parseSphere(const Field& field, double density) {
  MapField map = field.map({"center", "radius", "mass"});
  geometry::Sphere sphere{.center = map.require("center").vector(units::length)};
  if (std::optional<double> mass = massInstead(map, "radius"))
    sphere.radius = std::cbrt(3.0 * *mass / (4.0 * std::numbers::pi * density));
  else
    sphere.radius = map.require("radius").positive(units::length);
  return sphere;
}

geometry::Box parseBox(const Field& field) {
  MapField map = field.map({"min", "max"});
  geometry::Box box{.min = map.require("min").vector(units::length),
                    .max = map.require("max").vector(units::length)};
  for (int d = 0; d < 3; ++d)
    if (!(box.max[d] > box.min[d]))
      map.require("max").fail(
          fmt::format("must exceed min in every direction, but along {} max = {:.4g} m <= min = {:.4g} m",
                      axis_names[d], box.max[d], box.min[d]));
  return box;
}

// With `mass`, `axis` gives the direction only and the height follows from the mass.
geometry::Cylinder parseCylinder(const Field& field, double density) {
  MapField map = field.map({"base", "axis", "radius", "mass"});
  Field axis = map.require("axis");
  geometry::Cylinder cylinder{.base = map.require("base").vector(units::length),
                              .axis = axis.vector(units::length),
                              .radius = map.require("radius").positive(units::length)};
  if (!(cylinder.axis.norm() > 0.0)) axis.fail("must not be zero: its length is the cylinder's height");
  if (std::optional<Field> mass = map.find("mass")) {
    const double height =
        mass->positive(units::mass) / (density * std::numbers::pi * cylinder.radius * cylinder.radius);
    cylinder.axis = cylinder.axis.normalized() * height;
  }
  return cylinder;
}

geometry::MeshFile parseMeshFile(const Field& field, const fs::path& base_dir) {
  MapField map = field.map({"file", "scale"});
  Field file = map.require("file");
  const fs::path resolved = fs::absolute(base_dir / file.text("a file path")).lexically_normal();
  std::error_code error;
  if (!fs::is_regular_file(resolved, error))
    file.fail(fmt::format("no such mesh file (looked for '{}')", resolved.string()));
  if (!std::ifstream(resolved)) file.fail(fmt::format("cannot read the mesh file '{}'", resolved.string()));
  geometry::MeshFile mesh{.path = resolved.string(), .scale = 1.0};
  // A length: "scale: 1 mm" reads as "one mesh unit is a millimetre"; a bare number is the factor.
  if (std::optional<Field> scale = map.find("scale")) mesh.scale = scale->positive(units::length);
  return mesh;
}

geometry::Shape parseShape(const Field& field, const fs::path& base_dir, double density) {
  MapField map = field.map({"sphere", "box", "cylinder", "mesh"});
  if (map.entries().size() != 1) field.fail("must hold exactly one of sphere, box, cylinder, mesh");
  const MapField::Entry& entry = map.entries().front();
  if (entry.key == "sphere") return parseSphere(entry.value, density);
  if (entry.key == "box") return parseBox(entry.value);
  if (entry.key == "cylinder") return parseCylinder(entry.value, density);
  return parseMeshFile(entry.value, base_dir);
}

geometry::Refinement parseRefinement(const Field& field, double mesh_size) {
  MapField map = field.map({"center", "radius", "size"});
  Field size = map.require("size");
  geometry::Refinement refine{.center = map.require("center").vector(units::length),
                              .radius = map.require("radius").positive(units::length),
                              .size = size.positive(units::length)};
  if (refine.size > mesh_size)
    size.fail(fmt::format("must not exceed the body's mesh_size ({:.4g} m): a refinement zone is finer",
                          mesh_size));
  return refine;
}

geometry::FixedNodes parseFixed(const Field& field, const geometry::Shape& shape) {
  const std::string which = field.text();
  if (which == "none") return geometry::FixedNodes::none;
  if (which != "lateral-faces") field.fail("must be none or lateral-faces");
  if (!std::holds_alternative<geometry::Box>(shape) && !std::holds_alternative<geometry::Cylinder>(shape))
    field.fail(
        fmt::format("lateral-faces applies to a box or a cylinder, not to a {}", geometry::kindName(shape)));
  return geometry::FixedNodes::lateral_faces;
}

double distanceToBox(const Vec3& x, const geometry::BoundingBox& box) {
  return (x.cwiseMax(box.min).cwiseMin(box.max) - x).norm();
}

// The thinnest dimension of an analytic shape: a box's smallest side, a cylinder's height or
// diameter, a sphere's diameter.
double smallestDimension(const geometry::Shape& shape) {
  if (const auto* box = std::get_if<geometry::Box>(&shape)) return (box->max - box->min).minCoeff();
  if (const auto* cylinder = std::get_if<geometry::Cylinder>(&shape))
    return std::min(cylinder->axis.norm(), 2.0 * cylinder->radius);
  if (const auto* sphere = std::get_if<geometry::Sphere>(&shape)) return 2.0 * sphere->radius;
  return 0.0;
}

// Checks of one body that need several of its keys together.
void checkBody(const BodyConfig& body, const MapField& map, const std::vector<int>& symmetry_axes) {
  const geometry::Shape& shape = body.mesh.shape;
  if (std::holds_alternative<geometry::MeshFile>(shape)) {
    if (body.mesh.refine)
      map.require("refine").failBare("does not apply to a mesh file, which is used as given");
    return;
  }
  const Field shape_field = map.require("shape");
  const geometry::BoundingBox box = geometry::bounds(shape);
  if (!(geometry::volume(shape) > 0.0)) shape_field.fail("has no volume");
  for (int axis : symmetry_axes)
    if (box.max[axis] <= 0.0)
      shape_field.fail(fmt::format(
          "lies wholly on the cut-away side of the symmetry plane {} = 0, so nothing of it is kept",
          axis_names[axis]));
  const double largest = (box.max - box.min).maxCoeff();
  if (body.mesh.mesh_size > largest)
    map.require("mesh_size")
        .fail(fmt::format("is larger than the body, whose largest dimension is {:.4g} m", largest));
  // A plate thinner than one mesh cell has no material point inside its thickness: it cannot bend,
  // and the hole and spall measurements have nothing to resolve.
  const double thinnest = smallestDimension(shape);
  if (body.mesh.mesh_size > thinnest * (1.0 + 1e-9))  // a plate meshed at exactly its thickness passes
    map.require("mesh_size")
        .fail(fmt::format("is larger than the body's thinnest dimension ({:.4g} m): the {} would be less than "
                          "one mesh cell thick; use a mesh_size of at most {:.4g} m",
                          thinnest, geometry::kindName(shape), thinnest));
  if (body.mesh.refine && distanceToBox(body.mesh.refine->center, box) > body.mesh.refine->radius)
    map.require("refine").fail("the refinement zone does not reach the body");
}

BodyConfig parseBody(const Field& field, const std::vector<MaterialConfig>& materials,
                     const std::vector<int>& symmetry_axes, const fs::path& base_dir,
                     const std::vector<BodyConfig>& earlier) {
  MapField map = field.map({"name", "material", "shape", "velocity", "mesh_size", "refine", "fixed"});
  BodyConfig body;
  const Field name = map.require("name");
  body.name = name.text();
  for (std::size_t j = 0; j < earlier.size(); ++j)
    if (earlier[j].name == body.name) name.fail(fmt::format("duplicate body name (also bodies[{}])", j));

  const Field material = map.require("material");
  const std::string material_name = material.text();
  auto found = std::find_if(materials.begin(), materials.end(),
                            [&](const MaterialConfig& m) { return m.name == material_name; });
  if (found == materials.end()) {
    std::vector<std::string> known;
    for (const MaterialConfig& m : materials) known.push_back(m.name);
    material.fail(fmt::format("unknown material (defined: {})", fmt::join(known, ", ")));
  }
  body.material = static_cast<int>(found - materials.begin());

  body.mesh.shape = parseShape(map.require("shape"), base_dir, materialDensity(*found));
  body.mesh.symmetry_axes = symmetry_axes;
  body.mesh.mesh_size = map.require("mesh_size").positive(units::length);
  if (std::optional<Field> refine = map.find("refine"))
    body.mesh.refine = parseRefinement(*refine, body.mesh.mesh_size);
  if (std::optional<Field> velocity = map.find("velocity")) body.velocity = velocity->vector(units::velocity);
  if (std::optional<Field> fixed = map.find("fixed")) body.fixed = parseFixed(*fixed, body.mesh.shape);
  checkBody(body, map, symmetry_axes);
  return body;
}

}  // namespace

std::vector<BodyConfig> parseBodies(const Field& bodies, const std::vector<MaterialConfig>& materials,
                                    const std::vector<int>& symmetry_axes, const fs::path& base_dir) {
  std::vector<Field> items = bodies.list();
  if (items.empty()) bodies.fail("must list at least one body");
  std::vector<BodyConfig> result;
  for (const Field& item : items)
    result.push_back(parseBody(item, materials, symmetry_axes, base_dir, result));
  return result;
}

}  // namespace kessler::io
