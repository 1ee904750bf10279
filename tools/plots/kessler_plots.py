"""Shared helpers of Kessler's plotting scripts: imports that work without a display, the run
folder's layout (points.xdmf + fields/*.h5, summary.json, deck.resolved.yaml) and body names.

The scripts need numpy, matplotlib and h5py (Debian: python3-numpy python3-matplotlib
python3-h5py). When the interpreter that runs them lacks one, they re-run themselves once under
/usr/bin/python3, which has them on the project's machines.
"""
import json
import os
import sys
import xml.etree.ElementTree as ElementTree

SYSTEM_PYTHON = "/usr/bin/python3"


def require_modules(*names):
    """Imports the modules (matplotlib with the Agg backend) or re-runs the script under the
    system Python, or exits with a message that says what to install."""
    missing = []
    for name in names:
        try:
            __import__(name)
        except ImportError:
            missing.append(name)
    if missing:
        if (os.path.exists(SYSTEM_PYTHON) and not os.environ.get("KESSLER_PLOTS_REEXEC")
                and os.path.realpath(sys.executable) != os.path.realpath(SYSTEM_PYTHON)):
            os.environ["KESSLER_PLOTS_REEXEC"] = "1"
            os.execv(SYSTEM_PYTHON, [SYSTEM_PYTHON] + sys.argv)
        packages = " ".join("python3-" + m for m in missing)
        sys.exit(f"{os.path.basename(sys.argv[0])}: error: missing Python module(s) {', '.join(missing)} "
                 f"(install them, e.g. apt-get install {packages})")
    if "matplotlib" in names:
        import matplotlib
        matplotlib.use("Agg")  # no display on clusters and in CI


def fail(message):
    sys.exit(f"{os.path.basename(sys.argv[0])}: error: {message}")


def run_dir(path):
    if not os.path.isdir(path):
        fail(f"'{path}' is not a run folder")
    return path


def plots_dir(run):
    out = os.path.join(run, "plots")
    os.makedirs(out, exist_ok=True)
    return out


def save_figure(fig, run, name):
    """Writes fig as RUN/plots/NAME at the scripts' resolution, closes it and says where."""
    import matplotlib.pyplot as plt
    out = os.path.join(plots_dir(run), name)
    fig.savefig(out, dpi=120)
    plt.close(fig)
    print(f"{os.path.basename(sys.argv[0])}: wrote {out}")


def load_summary(run):
    """summary.json as a dict, or {} when absent."""
    path = os.path.join(run, "summary.json")
    if not os.path.exists(path):
        return {}
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def body_names(summary):
    bodies = summary.get("problem", {}).get("bodies", [])
    return [b.get("name", f"body {i}") for i, b in enumerate(bodies)]


def symmetry_axes(run):
    """Axes (0, 1, 2) of the deck's symmetry planes, from deck.resolved.yaml; [] if unknown."""
    path = os.path.join(run, "deck.resolved.yaml")
    if not os.path.exists(path):
        return []
    try:
        import yaml
    except ImportError:
        return []
    with open(path, encoding="utf-8") as f:
        deck = yaml.safe_load(f) or {}
    names = {"x": 0, "y": 1, "z": 2}
    return [names[a] for a in deck.get("symmetry", []) or [] if a in names]


def point_outputs(run):
    """[(time, step, h5 path)] of the point outputs, in time order: from points.xdmf when it is
    there (the authority on which outputs are complete), else from fields/*.h5."""
    xdmf = os.path.join(run, "points.xdmf")
    outputs = []
    if os.path.exists(xdmf):
        root = ElementTree.parse(xdmf).getroot()
        for grid in root.iter("Grid"):
            if grid.get("GridType") != "Uniform":
                continue
            time = float(grid.find("Time").get("Value"))
            item = grid.find("Geometry/DataItem").text.strip()
            file = item.split(":")[0]
            step = int(grid.get("Name").rsplit("_", 1)[-1])
            outputs.append((time, step, os.path.join(run, file)))
    else:
        import glob
        import h5py
        for path in sorted(glob.glob(os.path.join(run, "fields", "fields_*.h5"))):
            with h5py.File(path, "r") as h5:
                outputs.append((float(h5.attrs["time"]), int(h5.attrs["step"]), path))
    outputs.sort()
    if not outputs:
        fail(f"no point outputs in '{run}' (expected points.xdmf or fields/fields_*.h5)")
    return outputs


def read_points(path):
    """Positions (n x 3, m), body ids and eroded flags of one output."""
    import h5py
    import numpy as np
    with h5py.File(path, "r") as h5:
        x = np.asarray(h5["points/position"], dtype=float).reshape(-1, 3)
        body = np.asarray(h5["points/body"], dtype=int)
        eroded = np.asarray(h5["points/eroded"], dtype=bool) if "points/eroded" in h5 else np.zeros(len(x), bool)
    return x, body, eroded


def mirror(x, body, eroded, axes):
    """The points together with their images in the symmetry planes."""
    import numpy as np
    for a in axes:
        image = x.copy()
        image[:, a] = -image[:, a]
        x = np.vstack([x, image])
        body = np.concatenate([body, body])
        eroded = np.concatenate([eroded, eroded])
    return x, body, eroded
