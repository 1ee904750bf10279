#include "io/atomic_file.hpp"
#include "io/deck.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

namespace kessler::io {

namespace {

// The shortest text that reads back as exactly the same double.
std::string number(double value) { return fmt::format("{}", value); }

void vector(YAML::Emitter& out, const char* key, const Vec3& v, const char* unit) {
  out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq << number(v[0]) << number(v[1])
      << number(v[2]) << YAML::EndSeq << YAML::Comment(unit);
}

void scalar(YAML::Emitter& out, const char* key, double value, const char* unit) {
  out << YAML::Key << key << YAML::Value << number(value);
  if (*unit != '\0') out << YAML::Comment(unit);
}

void shape(YAML::Emitter& out, const geometry::Shape& shape) {
  out << YAML::Key << "shape" << YAML::Value << YAML::BeginMap << YAML::Key << geometry::kindName(shape)
      << YAML::Value << YAML::BeginMap;
  if (const auto* sphere = std::get_if<geometry::Sphere>(&shape)) {
    vector(out, "center", sphere->center, "m");
    scalar(out, "radius", sphere->radius, "m");
  } else if (const auto* box = std::get_if<geometry::Box>(&shape)) {
    vector(out, "min", box->min, "m");
    vector(out, "max", box->max, "m");
  } else if (const auto* cylinder = std::get_if<geometry::Cylinder>(&shape)) {
    vector(out, "base", cylinder->base, "m");
    vector(out, "axis", cylinder->axis, "m");
    scalar(out, "radius", cylinder->radius, "m");
  } else if (const auto* file = std::get_if<geometry::MeshFile>(&shape)) {
    out << YAML::Key << "file" << YAML::Value << file->path;
    scalar(out, "scale", file->scale, "m per mesh unit");
  }
  out << YAML::EndMap << YAML::EndMap;
}

void body(YAML::Emitter& out, const BodyConfig& body, const RunConfig& config) {
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << body.name;
  out << YAML::Key << "material" << YAML::Value
      << config.materials.at(static_cast<std::size_t>(body.material)).name;
  shape(out, body.mesh.shape);
  vector(out, "velocity", body.velocity, "m/s");
  scalar(out, "mesh_size", body.mesh.mesh_size, "m");
  if (const auto& refine = body.mesh.refine) {
    out << YAML::Key << "refine" << YAML::Value << YAML::BeginMap;
    vector(out, "center", refine->center, "m");
    scalar(out, "radius", refine->radius, "m");
    scalar(out, "size", refine->size, "m");
    out << YAML::EndMap;
  }
  out << YAML::Key << "fixed" << YAML::Value
      << (body.fixed == geometry::FixedNodes::lateral_faces ? "lateral-faces" : "none");
  out << YAML::EndMap;
}

}  // namespace

std::string resolvedDeckText(const RunConfig& config) {
  YAML::Emitter out;
  out << YAML::Comment("Resolved deck: every default filled in, every value in SI units.");
  out << YAML::BeginMap;
  if (!config.title.empty()) out << YAML::Key << "title" << YAML::Value << config.title;

  out << YAML::Key << "materials" << YAML::Value << YAML::BeginMap;
  for (const MaterialConfig& material : config.materials) {
    out << YAML::Key << material.name << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "model" << YAML::Value << material.model;
    scalar(out, "density", material.neo_hookean.density, "kg/m^3");
    scalar(out, "youngs_modulus", material.neo_hookean.youngs_modulus, "Pa");
    scalar(out, "poisson_ratio", material.neo_hookean.poisson_ratio, "");
    out << YAML::EndMap;
  }
  out << YAML::EndMap;

  out << YAML::Key << "bodies" << YAML::Value << YAML::BeginSeq;
  for (const BodyConfig& b : config.bodies) body(out, b, config);
  out << YAML::EndSeq;

  out << YAML::Key << "symmetry" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (int axis : config.symmetry_axes) out << (axis == 0 ? "x" : axis == 1 ? "y" : "z");
  out << YAML::EndSeq;

  const otm::Settings& s = config.solver;
  out << YAML::Key << "solver" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "method" << YAML::Value << "otm";
  scalar(out, "end_time", s.end_time, "s");
  scalar(out, "cfl", s.cfl, "");
  scalar(out, "lme_gamma", s.lme_gamma, "");
  scalar(out, "lme_tolerance", s.lme_tolerance, "");
  out << YAML::Key << "min_neighbours" << YAML::Value << s.min_neighbours;
  out << YAML::Key << "max_steps" << YAML::Value << s.max_steps << YAML::Comment("0: no limit");
  scalar(out, "contact_distance", s.contact_distance, "times the point spacing");
  out << YAML::EndMap;

  out << YAML::Key << "output" << YAML::Value << YAML::BeginMap;
  scalar(out, "every", config.output.every, "s");
  out << YAML::Key << "dir" << YAML::Value << config.output.dir;
  out << YAML::EndMap;

  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

void writeResolvedDeck(const RunConfig& config, const std::filesystem::path& file) {
  writeTextAtomically(file, resolvedDeckText(config));
}

}  // namespace kessler::io
