#!/usr/bin/env python3
"""CI check of `kessler bench --size tiny` (ctest bench.tiny): every benchmark problem runs, and
its JSON report is complete, with finite, positive figures. A smoke test by design: timings on a
shared CI machine are not pinned, only that the benchmarks still run and report.

usage: check_bench.py KESSLER JSON_FILE
"""
import json
import math
import subprocess
import sys

PROBLEMS = ["hvi-100k", "hvi-1m", "pysph-impact3d"]
POSITIVE = ["points", "nodes", "steps", "threads", "mean_neighbours", "wall_s", "us_per_point_step",
            "core_us_per_point_step", "peak_memory_bytes", "peak_memory_bytes_per_point", "mesh_size_m"]
PHASES = ["search", "shape functions", "assembly", "node update", "point update", "constitutive", "erosion",
          "time step", "output"]


def main():
    kessler, out = sys.argv[1], sys.argv[2]
    subprocess.run([kessler, "bench", "--size", "tiny", "--json", out], check=True)
    with open(out) as f:
        report = json.load(f)
    errors = []
    names = [p.get("name") for p in report.get("problems", [])]
    if names != PROBLEMS:
        errors.append(f"problems {names}, expected {PROBLEMS}")
    for p in report.get("problems", []):
        name = p.get("name")
        if p.get("status") != "ok":
            errors.append(f"{name}: status {p.get('status')}: {p.get('message')}")
        for key in POSITIVE:
            v = p.get(key)
            if not isinstance(v, (int, float)) or not math.isfinite(v) or v <= 0:
                errors.append(f"{name}: {key} = {v!r}, expected a finite positive number")
        if not isinstance(p.get("omp_wait_policy"), str) or not p.get("omp_wait_policy"):
            errors.append(f"{name}: omp_wait_policy = {p.get('omp_wait_policy')!r}, expected the policy's name")
        if p.get("steps") != 10:
            errors.append(f"{name}: {p.get('steps')} steps, expected 10")
        for key in ("phases_s", "phases_us_per_point_step"):
            phases = p.get(key, {})
            for phase in PHASES:
                v = phases.get(phase)
                if not isinstance(v, (int, float)) or not math.isfinite(v) or v < 0:
                    errors.append(f"{name}: {key}[{phase}] = {v!r}, expected a finite number >= 0")
            for phase in ("search", "shape functions", "assembly", "constitutive"):
                if not phases.get(phase, 0) > 0:
                    errors.append(f"{name}: {key}[{phase}] is not positive")
    for e in errors:
        print("bench.tiny:", e, file=sys.stderr)
    if errors:
        return 1
    print(f"bench.tiny: {len(names)} problems ran and reported complete, finite figures")
    return 0


if __name__ == "__main__":
    sys.exit(main())
