#include "solver/rkpm/collocation.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

namespace kessler::rkpm {

VelocityCollocation::VelocityCollocation(const Table<double>& psi, std::span<const std::uint8_t> constrained) {
  const LocalIndex n = psi.rows();
  for (int a = 0; a < 3; ++a) {
    Component& c = components_[static_cast<std::size_t>(a)];
    std::vector<LocalIndex> slot(static_cast<std::size_t>(n), -1);
    for (LocalIndex k = 0; k < n; ++k)
      if (constrained[k] & (1u << a)) {
        slot[k] = static_cast<LocalIndex>(c.particles.size());
        c.particles.push_back(k);
      }
    if (c.particles.empty()) continue;
    std::vector<Eigen::Triplet<double>> in_b, out_b;
    for (std::size_t r = 0; r < c.particles.size(); ++r) {
      const LocalIndex k = c.particles[r];
      for (LocalIndex e = psi.offset[k]; e < psi.offset[k + 1]; ++e) {
        const LocalIndex i = psi.column[static_cast<std::size_t>(e)];
        // An image's component a is its particle's, reversed if it is reflected across a's plane.
        const double sign = psi.mirror[static_cast<std::size_t>(e)] & (1u << a) ? -1.0 : 1.0;
        const double value = sign * psi.value[static_cast<std::size_t>(e)];
        if (slot[i] >= 0)
          in_b.emplace_back(static_cast<int>(r), static_cast<int>(slot[i]), value);
        else
          out_b.emplace_back(static_cast<int>(r), static_cast<int>(i), value);
      }
    }
    const auto m = static_cast<Eigen::Index>(c.particles.size());
    Eigen::SparseMatrix<double> J(m, m);
    J.setFromTriplets(in_b.begin(), in_b.end());
    c.coupling.resize(m, n);
    c.coupling.setFromTriplets(out_b.begin(), out_b.end());
    c.solver = std::make_shared<Eigen::SparseLU<Eigen::SparseMatrix<double>>>();
    c.solver->compute(J);
    if (c.solver->info() != Eigen::Success)
      throw Error(fmt::format(
          "RKPM velocity collocation: the shape functions of the {} particles that prescribe velocity component {} "
          "form a singular matrix at them ({}; docs/theory.md §12)",
          m, "xyz"[a], c.solver->lastErrorMessage()));
  }
}

void VelocityCollocation::impose(std::span<const Vec3> prescribed, std::span<Vec3> coefficients) const {
  for (int a = 0; a < 3; ++a) {
    const Component& c = components_[static_cast<std::size_t>(a)];
    if (c.particles.empty()) continue;
    const auto m = static_cast<Eigen::Index>(c.particles.size());
    Eigen::VectorXd v(static_cast<Eigen::Index>(coefficients.size()));
    for (std::size_t i = 0; i < coefficients.size(); ++i) v[static_cast<Eigen::Index>(i)] = coefficients[i][a];
    Eigen::VectorXd rhs(m);
    for (Eigen::Index r = 0; r < m; ++r) rhs[r] = prescribed[static_cast<std::size_t>(c.particles[r])][a];
    rhs -= c.coupling * v;
    const Eigen::VectorXd solved = c.solver->solve(rhs);
    for (Eigen::Index r = 0; r < m; ++r) coefficients[static_cast<std::size_t>(c.particles[r])][a] = solved[r];
  }
}

}  // namespace kessler::rkpm
