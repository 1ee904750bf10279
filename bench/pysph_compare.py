#!/usr/bin/env python3
"""Side-by-side cost of PySPH's 3D solid-impact example and `kessler bench pysph-impact3d`
(docs/performance.md): a steel sphere (radius 5 mm) onto a 2 x 40 x 40 mm aluminium plate at
3.1 km/s. Prints each code's microseconds per particle (material-point) step and core time,
and the ratio. Needs Debian's python3-pysph; without it, says so and exits 0.

usage: pysph_compare.py [--kessler PATH] [--threads N] [--steps N] [--method otm|sph]

Both codes' cost per step is measured the same way: as the difference of two runs (--steps and
6 x --steps), PySPH's example with output disabled, so that neither code's set-up, code generation
or first steps (memory first touched, lists first grown) count. Kessler's SPH runs at PySPH's own
lattice (0.5 mm, its `dx`); OTM at the bench's size (about as many material points as PySPH has
particles).
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


def pysph_cost(steps, threads):
    try:
        import pysph  # noqa: F401
        from pysph.solver.application import Application
    except ImportError:
        return None
    module = importlib.import_module("pysph.examples.solid_mech.impact3d")
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
            start = time.perf_counter()
            app.run(args)
            wall = time.perf_counter() - start
            particles = sum(pa.get_number_of_particles() for pa in app.particles)
            return wall, particles, app.solver.count

    os.environ["OMP_NUM_THREADS"] = str(threads)
    run(1)  # generates and compiles the kernels once
    w1, particles, s1 = run(steps)
    w2, _, s2 = run(6 * steps)
    us = 1e6 * (w2 - w1) / (particles * max(s2 - s1, 1))
    return {"particles": particles, "us_per_particle_step": us, "core_us": us * threads}


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
            "us_whole_run": short["us_per_point_step"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--kessler", default="kessler")
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--steps", type=int, default=10)
    parser.add_argument("--method", default="otm", choices=["otm", "sph"], help="Kessler's method (solver.method)")
    args = parser.parse_args()
    py = pysph_cost(args.steps, args.threads)
    if py is None:
        print("PySPH is not installed (Debian: apt install python3-pysph): nothing to compare.")
        print("Published figure (issue 5): about 76 us per particle-step per core for this example.")
        return 0
    k = kessler_cost(args.kessler, args.steps, args.threads, args.method)
    print(f"PySPH   impact3d: {py['particles']} particles, {py['us_per_particle_step']:.3f} us per particle-step, "
          f"{py['core_us']:.3f} us core")
    print(f"Kessler pysph-impact3d ({args.method}): {k['points']} material points, {k['us_per_point_step']:.3f} us per point-step, "
          f"{k['core_us']:.3f} us core ({k['us_whole_run']:.3f} us over the whole {args.steps}-step run, first steps included)")
    print(f"ratio (PySPH / Kessler, core time per particle-step): {py['core_us'] / k['core_us']:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
