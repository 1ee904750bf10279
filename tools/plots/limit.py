#!/usr/bin/env python3
"""The simulated ballistic limit of `kessler limit` beside the engineering equation's critical
diameter at the same speeds (Christiansen's for a Whipple shield, Cour-Palais's for one wall).

    python3 tools/plots/limit.py LIMIT_DIR

Reads LIMIT_DIR/limit.csv (columns speed_m_per_s, critical_diameter_m, held_m, failed_m,
christiansen_m, note) and LIMIT_DIR/trials.csv (speed_m_per_s, diameter_m, failed), and writes
LIMIT_DIR/plots/limit.png: every trial (held or failed), the bracket of each speed, and the
equation's critical diameters joined by a line.
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kessler_plots as kp  # noqa: E402


def read_csv(path, columns):
    if not os.path.exists(path):
        kp.fail(f"'{path}' does not exist (kessler limit writes it)")
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        for column in columns:
            if column not in (reader.fieldnames or []):
                kp.fail(f"'{path}' has no column '{column}'")
        return list(reader)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dir", help="kessler limit's output folder (holds limit.csv and trials.csv)")
    args = parser.parse_args()
    kp.require_modules("matplotlib")
    import matplotlib.pyplot as plt

    out_dir = kp.run_dir(args.dir)
    limits = read_csv(os.path.join(out_dir, "limit.csv"),
                      ("speed_m_per_s", "critical_diameter_m", "held_m", "failed_m", "christiansen_m", "note"))
    trials = read_csv(os.path.join(out_dir, "trials.csv"), ("speed_m_per_s", "diameter_m", "failed"))

    fig, ax = plt.subplots(figsize=(7, 5.5), constrained_layout=True)
    held = [(float(t["speed_m_per_s"]) / 1e3, float(t["diameter_m"]) * 1e3) for t in trials if t["failed"] == "0"]
    failed = [(float(t["speed_m_per_s"]) / 1e3, float(t["diameter_m"]) * 1e3) for t in trials if t["failed"] == "1"]
    if held:
        ax.scatter(*zip(*held), marker="o", facecolors="none", edgecolors="tab:green", label="run: rear wall holds")
    if failed:
        ax.scatter(*zip(*failed), marker="x", color="tab:red", label="run: rear wall fails")
    rows = sorted(limits, key=lambda r: float(r["speed_m_per_s"]))
    speeds = [float(r["speed_m_per_s"]) / 1e3 for r in rows]
    critical = [(s, float(r["critical_diameter_m"]) * 1e3) for s, r in zip(speeds, rows)
                if float(r["critical_diameter_m"]) > 0]
    if critical:
        ax.plot(*zip(*critical), color="tab:blue", marker="s", linewidth=1.8, label="simulated critical diameter")
    for s, r in zip(speeds, rows):
        if float(r["critical_diameter_m"]) <= 0 and r["note"]:
            d = max(float(r["held_m"]), float(r["failed_m"])) * 1e3
            ax.annotate(r["note"], (s, d), textcoords="offset points", xytext=(4, 6), fontsize=8)
    equation = [(s, float(r["christiansen_m"]) * 1e3) for s, r in zip(speeds, rows) if float(r["christiansen_m"]) > 0]
    if equation:
        ax.plot(*zip(*equation), color="black", linestyle="--", marker=".",
                label="ballistic-limit equation (same speeds)")
    ax.set_xlabel("impact speed (km/s)")
    ax.set_ylabel("projectile diameter (mm)")
    ax.set_ylim(bottom=0)
    ax.grid(True, linewidth=0.3, alpha=0.5)
    ax.legend(loc="best", fontsize=9)
    ax.set_title(f"simulated ballistic limit: {os.path.basename(os.path.abspath(out_dir))}", fontsize=10)
    kp.save_figure(fig, out_dir, "limit.png")


if __name__ == "__main__":
    main()
