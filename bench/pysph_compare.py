#!/usr/bin/env python3
"""Side-by-side cost of PySPH's 3D solid-impact example and `kessler bench pysph-impact3d`
(docs/performance.md): a steel sphere (radius 5 mm) onto a 2 x 40 x 40 mm aluminium plate at
3.1 km/s. Prints each code's microseconds per particle (material-point) step and core time,
and the ratio. Needs Debian's python3-pysph; without it, says so and exits 0.

usage: pysph_compare.py [--kessler PATH] [--threads N] [--steps N] [--method otm|sph] [--kessler-kernel]

Both codes' cost per step is measured the same way: as the difference of two runs (--steps and
6 x --steps), PySPH's example with output disabled, so that neither code's set-up, code generation
or first steps (memory first touched, lists first grown) count. Kessler's SPH runs at PySPH's own
lattice (0.5 mm, its `dx`); OTM at the bench's size (about as many material points as PySPH has
particles).

The two codes do not do the same work per particle-step: PySPH's example uses a Gaussian kernel
reaching 3h with h = 1.3 dx and a predictor-corrector that evaluates the accelerations twice a step;
Kessler's SPH a cubic spline reaching 2h with h = 1.2 spacings, once a step. So each code's mean
neighbours (PySPH's counted by its own search on the starting particles, including the particle
itself as its search lists it) and evaluations per step are printed too, with the cost per neighbour
and evaluation. `--kessler-kernel` runs PySPH's example with Kessler's kernel and smoothing instead
(cubic spline, h = 1.2 dx; everything else as the example has it): the two codes then meet about
as many neighbours.
"""
import argparse
import importlib
import inspect
import json
import os
import subprocess
import sys
import tempfile
import time


KESSLER_SMOOTHING = 1.2  # solver.sph.smoothing's default: h in spacings (support 2h)


def pysph_neighbours(particles, kernel):
    """The mean number of particles each particle's search lists (itself included), over both arrays."""
    from cyarray.api import UIntArray
    from pysph.base.nnps import LinkedListNNPS
    nnps = LinkedListNNPS(dim=3, particles=particles, radius_scale=kernel.radius_scale)
    found = UIntArray()
    total = count = 0
    for dst, pa in enumerate(particles):
        for i in range(pa.get_number_of_particles()):
            for src in range(len(particles)):
                nnps.set_context(src, dst)
                nnps.get_nearest_particles(src, dst, i, found)
                total += found.length
            count += 1
    return total / max(count, 1)


def pysph_cost(steps, threads, kessler_kernel=False):
    try:
        import pysph  # noqa: F401
        from pysph.solver.application import Application
    except ImportError:
        return None
    module = importlib.import_module("pysph.examples.solid_mech.impact3d")
    if kessler_kernel:  # (the example reads its kernel and h from module globals when it builds)
        from pysph.base.kernels import CubicSpline
        module.Gaussian = CubicSpline
        module.hdx = KESSLER_SMOOTHING
        module.h = KESSLER_SMOOTHING * module.dx
    classes = [c for _, c in inspect.getmembers(module, inspect.isclass)
               if issubclass(c, Application) and c is not Application and c.__module__ == module.__name__]
    if not classes:
        raise SystemExit("pysph.examples.solid_mech.impact3d defines no Application")

    def run(n):
        with tempfile.TemporaryDirectory() as out:
            app = classes[0]()
            args = ["--max-steps", str(n), "--disable-output", "-d", out]
            if threads > 1:
                args.append("--openmp")
            evaluations = [0]
            start = time.perf_counter()
            app.setup(args)
            integrator = app.solver.integrator
            compute = integrator.compute_accelerations

            def counted(*a, **k):
                evaluations[0] += 1
                return compute(*a, **k)
            integrator.compute_accelerations = counted
            app.run(args)
            wall = time.perf_counter() - start
            particles = sum(pa.get_number_of_particles() for pa in app.particles)
            return wall, particles, app.solver.count, evaluations[0], app

    os.environ["OMP_NUM_THREADS"] = str(threads)
    _, _, _, _, first = run(1)  # generates and compiles the kernels once
    w1, particles, s1, e1 = run(steps)[:4]
    w2, _, s2, e2 = run(6 * steps)[:4]
    us = 1e6 * (w2 - w1) / (particles * max(s2 - s1, 1))
    kernel = first.solver.kernel
    return {"particles": particles, "us_per_particle_step": us, "core_us": us * threads,
            "kernel": type(kernel).__name__, "neighbours": pysph_neighbours(first.particles, kernel),
            "evaluations_per_step": (e2 - e1) / max(s2 - s1, 1)}


