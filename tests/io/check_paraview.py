"""Opens a run's points.xdmf and nodes.xdmf with ParaView's own readers and checks what ParaView sees
against the run's HDF5 files: the output times, one vertex cell per point (ParaView draws nothing
without cells), every field array, and the values of position and of one field at every time.

Run with ParaView's Python: pvpython tests/io/check_paraview.py RUN_DIR
"""

import os
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy
from paraview import servermanager
from paraview.simple import XDMFReader, Xdmf3ReaderS
from vtk.util.numpy_support import vtk_to_numpy


def xdmf_frames(path):
    """[(time, h5 file, group)] of each grid, and the attribute names, from the XDMF itself."""
    frames, names = [], []
    for grid in ET.parse(path).getroot().iter("Grid"):
        if grid.get("GridType") != "Uniform":
            continue
        source = grid.find("Geometry/DataItem").text.strip()
        file, dataset = source.split(":", 1)
        frames.append((float(grid.find("Time").get("Value")), os.path.join(os.path.dirname(path), file),
                       dataset.rsplit("/", 1)[0]))
        names = [a.get("Name") for a in grid.findall("Attribute")]
    return frames, names


def check(path, reader_name, make_reader, problems):
    frames, names = xdmf_frames(path)
    reader = make_reader(path)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues)
    where = f"{os.path.basename(path)} ({reader_name})"
    if not numpy.allclose(times, [t for t, _, _ in frames], rtol=1e-12, atol=0):
        problems.append(f"{where}: ParaView's times {times} are not the XDMF's")
        return
    for time, file, group in frames:
        reader.UpdatePipeline(time)
        data = servermanager.Fetch(reader)
        if data.IsA("vtkMultiBlockDataSet"):
            data = data.GetBlock(0)
        with h5py.File(file, "r") as h5:
            position = h5[group + "/position"][()]
            n = position.shape[0]
            if data.GetNumberOfPoints() != n or data.GetNumberOfCells() != n:
                problems.append(f"{where} t = {time:.4g}: {data.GetNumberOfPoints()} points and "
                                f"{data.GetNumberOfCells()} cells, the run wrote {n} points")
                continue
            seen = vtk_to_numpy(data.GetPoints().GetData())
            if not numpy.array_equal(seen, position):
                problems.append(f"{where} t = {time:.4g}: positions differ from the HDF5's")
            arrays = data.GetPointData()
            for name in names:
                array = arrays.GetArray(name)
                if array is None:
                    problems.append(f"{where} t = {time:.4g}: no array '{name}'")
                    continue
                values = vtk_to_numpy(array)
                if not numpy.array_equal(values.reshape(h5[group + "/" + name].shape), h5[group + "/" + name][()]):
                    problems.append(f"{where} t = {time:.4g}: array '{name}' differs from the HDF5's")
    print(f"{where}: {len(frames)} times, {len(names)} arrays checked")


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip().splitlines()[-1], file=sys.stderr)
        return 2
    problems = []
    for name in ("points.xdmf", "nodes.xdmf"):
        path = os.path.join(argv[1], name)
        # Xdmf3ReaderS is ParaView's reader for .xdmf files; XDMFReader the older one, still offered.
        check(path, "Xdmf3ReaderS", lambda p: Xdmf3ReaderS(FileName=[p]), problems)
        check(path, "XDMFReader", lambda p: XDMFReader(FileNames=[p]), problems)
    for problem in problems:
        print(problem, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
