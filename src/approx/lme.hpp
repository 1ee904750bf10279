#pragma once
// Local maximum-entropy (LME) shape functions (Arroyo & Ortiz, IJNME 65:2167-2202, 2006, §2 and §4):
//   N_a(x) = exp(-beta |x - x_a|^2 + lambda* . (x - x_a)) / Z(x, lambda*),
// where lambda* minimises log Z, found (§4.2) by Newton's method with a backtracking line
// search, warm-started from the previous step's lambda. Gradients:
//   grad N_a = -N_a J^-1 (x - x_a),  J = d^2 log Z / d lambda^2 (the covariance of x - x_a).
// The identities sum N_a = 1, sum N_a x_a = x, sum grad N_a = 0, sum x_a (x) grad N_a = I hold
// to the Newton tolerance. A point outside the convex hull of its nodes has no minimiser
// (log Z is unbounded below): the solve reports it instead of returning garbage.
#include "core/types.hpp"

#include <span>

namespace kessler::lme {

// beta = gamma / h^2 and the cut-off radius r = h sqrt(-ln tol / gamma) where N_a < tol.
inline double beta(double gamma, double h) { return gamma / (h * h); }
double cutoffRadius(double gamma, double h, double tolerance);

// `no_nodes` and `not_finite` are refused before the solve: with no offsets, or a non-finite one (a
// point or node position that is NaN or infinite), log Z has no minimum to find.
enum class Status { converged, not_converged, outside_hull, ill_conditioned, no_nodes, not_finite };

struct Result {
  Status status = Status::converged;
  int iterations = 0;
  double residual = 0.0;  // |sum N_a (x - x_a)| / h at the end
  // With `check_conditioning` and Status::ill_conditioned: the smallest eigenvalue of J / h^2.
  double covariance = 0.0;
};

// The smallest principal variance of the weighted node offsets (the covariance J) over h^2 below
// which shapeFunctions() refuses the point as ill-conditioned when asked to: its gradients,
// -N_a J^-1 d_a, grow as the inverse. An interior point of a Gmsh mesh has about 0.1
// (1 / (2 gamma) at gamma = 4), a point a quarter spacing inside a flat free surface about 0.03
// across it; a point whose nodes are nearly coplanar as seen from it (at the edge of their hull,
// or squeezed into a layer) less. At about 2e-4, gradients of 800 / h put a node of a 0.25 mm
// sphere-plate run at 46 km/s in one step (docs/theory.md §2).
inline constexpr double min_covariance = 1e-3;

// Shape functions at a point from the offsets d_a = x - x_a of its nodes. On input `lambda`
// is the starting guess; on output the minimiser. N and dN have the size of d. With
// `check_conditioning`, a covariance below min_covariance h^2 is Status::ill_conditioned, with its
// smallest eigenvalue in Result::covariance; N and dN are then still the (valid) shape functions.
Result shapeFunctions(std::span<const Vec3> d, double beta, double h, Vec3& lambda, std::span<double> N,
                      std::span<Vec3> dN, bool check_conditioning = false);

const char* describe(Status status);

}  // namespace kessler::lme
