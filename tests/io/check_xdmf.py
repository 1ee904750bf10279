#!/usr/bin/env python3
"""Checks that XDMF files written by Kessler are consistent with the HDF5 files they reference.

For every file given: the XML parses, the root is <Xdmf> with a Domain holding a temporal
collection of Uniform grids, each with a Time, a Polyvertex topology and an XYZ geometry;
every <DataItem Format="HDF"> names a relative path to an existing HDF5 file and an existing
dataset whose shape equals Dimensions and whose type matches NumberType and Precision, and
whose first dimension equals the grid's NumberOfElements. Prints every problem and exits 1 if
there is one, 0 otherwise.

Usage: check_xdmf.py RUN_DIR/points.xdmf RUN_DIR/nodes.xdmf ...
"""
import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

# XDMF NumberType -> numpy dtype kind.
KINDS = {"Float": "f", "Int": "i", "UInt": "u", "Char": "i", "UChar": "u"}


def check_data_item(item, base, vertices, where, problems):
    if item.get("Format") != "HDF":
        problems.append(f"{where}: DataItem is not Format=\"HDF\"")
        return
    dims = tuple(int(d) for d in item.get("Dimensions", "").split())
    number_type = item.get("NumberType", "Float")
    precision = int(item.get("Precision", "4"))
    reference = (item.text or "").strip()
    if ":" not in reference:
        problems.append(f"{where}: '{reference}' is not FILE:/DATASET")
        return
    file_name, dataset_name = reference.split(":", 1)
    if os.path.isabs(file_name):
        problems.append(f"{where}: '{file_name}' is an absolute path")
    path = os.path.join(base, file_name)
    if not os.path.isfile(path):
        problems.append(f"{where}: HDF5 file '{path}' does not exist")
        return
    with h5py.File(path, "r") as h5:
        if dataset_name not in h5 or not isinstance(h5[dataset_name], h5py.Dataset):
            problems.append(f"{where}: no dataset '{dataset_name}' in '{path}'")
            return
        dataset = h5[dataset_name]
        if dataset.shape != dims:
            problems.append(f"{where}: '{reference}' has shape {dataset.shape}, XDMF says {dims}")
        if not dims or dims[0] != vertices:
            problems.append(f"{where}: '{reference}' has {dims[:1]} rows for {vertices} vertices")
        dtype = np.dtype(dataset.dtype)
        if KINDS.get(number_type) != dtype.kind or dtype.itemsize != precision:
            problems.append(f"{where}: '{reference}' is {dtype}, XDMF says {number_type} {precision}")


def check_file(xdmf_path, problems):
    base = os.path.dirname(os.path.abspath(xdmf_path))
    try:
        root = ET.parse(xdmf_path).getroot()
    except (ET.ParseError, OSError) as error:
        problems.append(f"{xdmf_path}: cannot parse: {error}")
        return 0
    if root.tag != "Xdmf" or root.get("Version") not in ("2.0", "3.0"):
        problems.append(f"{xdmf_path}: root is <{root.tag} Version={root.get('Version')}>, not <Xdmf> 2 or 3")
    collection = root.find("Domain/Grid")
    if collection is None or collection.get("GridType") != "Collection" \
            or collection.get("CollectionType") != "Temporal":
        problems.append(f"{xdmf_path}: Domain does not hold a temporal collection")
        return 0
    times = []
    for index, grid in enumerate(collection.findall("Grid")):
        where = f"{xdmf_path}: grid {index} ({grid.get('Name')})"
        time = grid.find("Time")
        topology = grid.find("Topology")
        geometry = grid.find("Geometry")
        if grid.get("GridType") != "Uniform" or time is None or topology is None or geometry is None:
            problems.append(f"{where}: not a Uniform grid with Time, Topology and Geometry")
            continue
        times.append(float(time.get("Value")))
        if topology.get("TopologyType") != "Polyvertex" or topology.get("NodesPerElement") != "1":
            problems.append(f"{where}: topology is not Polyvertex with one node per element")
        if geometry.get("GeometryType") != "XYZ":
            problems.append(f"{where}: geometry is not XYZ")
        vertices = int(topology.get("NumberOfElements", "-1"))
        # One vertex cell per point: without them ParaView's Xdmf3 readers draw nothing.
        cells = topology.findall("DataItem")
        if len(cells) != 1:
            problems.append(f"{where}: the Polyvertex topology names no vertex cells (a DataItem)")
        items = [(f"{where} geometry", item) for item in geometry.findall("DataItem")]
        items += [(f"{where} topology", item) for item in cells]
        for attribute in grid.findall("Attribute"):
            if attribute.get("Center") != "Node":
                problems.append(f"{where}: attribute {attribute.get('Name')} is not Center=\"Node\"")
            items += [(f"{where} attribute {attribute.get('Name')}", item)
                      for item in attribute.findall("DataItem")]
        for item_where, item in items:
            check_data_item(item, base, vertices, item_where, problems)
    if times != sorted(times):
        problems.append(f"{xdmf_path}: times {times} are not increasing")
    return len(times)


def main(argv):
    if len(argv) < 2:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    problems = []
    for xdmf_path in argv[1:]:
        grids = check_file(xdmf_path, problems)
        print(f"{xdmf_path}: {grids} time steps")
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
