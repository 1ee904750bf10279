#!/usr/bin/env python3
"""Cumulative fragment-size distribution N(>Lc) of a Kessler run on log-log axes, beside the
NASA standard breakup model's prediction for the same event.

    python3 tools/plots/fragments.py RUN_DIR

Reads RUN_DIR/fragments.csv (columns lc_m, copies, points and body; with several bodies each
body's distribution is drawn too) and the model's parameters from
RUN_DIR/summary.json, object "analysis" -> "breakup_model" (keys coefficient, mass_exponent,
length_exponent, reference_mass_kg, catastrophic; see docs/analysis.md), and writes
RUN_DIR/plots/fragments.png.
"""
import argparse
import csv
import os
import sys
import textwrap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kessler_plots as kp  # noqa: E402


def read_fragments(run):
    path = os.path.join(run, "fragments.csv")
    if not os.path.exists(path):
        kp.fail(f"'{path}' does not exist (the run writes it when its analysis runs)")
    lc, copies, points, body = [], [], [], []
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        for column in ("lc_m", "copies", "points", "body"):
            if column not in (reader.fieldnames or []):
                kp.fail(f"'{path}' has no column '{column}'")
        for row in reader:
            lc.append(float(row["lc_m"]))
            copies.append(int(row["copies"]))
            points.append(int(row["points"]))
            body.append(row["body"])
    return lc, copies, points, body


def breakup_model(summary):
    model = summary.get("analysis", {}).get("breakup_model") or summary.get("breakup_model")
    if not model:
        return None
    try:
        return {k: model[k] for k in ("coefficient", "mass_exponent", "length_exponent", "reference_mass_kg",
                                      "catastrophic")}
    except KeyError as missing:
        kp.fail(f"summary.json: breakup_model lacks {missing}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run", help="run folder (holds fragments.csv and summary.json)")
    args = parser.parse_args()
    kp.require_modules("numpy", "matplotlib")
    import matplotlib.pyplot as plt
    import numpy as np

    run = kp.run_dir(args.run)
    lc, copies, points, body = read_fragments(run)
    summary = kp.load_summary(run)
    model = breakup_model(summary)

    fig, ax = plt.subplots(figsize=(7, 5.5), constrained_layout=True)
    lc = np.asarray(lc)
    positive = lc > 0
    if positive.any():
        order = np.argsort(-lc[positive], kind="stable")
        sizes = lc[positive][order]
        counts = np.cumsum(np.asarray(copies)[positive][order])
        ax.step(sizes * 1e3, counts, where="post", color="tab:blue", linewidth=1.8,
                label=f"simulation ({counts[-1]} fragments)")
        # A collision of several bodies: each body's own distribution too.
        names = np.asarray(body)[positive]
        if len(set(names)) > 1:
            for k, name in enumerate(dict.fromkeys(names)):
                mine = names[order] == name
                ax.step(sizes[mine] * 1e3, np.cumsum(np.asarray(copies)[positive][order][mine]), where="post",
                        color=("tab:green", "tab:orange", "tab:purple", "tab:brown")[k % 4], linewidth=1.2,
                        label=f"{name} ({int(np.asarray(copies)[positive][order][mine].sum())} fragments)")
        single = np.asarray(points)[positive] == 1
        if single.any():
            resolution = np.median(lc[positive][single])
            ax.axvline(resolution * 1e3, color="grey", linestyle=":", linewidth=1,
                       label=f"one material point ({resolution * 1e3:.2f} mm)")
        lo, hi = sizes.min() * 0.5, sizes.max() * 2.0
    else:
        lo, hi = 1e-4, 1e-1
    if model:
        grid = np.logspace(np.log10(lo), np.log10(hi), 100)
        scale = model["coefficient"] * model["reference_mass_kg"] ** model["mass_exponent"]
        n = scale * grid ** model["length_exponent"]
        kind = "catastrophic" if model["catastrophic"] else "non-catastrophic"
        ax.plot(grid * 1e3, n, color="tab:red", linestyle="--", linewidth=1.5,
                label=f"NASA breakup model ({kind}, M = {model['reference_mass_kg']:.3g} kg)")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("characteristic length Lc (mm)")
    ax.set_ylabel("cumulative number N(>Lc)")
    ax.set_ylim(bottom=0.5)
    ax.grid(True, which="both", linewidth=0.3, alpha=0.5)
    ax.legend(loc="best", fontsize=9)
    title = summary.get("title", os.path.basename(os.path.abspath(run)))
    ax.set_title("\n".join(textwrap.wrap(f"{title}: fragment sizes", 70)), fontsize=10)
    kp.save_figure(fig, run, "fragments.png")


if __name__ == "__main__":
    main()
