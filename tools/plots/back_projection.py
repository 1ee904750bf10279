#!/usr/bin/env python3
"""Back-projection of the fragments of a Kessler run: every point drawn where it was at the
first output (t = 0), coloured by the fragment it ends in, broken material (free particles,
eroded debris) in grey. It shows which original material becomes which fragment.

    python3 tools/plots/back_projection.py RUN_DIR [--largest N]

Reads RUN_DIR/fragment_points.csv (id, fragment rank; 0 = broken), RUN_DIR/fragments.csv and
the first point output (positions and ids), and writes RUN_DIR/plots/back_projection.png: a
slice one point thick through the bodies' centres, in the plane of the shot and of the
largest spread across it, and the same points seen along the shot. The N largest fragments
(default 10) have their own colours; the other fragments share a sand colour.
"""
import argparse
import csv
import os
import sys
import textwrap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kessler_plots as kp  # noqa: E402

AXIS_NAMES = "xyz"


def read_labels(run):
    path = os.path.join(run, "fragment_points.csv")
    if not os.path.exists(path):
        kp.fail(f"'{path}' does not exist (the run writes it when its analysis runs)")
    ids, labels = [], []
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames != ["id", "fragment"]:
            kp.fail(f"'{path}' has columns {reader.fieldnames}, expected id, fragment")
        for row in reader:
            ids.append(int(row["id"]))
            labels.append(int(row["fragment"]))
    return ids, labels


def read_first(path):
    """Positions, ids, bodies and velocities of one point output."""
    import h5py
    import numpy as np
    with h5py.File(path, "r") as h5:
        if "points/id" not in h5:
            kp.fail(f"'{path}' has no points/id")
        x = np.asarray(h5["points/position"], dtype=float).reshape(-1, 3)
        ids = np.asarray(h5["points/id"], dtype=np.int64)
        body = np.asarray(h5["points/body"], dtype=int)
        v = np.asarray(h5["points/velocity"], dtype=float).reshape(-1, 3)
    return x, ids, body, v


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run", help="run folder (holds fragment_points.csv and the outputs)")
    parser.add_argument("--largest", type=int, default=10, help="fragments with a colour of their own (at most 10)")
    args = parser.parse_args()
    kp.require_modules("numpy", "matplotlib", "h5py")
    import matplotlib.pyplot as plt
    import numpy as np

    run = kp.run_dir(args.run)
    label_ids, labels = read_labels(run)
    outputs = kp.point_outputs(run)
    x, ids, body, v = read_first(outputs[0][2])
    fragment_of = dict(zip(label_ids, labels))
    missing = [i for i in ids[:1000] if int(i) not in fragment_of]
    if missing:
        kp.fail(f"point {missing[0]} of the first output is not in fragment_points.csv (another run's files?)")
    label = np.array([fragment_of[int(i)] for i in ids])

    # The shot: the axis of the fastest body's mean velocity at t = 0; the slice plane holds it
    # and the axis of the largest spread across it.
    speeds = [np.linalg.norm(v[body == b].mean(axis=0)) for b in np.unique(body)]
    fastest = np.unique(body)[int(np.argmax(speeds))]
    shot = int(np.argmax(np.abs(v[body == fastest].mean(axis=0))))
    across = [a for a in range(3) if a != shot]
    spread = [np.ptp(x[:, a]) for a in across]
    wide, normal = (across[0], across[1]) if spread[0] >= spread[1] else (across[1], across[0])
    # The middle of the bodies across the slice: a symmetry plane of a half or quarter model,
    # else the middle of their extent; of each body, the layer of points nearest it.
    centre = 0.0 if normal in kp.symmetry_axes(run) else 0.5 * (x[:, normal].min() + x[:, normal].max())
    in_slice = np.zeros(len(x), dtype=bool)
    for b in np.unique(body):
        mine = body == b
        layer = x[mine, normal][np.argmin(np.abs(x[mine, normal] - centre))]
        # Within 0.45 of the body's mean spacing (from its box, which overestimates it): one layer of
        # a lattice, a slab one point thick of a tet mesh's barycentres.
        spacing = np.cbrt(np.prod(np.maximum(np.ptp(x[mine], axis=0), 1e-12)) / mine.sum())
        in_slice |= mine & (np.abs(x[:, normal] - layer) < 0.45 * spacing)
    sizes, _ = np.histogram(label[label > 0], bins=np.arange(1, label.max() + 2)) if label.max() > 0 else ([], None)
    order = np.argsort(-np.asarray(sizes), kind="stable")[:min(args.largest, 10)] + 1 if len(sizes) else []
    palette = plt.get_cmap("tab10")
    colours = np.tile(np.array([0.93, 0.87, 0.60, 1.0]), (len(x), 1))  # smaller fragments: sand
    colours[label == 0] = (0.55, 0.55, 0.55, 1.0)  # broken
    for k, f in enumerate(order):
        colours[label == f] = palette(k % 10)

    fig, axes = plt.subplots(1, 2, figsize=(12, 5.5), constrained_layout=True)
    marker = max(0.5, min(12.0, 2.0e4 / max(in_slice.sum(), 1)))
    ax = axes[0]
    ax.scatter(x[in_slice, shot] * 1e3, x[in_slice, wide] * 1e3, s=marker, c=colours[in_slice], marker="s",
               linewidths=0)
    ax.set_xlabel(f"{AXIS_NAMES[shot]} at t = 0 (mm)")
    ax.set_ylabel(f"{AXIS_NAMES[wide]} at t = 0 (mm)")
    ax.set_title(f"each body's layer of points nearest {AXIS_NAMES[normal]} = {centre * 1e3:.0f} mm", fontsize=9)
    ax.set_aspect("equal")
    ax = axes[1]
    # The same points where they are at the last output.
    xe, ide, _, _ = read_first(outputs[-1][2])
    where = {int(i): k for k, i in enumerate(ide)}
    chosen = [where.get(int(i), -1) for i in ids[in_slice]]
    found = np.array([k >= 0 for k in chosen])
    end = xe[[k for k in chosen if k >= 0]]
    ax.scatter(end[:, shot] * 1e3, end[:, wide] * 1e3, s=marker / 2, c=colours[in_slice][found], marker="s",
               linewidths=0)
    ax.set_xlabel(f"{AXIS_NAMES[shot]} at t = {outputs[-1][0] * 1e6:.0f} us (mm)")
    ax.set_ylabel(f"{AXIS_NAMES[wide]} at t = {outputs[-1][0] * 1e6:.0f} us (mm)")
    ax.set_title("the same points at the last output", fontsize=9)
    ax.set_aspect("equal")
    broken = (label == 0).mean() * 100.0 if len(label) else 0.0
    fragments = int(label.max()) if len(label) else 0
    summary = kp.load_summary(run)
    title = summary.get("title", os.path.basename(os.path.abspath(run)))
    fig.suptitle("\n".join(textwrap.wrap(
        f"{title}: back-projection of the {fragments} final fragments "
        f"(the {len(order)} largest coloured, the others sand), {broken:.0f}% of the points broken (grey)",
        110)), fontsize=10)
    kp.save_figure(fig, run, "back_projection.png")


if __name__ == "__main__":
    main()
