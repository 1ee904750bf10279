#include "solver/rkpm/rkpm_method.hpp"

#include "solver/common/particle_bodies.hpp"
#include "solver/rkpm/setup.hpp"

#include <fmt/format.h>

namespace kessler::rkpm {

Settings settingsFor(const Problem& problem) {
  return Settings{problem.settings.solver, problem.settings.rkpm, problem.walls, mirrorBox(problem)};
}

RkpmMethod::RkpmMethod(Model model, const Settings& settings)
    : model_(std::move(model)), integrator_(model_, settings), diagnostics_(settings.solver) {}

RkpmMethod::RkpmMethod(Model model, const Problem& problem) : RkpmMethod(std::move(model), settingsFor(problem)) {
  for (const PlaneConstraint& plane : problem.planes) {
    if (!plane.history) continue;
    std::vector<Index> ids;
    for (const LocalIndex p : particlesOnPlane(model_, plane)) ids.push_back(model_.points.id[p]);
    histories_.add(plane, std::move(ids));
  }
  histories_.locate(model_.points.id, false);  // RKPM keeps its particles in place
}

void RkpmMethod::step() {
  // The histories at the middle of the step, as OTM's and SPH's.
  const Clock c = integrator_.clock();
  histories_.apply(c.time + 0.5 * c.dt_next, model_.prescribed_v);
  integrator_.step();
}

void RkpmMethod::check(double initial_total_energy) {
  const Clock c = integrator_.clock();
  const StepInfo at{c.steps, c.time, c.dt_next, c.dt_initial};
  auto driven = [&] {
    return prescribedWork(histories_, model_.constrained, model_.prescribed_v, model_.points.owned);
  };
  const StepLengthRule rule{[&](LocalIndex p) { return integrator_.stepLength(p); },
                            [&](LocalIndex) { return std::string("its spacing times its smallest stretch"); }};
  diagnostics_.check(model_, at, initial_total_energy, rule, driven);
}

std::vector<std::string> RkpmMethod::notes() const {
  const KernelUpdates u = integrator_.kernelUpdates();
  if (u.made == 0 && u.refused == 0) return {};
  std::vector<std::string> notes{
      fmt::format("{} kernel updates, {} refused (no usable kernels on the configuration then); the coefficients' "
                  "kinetic energy they took, booked apart: {:.6g} J (docs/theory.md §12)",
                  u.made, u.refused, u.energy)};
  if (!integrator_.lastRefusal().empty())
    notes.push_back(fmt::format("the last refused kernel update, at {}", integrator_.lastRefusal()));
  return notes;
}

NodeCloud RkpmMethod::nodes() const {
  const PointStore& points = model_.points;
  return NodeCloud{points.id,    points.body, model_.coefficient_x, model_.coefficient_v, integrator_.masses(),
                   points.owned, false};
}

void RkpmMethod::save(StateWriter& out) const {
  saveClock(out, "rkpm_", integrator_.clock());
  out.scalar("rkpm_contact_energy", integrator_.contactEnergy());
  out.group("/rkpm");
  out.array("/rkpm/constrained", model_.constrained);
  out.array("/rkpm/prescribed_v", model_.prescribed_v);
  out.array("/rkpm/reference", model_.reference);
  out.array("/rkpm/coefficient_x", model_.coefficient_x);
  out.array("/rkpm/coefficient_v", model_.coefficient_v);
  out.array("/rkpm/cell_volume", model_.cell_volume);
  std::vector<Vec3> geometry;
  std::vector<std::int64_t> sides;
  for (const CellFace& f : model_.faces) {
    geometry.push_back(f.area);
    geometry.push_back(f.centroid);
    sides.push_back(f.inner);
    sides.push_back(f.outer);
  }
  out.scalar("rkpm_faces", static_cast<std::int64_t>(model_.faces.size()));
  out.array("/rkpm/face_geometry", geometry);
  out.array("/rkpm/face_sides", sides);
  std::vector<std::int64_t> surface;
  for (const auto& t : model_.surface) surface.insert(surface.end(), t.begin(), t.end());
  out.scalar("rkpm_surface_triangles", static_cast<std::int64_t>(model_.surface.size()));
  out.array("/rkpm/surface", surface);
  std::vector<std::int32_t> element;
  for (const std::array<int, 3>& e : model_.element) element.insert(element.end(), e.begin(), e.end());
  out.array("/rkpm/element", element);
  if (!model_.crack.empty()) out.array("/rkpm/crack", model_.crack);
  if (!model_.reference_F.empty()) {  // after a kernel update
    out.array("/rkpm/origin", model_.origin);
    out.array("/rkpm/reference_F", model_.reference_F);
    out.array("/rkpm/alone", model_.alone);
  }
  const KernelUpdates u = integrator_.kernelUpdates();
  if (u.made > 0 || u.refused > 0) {
    out.array("/rkpm/kernel_updates", std::vector<std::int64_t>{u.made, u.refused, u.retry_at});
    out.array("/rkpm/kernel_update_energy", std::vector<double>{u.energy});
  }
}

void RkpmMethod::load(const StateReader& in) {
  const auto n = static_cast<std::size_t>(model_.points.size());
  in.array("/rkpm/constrained", model_.constrained, n);
  in.array("/rkpm/prescribed_v", model_.prescribed_v, n);
  in.array("/rkpm/reference", model_.reference, n);
  in.array("/rkpm/coefficient_x", model_.coefficient_x, n);
  in.array("/rkpm/coefficient_v", model_.coefficient_v, n);
  in.array("/rkpm/cell_volume", model_.cell_volume, n);
  const std::int64_t faces = in.intScalar("rkpm_faces");
  if (faces < 0) in.fail(fmt::format("rkpm_faces: {} faces", faces));
  std::vector<std::int64_t> sides;
  in.array("/rkpm/face_sides", sides, 2 * static_cast<std::size_t>(faces));
  std::vector<Vec3> geometry;
  in.array("/rkpm/face_geometry", geometry, 2 * static_cast<std::size_t>(faces));
  model_.faces.resize(sides.size() / 2);
  for (std::size_t f = 0; f < model_.faces.size(); ++f) {
    const LocalIndex inner = static_cast<LocalIndex>(sides[2 * f]), outer = static_cast<LocalIndex>(sides[2 * f + 1]);
    if (inner < 0 || static_cast<std::size_t>(inner) >= n || outer < -1 || outer >= static_cast<LocalIndex>(n))
      in.fail(fmt::format("/rkpm/face_sides: face {} names particles {} and {} of {}", f, inner, outer, n));
    model_.faces[f] = {geometry[2 * f], geometry[2 * f + 1], inner, outer};
  }
  const std::int64_t triangles = in.intScalar("rkpm_surface_triangles");
  if (triangles < 0) in.fail(fmt::format("rkpm_surface_triangles: {} triangles", triangles));
  std::vector<std::int64_t> surface;
  in.array("/rkpm/surface", surface, 3 * static_cast<std::size_t>(triangles));
  model_.surface.resize(static_cast<std::size_t>(triangles));
  for (std::size_t t = 0; t < model_.surface.size(); ++t)
    for (std::size_t v = 0; v < 3; ++v) {
      const std::int64_t p = surface[3 * t + v];
      if (p < 0 || p >= static_cast<std::int64_t>(n))
        in.fail(fmt::format("/rkpm/surface: triangle {} names particle {} of {}", t, p, n));
      model_.surface[t][v] = static_cast<LocalIndex>(p);
    }
  // The lattice elements the surface is built from as particles leave as debris. A checkpoint written
  // before they were kept (2026-12-01) has none: its run goes on with the surface it saved.
  model_.element.assign(n, {-1, -1, -1});
  if (in.has("/rkpm/element")) {
    std::vector<std::int32_t> element;
    in.array("/rkpm/element", element, 3 * n);
    for (std::size_t p = 0; p < n; ++p) model_.element[p] = {element[3 * p], element[3 * p + 1], element[3 * p + 2]};
  }
  // The crack made before the first step, which the kernels do not reach across (none if not saved).
  model_.crack.clear();
  if (in.has("/rkpm/crack")) in.array("/rkpm/crack", model_.crack, n);
  // The last kernel update's configuration (none if the run made none).
  model_.origin.clear();
  model_.reference_F.clear();
  model_.alone.clear();
  if (in.has("/rkpm/reference_F")) {
    in.array("/rkpm/origin", model_.origin, n);
    in.array("/rkpm/reference_F", model_.reference_F, n);
    in.array("/rkpm/alone", model_.alone, n);
  }
  KernelUpdates updates;
  if (in.has("/rkpm/kernel_updates")) {
    std::vector<std::int64_t> counts;
    std::vector<double> energy;
    in.array("/rkpm/kernel_updates", counts, 3);
    in.array("/rkpm/kernel_update_energy", energy, 1);
    updates = {counts[0], counts[1], counts[2], energy[0]};
  }
  integrator_.restore(loadClock(in, "rkpm_"),
                      in.doubleScalar("rkpm_contact_energy"), updates);
}

}  // namespace kessler::rkpm
