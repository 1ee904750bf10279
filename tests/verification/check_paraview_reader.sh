#!/usr/bin/env bash
# A short impact run opened with ParaView's own readers (pvpython): times, vertex cells, every array
# and its values as the HDF5 files hold them (tests/io/check_paraview.py).
set -euo pipefail
kessler=$1 pvpython=$2 deck=$3 out=$4
rm -rf "$out"
"$kessler" run "$deck" --out "$out" --quiet --set solver.end_time="2 us" --set output.every="1 us" \
  --set bodies.0.mesh_size="1.5 mm" --set bodies.1.mesh_size="1.5 mm" --set analysis.plots=false
"$pvpython" "$(dirname "$0")/../io/check_paraview.py" "$out"
