#pragma once
// Building blocks shared by the verification problems.
#include "geometry/shape.hpp"
#include "material/neo_hookean.hpp"
#include "solver/common/method.hpp"
#include "solver/common/problem.hpp"

#include <array>
#include <memory>

namespace kessler::verify {

// An aluminium-like neo-Hookean solid: rho 2700 kg/m^3, E 70 GPa, nu 0.33; and its parameters.
std::shared_ptr<const NeoHookean> elasticAluminium();
NeoHookeanParameters elasticAluminiumParameters();

// A box body of n x m x k cells (geometry::StructuredBox: OTM's Kuhn tets, SPH's lattice).
BodySetup boxBody(const std::string& name, const geometry::Box& box, const std::array<int, 3>& cells,
                  const Vec3& velocity, const MaterialPtr& material);

// Every carrier of the problem's bodies keeps a zero velocity along `axis` (uniaxial strain
// across it).
PlaneConstraint lockAxis(int axis);

// The method the checks run (`kessler verify --method`; otm unless chosen): every check builds its
// problem's method with makeCheckMethod.
void useMethod(const std::string& name);
const std::string& checkedMethod();
// The problem's method, as the checks run it (its solver.method set to checkedMethod()).
std::unique_ptr<Method> makeCheckMethod(Problem problem);

// The problem's method (makeCheckMethod), initialised and run to its end time; `after_step` (if given) is called
// after every step and stops the run when it returns false.
std::unique_ptr<Method> runToEnd(const Problem& problem,
                                 const std::function<bool(const Method&)>& after_step = nullptr);

// Number of node and point values (positions, velocities, F, stress, volume) that differ bitwise
// between two methods' states.
long countDifferences(const Method& a, const Method& b);

}  // namespace kessler::verify
