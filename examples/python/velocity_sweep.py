#!/usr/bin/env python3
"""A parameter study from Python: the Whipple shield of examples/whipple.yaml struck at several
speeds, coarse, with the bumper's hole diameter and the rear wall's outcome plotted against speed
beside Christiansen's ballistic-limit equation (docs/python.md, docs/analysis.md).

    python3 examples/python/velocity_sweep.py                 # 3, 5 and 7 km/s, about 3 minutes on two cores
    python3 examples/python/velocity_sweep.py --speeds 2 4 6 8 --out results/sweep
    python3 examples/python/velocity_sweep.py --end-time "4 us"   # a quick look: the bumper only

Each run is coarse (projectile 0.7 mm, bumper 0.8 mm, rear wall 1.94 mm: one cell through it), so
the rear-wall outcome is an indication, not a ballistic limit: `kessler limit` bisects that
(docs/analysis.md). Writes OUT/sweep.csv and OUT/sweep.png.
"""

import argparse
import csv
import os
import sys

import kessler

HERE = os.path.dirname(os.path.abspath(__file__))
DECK = os.path.join(HERE, "..", "whipple.yaml")


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument("--speeds", type=float, nargs="+", default=[3.0, 5.0, 7.0], help="impact speeds, km/s")
    parser.add_argument("--out", default="results/velocity-sweep", help="folder for the runs, the CSV and the plot")
    parser.add_argument("--end-time", default="40 us", help="simulated time of each run (default: the deck's 40 us)")
    parser.add_argument("--threads", type=int, default=0)
    args = parser.parse_args()

    rows = []
    for speed in args.speeds:
        settings = {
            "bodies.0.velocity": [0, 0, f"-{speed} km/s"],
            "bodies.0.mesh_size": "0.7 mm",
            "bodies.1.mesh_size": "0.8 mm",
            "bodies.2.mesh_size": "1.94 mm",
            "solver.end_time": args.end_time,
            "output.every": "2 us",
            "analysis.plots": False,
        }
        run = kessler.run(DECK, out=os.path.join(args.out, f"v{speed:g}"), sets=settings, threads=args.threads,
                          quiet=True, progress=sys.stderr.isatty())
        a = run.analysis
        holes = {h["body"]: h for h in a.get("holes", [])}
        bumper = holes.get("bumper", {})
        limit = a.get("ballistic_limit", {})
        rows.append({
            "speed_km_per_s": speed,
            "bumper_hole_mm": 1e3 * bumper["diameter_m"] if bumper.get("found") else 0.0,
            "rear_wall": a.get("rear_wall", {}).get("classification", "none"),
            "rear_wall_failed": a.get("rear_wall", {}).get("failed", False),
            "christiansen_critical_mm": 1e3 * limit.get("critical_diameter_m", float("nan")),
            "christiansen_predicts_perforation": limit.get("predicts_perforation", False),
            "wall_s": run.summary["wall_time_s"],
        })
        r = rows[-1]
        print(f"{speed:g} km/s: bumper hole {r['bumper_hole_mm']:.1f} mm, rear wall {r['rear_wall']}; "
              f"Christiansen: critical diameter {r['christiansen_critical_mm']:.2f} mm "
              f"({'perforation' if r['christiansen_predicts_perforation'] else 'no perforation'}); {r['wall_s']:.0f} s",
              flush=True)

    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "sweep.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    speeds = [r["speed_km_per_s"] for r in rows]
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(6.5, 6), sharex=True)
    top.plot(speeds, [r["bumper_hole_mm"] for r in rows], "o-", label="simulated bumper hole")
    top.set_ylabel("bumper hole diameter (mm)")
    top.legend()
    failed = [r["rear_wall_failed"] for r in rows]
    bottom.scatter([s for s, f in zip(speeds, failed) if f], [1] * sum(failed), marker="x", color="C3", s=80,
                   label="simulated: rear wall fails")
    bottom.scatter([s for s, f in zip(speeds, failed) if not f], [1] * (len(failed) - sum(failed)), marker="o",
                   color="C2", s=80, label="simulated: rear wall holds")
    predicted = [r["christiansen_predicts_perforation"] for r in rows]
    bottom.scatter(speeds, [0] * len(speeds), marker="s", c=["C3" if p else "C2" for p in predicted], s=60,
                   label="Christiansen (red: perforation)")
    for s, r in zip(speeds, rows):
        bottom.annotate(r["rear_wall"], (s, 1), textcoords="offset points", xytext=(0, 10), ha="center", fontsize=8)
    bottom.set_yticks([0, 1], ["equation", "simulation"])
    bottom.set_ylim(-0.6, 1.8)
    bottom.set_xlabel("impact speed (km/s)")
    bottom.legend(fontsize=8, loc="lower right")
    fig.suptitle("5 mm Al sphere on the Whipple shield (coarse)")
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "sweep.png"), dpi=120)
    print(f"wrote {os.path.join(args.out, 'sweep.csv')} and sweep.png")


if __name__ == "__main__":
    main()
