#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/deck.hpp"
#include "io/material_keys.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <concepts>
#include <string>

namespace kessler::io {

namespace {

// The shortest text that reads back as exactly the same double.
std::string number(double value) {
  return fmt::format("{}", value);
}

void vector(YAML::Emitter& out, const char* key, const Vec3& v, const char* unit) {
  out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq << number(v[0]) << number(v[1]) << number(v[2])
      << YAML::EndSeq << YAML::Comment(unit);
}

void scalar(YAML::Emitter& out, const char* key, double value, const char* unit) {
  out << YAML::Key << key << YAML::Value << number(value);
  if (*unit != '\0') out << YAML::Comment(unit);
}

void shape(YAML::Emitter& out, const geometry::Shape& shape) {
  out << YAML::Key << "shape" << YAML::Value << YAML::BeginMap << YAML::Key << geometry::kindName(shape) << YAML::Value
      << YAML::BeginMap;
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

template <typename P, std::size_t N>
void block(YAML::Emitter& out, const char* name, const char* model, const P& p,
           const material_keys::Key<P> (&table)[N]) {
  out << YAML::Key << name << YAML::Value << YAML::BeginMap;
  if (model != nullptr) out << YAML::Key << "model" << YAML::Value << model;
  for (const material_keys::Key<P>& key : table) scalar(out, key.name, p.*(key.member), key.unit);
  out << YAML::EndMap;
}

// A tabular EOS is written as the file (absolute, as the parser resolved it) and material it came from.
void tabularEos(YAML::Emitter& out, const eos::Tabular& table) {
  out << YAML::Key << "eos" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "model" << YAML::Value << "tabular";
  out << YAML::Key << "file" << YAML::Value << table.parameters().file;
  out << YAML::Key << "material_id" << YAML::Value << table.parameters().material_id;
  out << YAML::EndMap;
}

void impactMaterial(YAML::Emitter& out, const MaterialConfig& material) {
  namespace keys = material_keys;
  const ImpactMaterialParameters& p = material.impact;
  out << YAML::Key << "model" << YAML::Value << "impact";
  if (!material.library.empty())
    out << YAML::Comment(fmt::format("library entry {}, every parameter written out", material.library));
  scalar(out, "density", eos::referenceDensity(p.eos), "kg/m^3");
  scalar(out, "shear_modulus", p.shear_modulus, "Pa");

  const char* eos_model = keys::eos_models[p.eos.index()];
  if (const auto* mg = std::get_if<eos::MieGruneisen>(&p.eos))
    block(out, "eos", eos_model, mg->parameters(), keys::mie_gruneisen);
  else if (const auto* polynomial = std::get_if<eos::Polynomial>(&p.eos))
    block(out, "eos", eos_model, polynomial->parameters(), keys::polynomial);
  else if (const auto* tillotson = std::get_if<eos::Tillotson>(&p.eos))
    block(out, "eos", eos_model, tillotson->parameters(), keys::tillotson);
  else if (const auto* gas = std::get_if<eos::IdealGas>(&p.eos))
    block(out, "eos", eos_model, gas->parameters(), keys::ideal_gas);
  else
    tabularEos(out, std::get<eos::Tabular>(p.eos));

  const char* strength_model = keys::strength_models[p.yield.index()];
  if (const auto* linear = std::get_if<strength::LinearHardening>(&p.yield))
    block(out, "strength", strength_model, linear->parameters(), keys::linear_hardening);
  else if (const auto* power_law = std::get_if<strength::PowerLaw>(&p.yield))
    block(out, "strength", strength_model, power_law->parameters(), keys::power_law);
  else if (const auto* johnson_cook = std::get_if<strength::JohnsonCook>(&p.yield))
    block(out, "strength", strength_model, johnson_cook->parameters(), keys::johnson_cook);
  else
    out << YAML::Key << "strength" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "model" << YAML::Value
        << strength_model << YAML::EndMap;

  if (p.damage)
    block(out, "failure", "johnson-cook", *p.damage, keys::johnson_cook_damage);
  else
    out << YAML::Key << "failure" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "model" << YAML::Value
        << "none" << YAML::EndMap;
  block(out, "thermal", nullptr, p.thermal, keys::thermal);
  // No tension cut-off is the default, and infinity has no deck spelling.
  if (std::isfinite(p.pressure_floor)) scalar(out, "tension_cutoff", p.pressure_floor, "Pa");
  scalar(out, "spall_strength", p.spall_strength, "Pa; 0: no spall");
  block(out, "viscosity", nullptr, p.viscosity, keys::viscosity);
  scalar(out, "fracture_energy", p.fracture_energy, "J/m^2; 0: no eigenerosion");
  // All plastic work is the default, and -infinity has no deck spelling.
  if (std::isfinite(p.fracture_min_triaxiality))
    scalar(out, "fracture_min_triaxiality", p.fracture_min_triaxiality, "plastic work below it does not erode");
}

void body(YAML::Emitter& out, const BodyConfig& body, const RunConfig& config) {
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << body.name;
  out << YAML::Key << "material" << YAML::Value << config.materials.at(static_cast<std::size_t>(body.material)).name;
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

void analysis(YAML::Emitter& out, const RunConfig& config) {
  const AnalysisConfig& a = config.analysis;
  out << YAML::Key << "analysis" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "enabled" << YAML::Value << (a.enabled ? "true" : "false");
  if (a.enabled) {
    auto names = [&](const char* key, const std::vector<int>& bodies) {
      out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
      for (int b : bodies) out << config.bodies.at(static_cast<std::size_t>(b)).name;
      out << YAML::EndSeq;
    };
    names("projectile", a.projectiles);
    vector(out, "shot_direction", a.shot_direction, "unit vector");
    if (!a.plates.empty()) {  // none: a collision, inferred again on reading
      names("plates", a.plates);
      out << YAML::Key << "cloud_reference" << YAML::Value
          << config.bodies.at(static_cast<std::size_t>(a.plates.at(static_cast<std::size_t>(a.cloud_reference)))).name;
    }
  }
  scalar(out, "link_stretch", a.link_stretch, "");
  out << YAML::Key << "plots" << YAML::Value << (a.plots ? "true" : "false");
  // Only when the deck gave it: left out, the analysis knows the values are its Al 6061-T6 defaults.
  if (a.wall_given) {
    out << YAML::Key << "rear_wall" << YAML::Value << YAML::BeginMap;
    scalar(out, "yield_stress", a.wall_yield_stress, "Pa");
    scalar(out, "brinell_hardness", a.wall_brinell_hardness, "");
    scalar(out, "sound_speed", a.wall_sound_speed, "m/s");
    out << YAML::EndMap;
  }
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
    if (material.model == "impact") {
      impactMaterial(out, material);
    } else {
      out << YAML::Key << "model" << YAML::Value << material.model;
      scalar(out, "density", material.neo_hookean.density, "kg/m^3");
      scalar(out, "youngs_modulus", material.neo_hookean.youngs_modulus, "Pa");
      scalar(out, "poisson_ratio", material.neo_hookean.poisson_ratio, "");
      scalar(out, "fracture_energy", material.neo_hookean.fracture_energy, "J/m^2; 0: no eigenerosion");
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;

  out << YAML::Key << "bodies" << YAML::Value << YAML::BeginSeq;
  for (const BodyConfig& b : config.bodies) body(out, b, config);
  out << YAML::EndSeq;

  out << YAML::Key << "symmetry" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (int axis : config.symmetry_axes) out << (axis == 0 ? "x" : axis == 1 ? "y" : "z");
  out << YAML::EndSeq;

  const SolverSettings& s = config.solver;
  out << YAML::Key << "solver" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "method" << YAML::Value << config.method;
  scalar(out, "end_time", s.end_time, "s");
  scalar(out, "cfl", s.cfl, "");
  out << YAML::Key << "max_steps" << YAML::Value << s.max_steps << YAML::Comment("0: no limit");
  out << YAML::Key << "debris_contact" << YAML::Value << (s.debris_contact ? "true" : "false");
  out << YAML::Key << "contact" << YAML::Value << YAML::BeginMap;
  const bool sliding = s.contact.sliding();
  out << YAML::Key << "type" << YAML::Value << (sliding ? "sliding" : "seizing");
  if (sliding) scalar(out, "friction", s.contact.friction, "Coulomb");
  out << YAML::EndMap;
  scalar(out, "min_dt_fraction", s.min_dt_fraction, "of the initial time step; 0: no check");
  scalar(out, "max_energy_growth", s.max_energy_growth, "relative to the initial total energy");
  const OtmOptions& o = config.otm;
  out << YAML::Key << "otm" << YAML::Value << YAML::BeginMap;
  scalar(out, "lme_gamma", o.lme_gamma, "");
  scalar(out, "lme_tolerance", o.lme_tolerance, "");
  out << YAML::Key << "min_neighbours" << YAML::Value << o.min_neighbours;
  scalar(out, "contact_distance", o.contact_distance, "times the point spacing");
  out << YAML::Key << "crack_visibility" << YAML::Value << (o.crack_visibility ? "true" : "false");
  out << YAML::Key << "volume_averaging" << YAML::Value << (o.volume_averaging ? "true" : "false");
  out << YAML::EndMap;
  out << YAML::EndMap;

  out << YAML::Key << "output" << YAML::Value << YAML::BeginMap;
  scalar(out, "every", config.output.every, "s");
  out << YAML::Key << "dir" << YAML::Value << config.output.dir;
  out << YAML::EndMap;

  out << YAML::Key << "checkpoint" << YAML::Value << YAML::BeginMap;
  scalar(out, "every", config.checkpoint.every, "s of simulated time; 0: never");
  scalar(out, "wall_interval", config.checkpoint.wall_interval, "s of wall time; 0: never");
  out << YAML::EndMap;

  analysis(out, config);

  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

void writeResolvedDeck(const RunConfig& config, const std::filesystem::path& file) {
  writeTextAtomically(file, resolvedDeckText(config));
}

}  // namespace kessler::io
