"""A run folder as Python values: kessler.Results (docs/python.md).

Fields are read from the run's HDF5 files only when asked for; the output times come from
points.xdmf and nodes.xdmf, the files ParaView opens.
"""

import csv
import json
import os
import xml.etree.ElementTree as ElementTree


def _series(xdmf):
    """[(time, {field: (h5 file, dataset)})] of one XDMF temporal collection."""
    frames = []
    if not os.path.exists(xdmf):
        return frames
    folder = os.path.dirname(xdmf)
    for grid in ElementTree.parse(xdmf).getroot().iter("Grid"):
        if grid.get("GridType") != "Uniform":
            continue
        fields = {}
        for item_parent in list(grid.findall("Geometry")) + list(grid.findall("Attribute")):
            item = item_parent.find("DataItem")
            file, dataset = item.text.strip().split(":", 1)
            name = "position" if item_parent.tag == "Geometry" else item_parent.get("Name")
            fields[name] = (os.path.join(folder, file), dataset)
        frames.append((float(grid.find("Time").get("Value")), fields))
    return frames


class Frame:
    """The fields of one output time, a read-only mapping of name -> numpy array, each read from
    the HDF5 file on first access: frame["pressure"], frame["position"] (n x 3), list(frame)."""

    def __init__(self, time, fields):
        self.time = time
        self._fields = fields
        self._cache = {}

    def __getitem__(self, name):
        if name not in self._cache:
            if name not in self._fields:
                raise KeyError(f"no field '{name}' at t = {self.time:.6g} s (fields: {', '.join(self._fields)})")
            import h5py
            import numpy
            file, dataset = self._fields[name]
            with h5py.File(file, "r") as f:
                self._cache[name] = numpy.asarray(f[dataset][()])
        return self._cache[name]

    def __iter__(self):
        return iter(self._fields)

    def __len__(self):
        return len(self._fields)

    def __contains__(self, name):
        return name in self._fields

    def keys(self):
        return self._fields.keys()

    def __repr__(self):
        return f"<kessler.Frame t = {self.time:.6g} s: {', '.join(self._fields)}>"


def _table(path):
    """A CSV file with a header row as a numpy structured array (numbers as float, text as str)."""
    import numpy
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, body = rows[0], rows[1:]
    columns = []
    for i, name in enumerate(header):
        values = [r[i] for r in body]
        try:
            columns.append(numpy.array([float(v) for v in values], dtype=float))
        except ValueError:
            columns.append(numpy.array(values, dtype=str))
    dtype = [(name, c.dtype if c.dtype.kind != "U" else f"U{max(1, c.dtype.itemsize // 4)}")
             for name, c in zip(header, columns)]
    table = numpy.zeros(len(body), dtype=dtype)
    for name, c in zip(header, columns):
        table[name] = c
    return table


class Results:
    """A run folder: Results("results/sphere-plate") or what kessler.run returns.

    summary, analysis    summary.json and its "analysis" object, as dicts ({} while the run goes on)
    status               "completed", "interrupted", "stopped" or "failed"; None while it goes on
    times                the output times (s) of the point fields
    points(i), nodes(i)  the fields at output i (negative counts from the end), as a Frame
    history              history.csv (step, time, energies, momentum) as a structured array
    fragments            fragments.csv (one row per fragment, largest first) as a structured array
    deck                 the resolved deck's text (deck.resolved.yaml)
    """

    def __init__(self, folder):
        self.folder = os.fspath(folder)
        if not os.path.isfile(os.path.join(self.folder, "deck.resolved.yaml")):
            raise FileNotFoundError(f"{self.folder}: not a Kessler run folder (no deck.resolved.yaml)")
        self._points = None
        self._nodes = None

    def _path(self, name):
        return os.path.join(self.folder, name)

    @property
    def summary(self):
        """summary.json as a dict; {} for a run still going (it writes the summary at its end)."""
        path = self._path("summary.json")
        if not os.path.exists(path):
            return {}
        with open(path) as f:
            return json.load(f)

    @property
    def status(self):
        return self.summary.get("status")

    @property
    def analysis(self):
        """The impact analysis (docs/analysis.md §9); empty when the run has none."""
        return self.summary.get("analysis", {})

    @property
    def deck(self):
        with open(self._path("deck.resolved.yaml")) as f:
            return f.read()

    def _point_series(self):
        if self._points is None:
            self._points = _series(self._path("points.xdmf"))
        return self._points

    def _node_series(self):
        if self._nodes is None:
            self._nodes = _series(self._path("nodes.xdmf"))
        return self._nodes

    @property
    def times(self):
        import numpy
        return numpy.array([t for t, _ in self._point_series()])

    def points(self, i=-1):
        t, fields = self._point_series()[i]
        return Frame(t, fields)

    def nodes(self, i=-1):
        t, fields = self._node_series()[i]
        return Frame(t, fields)

    @property
    def history(self):
        return _table(self._path("history.csv"))

    @property
    def fragments(self):
        path = self._path("fragments.csv")
        if not os.path.exists(path):
            raise FileNotFoundError(f"{path}: this run has no fragment analysis")
        return _table(path)

    def __repr__(self):
        return f"<kessler.Results {self.folder}: {self.status}, {len(self._point_series())} outputs>"