PYSPH_DX = "0.5 mm"  # impact3d.py's dx (and dy, dz)


def kessler_cost(kessler, steps, threads, method):
    overrides = ["--set", f"solver.method={method}"]
    if method == "sph":  # one particle per lattice cell, as PySPH's
        overrides += ["--set", f"bodies.0.mesh_size={PYSPH_DX}", "--set", f"bodies.1.mesh_size={PYSPH_DX}"]

    def run(n):
        with tempfile.TemporaryDirectory() as out:
            report = os.path.join(out, "bench.json")
            subprocess.run([kessler, "bench", "pysph-impact3d", "--steps", str(n), "--threads", str(threads),
                            *overrides, "--json", report], check=True)
            with open(report) as f:
                return json.load(f)["problems"][0]

    short, long = run(steps), run(6 * steps)
    us = 1e6 * (long["wall_s"] - short["wall_s"]) / (long["points"] * max(long["steps"] - short["steps"], 1))
    return {"points": long["points"], "us_per_point_step": us, "core_us": us * threads,
            "us_whole_run": short["us_per_point_step"], "neighbours": long.get("mean_neighbours", 0.0)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--kessler", default="kessler")
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--steps", type=int, default=10)
    parser.add_argument("--method", default="otm", choices=["otm", "sph"], help="Kessler's method (solver.method)")
    parser.add_argument("--kessler-kernel", action="store_true",
                        help="run PySPH's example with Kessler's SPH kernel and smoothing (cubic spline, h = 1.2 dx)")
    args = parser.parse_args()
    py = pysph_cost(args.steps, args.threads, args.kessler_kernel)
    if py is None:
        print("PySPH is not installed (Debian: apt install python3-pysph): nothing to compare.")
        print("Published figure (issue 5): about 76 us per particle-step per core for this example.")
        return 0
    k = kessler_cost(args.kessler, args.steps, args.threads, args.method)
    variant = " with Kessler's kernel (cubic spline, h = 1.2 dx)" if args.kessler_kernel else ""
    print(f"PySPH   impact3d{variant}: {py['particles']} particles, {py['us_per_particle_step']:.3f} us per "
          f"particle-step, {py['core_us']:.3f} us core")
    print(f"Kessler pysph-impact3d ({args.method}): {k['points']} material points, {k['us_per_point_step']:.3f} us per point-step, "
          f"{k['core_us']:.3f} us core ({k['us_whole_run']:.3f} us over the whole {args.steps}-step run, first steps included)")
    print(f"ratio (PySPH / Kessler, core time per particle-step): {py['core_us'] / k['core_us']:.2f}")
    # The work behind a particle-step: the neighbours each code meets and how often a step meets them
    # (Kessler's count leaves the particle itself out, PySPH's search lists it).
    py_others = py["neighbours"] - 1.0
    print(f"PySPH   {py['kernel']} kernel: {py_others:.1f} neighbours per particle (its search lists "
          f"{py['neighbours']:.1f}, itself included), {py['evaluations_per_step']:.2f} evaluations per step: "
          f"{1e3 * py['core_us'] / (py_others * py['evaluations_per_step']):.1f} ns core per neighbour and evaluation")
    if args.method == "sph" and k["neighbours"] > 0:
        print(f"Kessler cubic spline: {k['neighbours']:.1f} neighbours per particle, 1 evaluation per step: "
              f"{1e3 * k['core_us'] / k['neighbours']:.1f} ns core per neighbour and evaluation")
        ratio = (py["core_us"] / (py_others * py["evaluations_per_step"])) / (k["core_us"] / k["neighbours"])
        print(f"ratio per neighbour and evaluation: {ratio:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
