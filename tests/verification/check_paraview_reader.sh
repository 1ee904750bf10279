#!/usr/bin/env bash
# ParaView is the reader the outputs are for. A short impact run, then with ParaView itself:
#  - its own XDMF readers see every time, point, vertex cell and array as the HDF5 files hold them
#    (tests/io/check_paraview.py);
#  - the run's kessler.pvsm loads, names this run's points.xdmf and shows the last output;
#  - `kessler render` draws a picture of the given size that is not empty.
set -euo pipefail
kessler=$1 pvpython=$2 python=$3 deck=$4 out=$5
rm -rf "$out"
"$kessler" run "$deck" --out "$out" --quiet --set solver.end_time="2 us" --set output.every="1 us" \
  --set bodies.0.mesh_size="1.5 mm" --set bodies.1.mesh_size="1.5 mm"
"$pvpython" "$(dirname "$0")/../io/check_paraview.py" "$out"

test -f "$out/kessler.pvsm" || { echo "no kessler.pvsm in $out (see $out/plots/paraview.log)"; exit 1; }
"$pvpython" - "$out" <<'PY'
import os, sys
from paraview.simple import GetActiveView, GetSources, LoadState
run = os.path.abspath(sys.argv[1])
LoadState(os.path.join(run, "kessler.pvsm"))
files = [p.FileName for p in GetSources().values() if hasattr(p, "FileName")]
assert [os.path.join(run, "points.xdmf")] in [list(f) for f in files], files
assert abs(GetActiveView().ViewTime - 2e-6) < 1e-12, GetActiveView().ViewTime
print("kessler.pvsm ok: loads", files[0][0], "at t =", GetActiveView().ViewTime)
PY

"$kessler" render "$out" --time 1e-6 --color temperature --size 320 240
"$python" - "$out/pictures" <<'PY'
import glob, sys
import matplotlib.image as image
import numpy as np
files = glob.glob(sys.argv[1] + "/temperature_*.png")
assert len(files) == 1, files
picture = image.imread(files[0])
assert picture.shape[:2] == (240, 320), picture.shape
# Not a blank view: many colours, and some pixels far from the white background.
colours = len(np.unique(picture.reshape(-1, picture.shape[2]), axis=0))
drawn = np.mean(np.any(picture[:, :, :3] < 0.8, axis=2))
assert colours > 20 and drawn > 0.02, (colours, drawn)
print(f"render ok: {files[0]}, {colours} colours, {100 * drawn:.0f}% of it drawn")
PY
