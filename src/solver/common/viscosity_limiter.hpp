#pragma once
// The limiter of the laws' artificial bulk viscosity (material/impact_material.cpp; docs/theory.md §5).
namespace kessler {

// Christensen's limiter for one point from the ratios r_a = ln j_a / ln j_p of the volume changes
// around it (OTM: its nodes' means; RKPM: the particles its kernel row reaches) to its own over the
// step (compression only): phi = clamp(min(mean r, 2 min r), 0, 1). `mean_ratio` is the
// shape-function-weighted mean, `min_ratio` the smallest. A linear velocity field gives ratios near 1
// and no viscosity; a shock, where the point compresses far more than those beside it, small ones.
double christensenLimiter(double mean_ratio, double min_ratio);

}  // namespace kessler
