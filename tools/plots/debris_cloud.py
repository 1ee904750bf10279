#!/usr/bin/env python3
"""Side views of the debris cloud: the material points at every output time of a Kessler run,
in two orthogonal projections that both contain the impact axis, coloured by body (eroded points
lighter), equal aspect, axes in mm.

    python3 tools/plots/debris_cloud.py RUN_DIR [--every N] [--no-mirror]

Writes RUN_DIR/plots/debris_cloud_<step>.png for each output and debris_cloud_final.png. The
impact axis is the direction of the largest mean body velocity at the first output; a half or
quarter model (deck `symmetry:`) is mirrored to show the whole event.
"""
import argparse
import concurrent.futures
import os
import shutil
import sys
import textwrap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kessler_plots as kp  # noqa: E402

AXIS_NAMES = "xyz"


def impact_axis(x, v, body):
    """Axis (0-2) of the fastest body's mean velocity."""
    import numpy as np
    best, axis = -1.0, 2
    for b in np.unique(body):
        mean = v[body == b].mean(axis=0)
        speed = np.linalg.norm(mean)
        if speed > best:
            best, axis = speed, int(np.argmax(np.abs(mean)))
    return axis if best > 0 else 2


def first_velocity(path):
    import h5py
    import numpy as np
    with h5py.File(path, "r") as h5:
        return np.asarray(h5["points/velocity"], dtype=float).reshape(-1, 3)


def view_limits(frames):
    """Common limits of all frames (robust: 0.05-99.95 percentiles, 5 % margin), in mm."""
    import numpy as np
    lo = np.full(3, np.inf)
    hi = np.full(3, -np.inf)
    for x in frames:
        lo = np.minimum(lo, np.percentile(x, 0.05, axis=0))
        hi = np.maximum(hi, np.percentile(x, 99.95, axis=0))
    span = np.maximum(hi - lo, 1e-9)
    return (lo - 0.05 * span) * 1e3, (hi + 0.05 * span) * 1e3


def draw(job):
    """One picture: the two side views of one output (a separate process per picture)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    x, body, eroded = job["x"], job["body"], job["eroded"]
    axis, across, lo, hi, names = job["axis"], job["across"], job["lo"], job["hi"], job["names"]
    colours = plt.get_cmap("tab10")
    spans = [(hi[h] - lo[h], hi[axis] - lo[axis]) for h in across]
    height = min(9.0, max(2.5, 5.5 * max(v / h for h, v in spans))) + 1.3
    fig, views = plt.subplots(1, 2, figsize=(12, height), constrained_layout=True)
    size = max(0.2, min(6.0, 2e4 / max(len(x), 1)))
    for view, horizontal in zip(views, across):
        for b in job["bodies"]:
            label = names[b] if b < len(names) else f"body {b}"
            colour = colours(b % 10)
            intact = (body == b) & ~eroded
            broken = (body == b) & eroded
            view.scatter(x[intact, horizontal] * 1e3, x[intact, axis] * 1e3, s=size, color=colour,
                         linewidths=0, label=label, rasterized=True)
            if broken.any():
                view.scatter(x[broken, horizontal] * 1e3, x[broken, axis] * 1e3, s=size, color=colour,
                             alpha=0.3, linewidths=0, label=f"{label} (eroded)", rasterized=True)
        view.set_xlim(lo[horizontal], hi[horizontal])
        view.set_ylim(lo[axis], hi[axis])
        view.set_aspect("equal")
        view.set_xlabel(f"{AXIS_NAMES[horizontal]} (mm)")
        view.set_ylabel(f"{AXIS_NAMES[axis]} (mm)")
        view.set_title(f"{AXIS_NAMES[horizontal]}-{AXIS_NAMES[axis]} view")
        view.grid(True, linewidth=0.3, alpha=0.5)
    # A fixed corner: loc="best" scans every scatter point and took most of the drawing time.
    views[1].legend(loc="upper right", markerscale=max(1.0, 12.0 / size), fontsize=8)
    fig.suptitle("\n".join(textwrap.wrap(f"{job['title']}: t = {job['time'] * 1e6:.2f} µs", 110)))
    fig.savefig(job["path"], dpi=110)
    plt.close(fig)
    return job["path"]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run", help="run folder (holds points.xdmf and fields/)")
    parser.add_argument("--every", type=int, default=1, help="plot every N-th output (default 1)")
    parser.add_argument("--no-mirror", action="store_true", help="show a half model as simulated")
    args = parser.parse_args()
    kp.require_modules("numpy", "matplotlib", "h5py")
    import numpy as np

    run = kp.run_dir(args.run)
    outputs = kp.point_outputs(run)
    summary = kp.load_summary(run)
    names = kp.body_names(summary)
    sym = [] if args.no_mirror else kp.symmetry_axes(run)
    selected = outputs[::max(args.every, 1)]
    if selected[-1] != outputs[-1]:
        selected.append(outputs[-1])

    frames = []
    for _, _, path in selected:
        frames.append(kp.mirror(*kp.read_points(path), sym))
    x0, body0, _ = kp.read_points(selected[0][2])
    axis = impact_axis(x0, first_velocity(selected[0][2]), body0)
    across = [a for a in range(3) if a != axis]
    lo, hi = view_limits([f[0] for f in frames])
    bodies = sorted({int(b) for f in frames for b in np.unique(f[1])})
    out = kp.plots_dir(run)

    title = summary.get("title", os.path.basename(os.path.abspath(run)))
    jobs = [dict(time=time, path=os.path.join(out, f"debris_cloud_{step:08d}.png"), x=x, body=body, eroded=eroded,
                 axis=axis, across=across, lo=lo, hi=hi, bodies=bodies, names=names, title=title)
            for (time, step, _), (x, body, eroded) in zip(selected, frames)]
    # One picture per process, as many at once as there are cores: matplotlib draws on one.
    with concurrent.futures.ProcessPoolExecutor(max_workers=max(1, min(len(jobs), os.cpu_count() or 1))) as pool:
        written = list(pool.map(draw, jobs))
    shutil.copyfile(written[-1], os.path.join(out, "debris_cloud_final.png"))
    print(f"debris_cloud.py: wrote {len(written)} pictures to {out}")


if __name__ == "__main__":
    main()
