#!/usr/bin/env bash
# examples/python/velocity_sweep.py as a user runs it, shortened to two speeds and 1.5 us: the Python
# module drives the runs, and the CSV and the plot come out with one row per speed.
set -euo pipefail
python=$1 source=$2 out=$3
rm -rf "$out"
"$python" "$source/examples/python/velocity_sweep.py" --speeds 4 6 --end-time "1.5 us" --out "$out"
"$python" - "$out" <<'PY'
import csv, os, sys
rows = list(csv.DictReader(open(os.path.join(sys.argv[1], "sweep.csv"))))
assert [float(r["speed_km_per_s"]) for r in rows] == [4.0, 6.0], rows
# 1.5 us in, the projectile is through the bumper: a hole, and Christiansen's verdict beside it.
assert all(float(r["bumper_hole_mm"]) > 5.0 and float(r["christiansen_critical_mm"]) > 0 for r in rows), rows
assert os.path.getsize(os.path.join(sys.argv[1], "sweep.png")) > 10000
print("velocity_sweep.py ok:", [(r["speed_km_per_s"], r["bumper_hole_mm"], r["rear_wall"]) for r in rows])
PY
