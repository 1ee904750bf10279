#!/usr/bin/env python3
"""Residual velocity against impact speed for a set of runs of one deck at several speeds (a
projectile perforating a plate), beside the Recht-Ipson relation

    v_r = a (v^p - v_bl^p)^(1/p),   a = m_p / (m_p + m_plug),   p = 2

(Recht & Ipson, J. Appl. Mech. 30, 1963). v_bl is taken from the runs themselves: between the
fastest run that does not perforate and the slowest that does.

    python3 tools/plots/residual_velocity.py RUN_DIR [RUN_DIR ...] --projectile rod \
        --plug-mass 0.0165 --out DIR

For each run it reads the point outputs and summary.json: the projectile's velocity along its
initial direction of flight (its points' mass-weighted mean, mass = density x volume) at every
output, and the rear-wall verdict of the run's analysis (perforated or not). A run that did not
perforate has v_r = 0; its projectile's speed at the end is printed beside it, since a run that
ends too early has not decided. Writes DIR/plots/residual_velocity.png and DIR/residual_velocity.csv.
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kessler_plots as kp  # noqa: E402


def projectile_history(run, body):
    """[(time, velocity along the initial flight direction)] of the projectile's points."""
    import h5py
    import numpy as np
    history, direction = [], None
    for time, _, path in kp.point_outputs(run):
        with h5py.File(path, "r") as h5:
            ids = np.asarray(h5["points/body"], dtype=int)
            mask = ids == body
            mass = np.asarray(h5["points/density"])[mask] * np.asarray(h5["points/volume"])[mask]
            v = np.asarray(h5["points/velocity"], dtype=float).reshape(-1, 3)[mask]
        mean = (mass[:, None] * v).sum(axis=0) / mass.sum()
        if direction is None:
            direction = mean / np.linalg.norm(mean)
        history.append((time, float(mean @ direction)))
    return history


def recht_ipson(v, v_bl, a, p=2.0):
    import numpy as np
    v = np.asarray(v, dtype=float)
    return np.where(v > v_bl, a * np.maximum(v**p - v_bl**p, 0.0) ** (1.0 / p), 0.0)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+", help="run folders, one per impact speed")
    parser.add_argument("--projectile", default="rod", help="the projectile body's name (default: rod)")
    parser.add_argument("--plug-mass", type=float, required=True,
                        help="the plug's mass, kg (whole model: the plate under the projectile's face)")
    parser.add_argument("--out", required=True, help="folder for the table and the plot")
    args = parser.parse_args()
    kp.require_modules("numpy", "h5py", "matplotlib")
    import matplotlib.pyplot as plt
    import numpy as np

    rows = []
    for run in args.runs:
        kp.run_dir(run)
        summary = kp.load_summary(run)
        names = kp.body_names(summary)
        if args.projectile not in names:
            kp.fail(f"'{run}' has no body '{args.projectile}' (bodies: {', '.join(names)})")
        limit = summary.get("analysis", {}).get("ballistic_limit", {})
        speed = limit.get("impact_speed_m_per_s")
        mass = summary.get("analysis", {}).get("breakup_model", {}).get("projectile_mass_kg")
        if speed is None or mass is None:
            kp.fail(f"'{run}/summary.json' lacks the impact speed or projectile mass (did its analysis run?)")
        history = projectile_history(run, names.index(args.projectile))
        perforated = limit.get("simulated") == "perforation"
        rows.append({"run": run, "speed": speed, "mass": mass, "perforated": perforated, "end_time": history[-1][0],
                     "end_speed": history[-1][1], "verdict": limit.get("simulated", "")})
    rows.sort(key=lambda r: r["speed"])
    a = rows[0]["mass"] / (rows[0]["mass"] + args.plug_mass)
    held = [r["speed"] for r in rows if not r["perforated"]]
    failed = [r["speed"] for r in rows if r["perforated"]]
    low, high = (max(held) if held else 0.0), (min(failed) if failed else float("inf"))

    os.makedirs(args.out, exist_ok=True)
    table = os.path.join(args.out, "residual_velocity.csv")
    with open(table, "w", newline="", encoding="utf-8") as f:
        writer = csv.writer(f)
        writer.writerow(["run", "impact_speed_m_per_s", "verdict", "residual_m_per_s", "end_time_s",
                         "projectile_speed_at_end_m_per_s"])
        for r in rows:
            residual = r["end_speed"] if r["perforated"] else 0.0
            writer.writerow([r["run"], f"{r['speed']:.1f}", r["verdict"], f"{residual:.1f}", f"{r['end_time']:.3g}",
                             f"{r['end_speed']:.1f}"])
            print(f"{r['speed']:7.0f} m/s  {r['verdict']:<16} projectile at {r['end_speed']:7.1f} m/s "
                  f"at {1e6 * r['end_time']:.1f} us  ({r['run']})")
    print(f"a = m_p / (m_p + m_plug) = {a:.3f}; simulated v_bl in ({low:.0f}, {high:.0f}] m/s")
    print(f"{os.path.basename(sys.argv[0])}: wrote {table}")

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    top = 1.1 * max(r["speed"] for r in rows)
    v = np.linspace(0.0, top, 200)
    for v_bl, style in ((low, "--"), (high, ":")):
        if 0.0 < v_bl < top:
            ax.plot(v, recht_ipson(v, v_bl, a), style, color="0.4",
                    label=f"Recht-Ipson, a = {a:.2f}, p = 2, v_bl = {v_bl:.0f} m/s")
    for r in rows:
        if r["perforated"]:
            ax.plot(r["speed"], r["end_speed"], "o", color="tab:red")
            ax.annotate(f"at {1e6 * r['end_time']:.0f} us", (r["speed"], r["end_speed"]), textcoords="offset points",
                        xytext=(6, -10), fontsize=7)
        else:
            ax.plot(r["speed"], 0.0, "s", color="tab:blue")
            ax.annotate(f"held; rod at {r['end_speed']:.0f} m/s\nat {1e6 * r['end_time']:.0f} us",
                        (r["speed"], 0.0), textcoords="offset points", xytext=(0, 10), ha="center", fontsize=7)
    ax.plot([], [], "o", color="tab:red", label="simulated: perforated")
    ax.plot([], [], "s", color="tab:blue", label="simulated: not perforated")
    ax.set_xlabel("impact speed v (m/s)")
    ax.set_ylabel("residual velocity v_r (m/s)")
    ax.set_xlim(0.0, top)
    ax.set_ylim(bottom=-0.05 * top)
    ax.legend(fontsize=7, loc="upper left")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    kp.save_figure(fig, args.out, "residual_velocity.png")


if __name__ == "__main__":
    main()
