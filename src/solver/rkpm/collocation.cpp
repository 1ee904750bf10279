#include "solver/rkpm/collocation.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace kessler::rkpm {

SurfaceHolds surfaceHolds(const Model& model) {
  SurfaceHolds out;
  for (std::size_t f = 0; f < model.faces.size(); ++f) {
    const CellFace& face = model.faces[f];
    for (int a = 0; a < 3; ++a)
      if (surfaceFaceAlong(face, a) && (model.constrained[face.inner] & (held_at_surface << a))) {
        out.faces.push_back(static_cast<LocalIndex>(f));
        out.held.push_back({face.inner, a});
      }
  }
  return out;
}

VelocityCollocation::VelocityCollocation(const Table<double>& psi, std::span<const std::uint8_t> constrained,
                                         std::span<const double> mass, const Table<double>& at_faces,
                                         std::span<const HeldFace> held) {
  const LocalIndex n = psi.rows();
  KESSLER_VERIFY(mass.size() == static_cast<std::size_t>(n), "{} masses for {} particles", mass.size(), n);
  inverse_mass_.resize(n);
  for (LocalIndex i = 0; i < n; ++i) inverse_mass_[i] = 1.0 / mass[static_cast<std::size_t>(i)];
  for (int a = 0; a < 3; ++a) {
    Component& c = components_[static_cast<std::size_t>(a)];
    std::vector<Eigen::Triplet<double>> entries;
    // Row r of P: the shape functions of `table`'s row `at`, held to particle k's prescribed value.
    auto add = [&](const Table<double>& table, LocalIndex at, LocalIndex k) {
      const auto r = static_cast<int>(c.source.size());
      c.source.push_back(k);
      for (LocalIndex e = table.offset[at]; e < table.offset[at + 1]; ++e) {
        // An image's component a is its particle's, reversed if it is reflected across a's plane.
        const double sign = table.mirror[static_cast<std::size_t>(e)] & (1u << a) ? -1.0 : 1.0;
        entries.emplace_back(r, static_cast<int>(table.column[static_cast<std::size_t>(e)]),
                             sign * table.value[static_cast<std::size_t>(e)]);
      }
    };
    for (LocalIndex k = 0; k < n; ++k)
      if ((constrained[k] & (1u << a)) && !(constrained[k] & (held_at_surface << a))) add(psi, k, k);
    for (std::size_t r = 0; r < held.size(); ++r)
      if (held[r].axis == a) add(at_faces, static_cast<LocalIndex>(r), held[r].particle);
    if (c.source.empty()) continue;
    const auto m = static_cast<Eigen::Index>(c.source.size());
    c.shape.resize(m, n);
    c.shape.setFromTriplets(entries.begin(), entries.end());
    c.shape_t = c.shape.transpose();
    c.solver = std::make_shared<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>();
    c.solver->compute(Eigen::SparseMatrix<double>(c.shape * inverse_mass_.asDiagonal() * c.shape_t));
    if (c.solver->info() != Eigen::Success)
      throw Error(fmt::format(
          "RKPM velocity collocation: the shape functions at the {} particles or surface faces that prescribe "
          "velocity component {} form a singular system there (docs/theory.md §12)",
          m, "xyz"[a]));
  }
}

void VelocityCollocation::impose(std::span<const Vec3> prescribed, std::span<Vec3> coefficients) const {
  for (int a = 0; a < 3; ++a) {
    const Component& c = components_[static_cast<std::size_t>(a)];
    if (c.source.empty()) continue;
    const auto m = static_cast<Eigen::Index>(c.source.size());
    Eigen::VectorXd v(static_cast<Eigen::Index>(coefficients.size()));
    for (std::size_t i = 0; i < coefficients.size(); ++i) v[static_cast<Eigen::Index>(i)] = coefficients[i][a];
    Eigen::VectorXd rhs(m);
    for (Eigen::Index r = 0; r < m; ++r) rhs[r] = prescribed[static_cast<std::size_t>(c.source[r])][a];
    rhs -= c.shape * v;
    const Eigen::VectorXd impulse = c.solver->solve(rhs);
    const Eigen::VectorXd change = inverse_mass_.asDiagonal() * (c.shape_t * impulse);
    for (std::size_t i = 0; i < coefficients.size(); ++i) coefficients[i][a] += change[static_cast<Eigen::Index>(i)];
  }
}

}  // namespace kessler::rkpm
