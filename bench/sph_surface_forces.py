#!/usr/bin/env python3
"""Where SPH's kernel-corrected forces put a face's traction (docs/validation.md, "SPH's footprint
on its cells"; the forces of docs/theory.md §10).

A cubic lattice of unit spacing fills the half-space z > 0 (periodic in x and y); every particle
bears the same stress sigma = -p I. The forces

    f_i = sum_j V_i V_j (sigma B_i^T + sigma B_j^T) grad_i W_ij,
    B_i = [ sum_j V_j (x_j - x_i) (x) grad_i W_ij ]^-1,

with the cubic B-spline of smoothing length h = 1.2 spacings, sum over the particles beside the
face to the traction on it, -p per unit area. This prints how that sum is split among the layers
from the face: a wall that holds the first layer alone absorbs that layer's share, and leaves the
layers behind it their own.

usage: sph_surface_forces.py [--smoothing H] [--layers N]
"""
import argparse

import numpy as np


def kernel_slope(r, h):
    """dW/dr of the 3-D cubic B-spline with support 2h (solver/sph/kernel.hpp)."""
    q = r / h
    norm = 1.0 / (np.pi * h**3)
    inner = norm * (-3.0 * q + 2.25 * q * q) / h
    outer = norm * (-0.75 * (2.0 - q) ** 2) / h
    return np.where(q < 1.0, inner, np.where(q < 2.0, outer, 0.0))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--smoothing", type=float, default=1.2, help="h in spacings (default 1.2, as shipped)")
    parser.add_argument("--layers", type=int, default=12, help="lattice layers above the face (default 12)")
    args = parser.parse_args()
    h, width, layers = args.smoothing, 8, args.layers
    x = np.array([(i + 0.5, j + 0.5, k + 0.5) for i in range(width) for j in range(width) for k in range(layers)])
    volume = 1.0

    def pairs(i):
        d = x[i] - x  # x_i - x_j, nearest periodic image in x and y
        d[:, :2] -= width * np.round(d[:, :2] / width)
        r = np.linalg.norm(d, axis=1)
        near = (r > 0.0) & (r < 2.0 * h)
        others, d, r = np.nonzero(near)[0], d[near], r[near]
        return others, (kernel_slope(r, h) / r)[:, None] * d, d

    gradients = [pairs(i) for i in range(len(x))]
    correction = np.array([np.linalg.inv(np.einsum("ja,jb->ab", -volume * d, g)) for _, g, d in gradients])
    sigma = -np.eye(3)  # p = 1
    force = np.zeros_like(x)
    for i, (others, g, _) in enumerate(gradients):
        stress_b = sigma @ correction[i].T + np.einsum("ab,jcb->jac", sigma, correction[others])
        force[i] = volume * volume * np.einsum("jab,jb->a", stress_b, g).sum(axis=0)
    print(f"h = {h} spacings; uniform pressure p on a cubic lattice beside the face z = 0")
    print("layer  f_z per particle / (p times its face's area)")
    total = 0.0
    for k in range(min(6, layers // 2)):
        share = force[np.abs(x[:, 2] - (k + 0.5)) < 1e-9, 2].mean()
        total += share
        print(f"{k:5d}  {share:+.4f}")
    print(f"sum    {total:+.4f}  (the traction: -1)")


if __name__ == "__main__":
    main()
