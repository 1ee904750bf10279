#!/usr/bin/env bash
# `kessler limit` on a short case (docs/analysis.md §12): the sphere-plate example at 1 mm and 1 km/s
# over diameters 2-8 mm in steps of 4 mm. Checked: the 8 mm sphere perforates the 2 mm plate and the
# 2 mm sphere does not (so the bisection runs), the bracket it reports is no wider than the step and
# lies between those, limit.csv and trials.csv agree on the number of runs, and Christiansen's (here
# Cour-Palais's single-wall) critical diameter is written beside it. The physics of the answer is a
# study (docs/validation.md), not this test.
set -euo pipefail
kessler=$1 python=$2 deck=$3 out=$4
rm -rf "$out"
"$kessler" limit "$deck" --speeds 1 --min 2 --max 8 --step 4 --out "$out" \
  --set bodies.0.mesh_size="1 mm" --set bodies.1.mesh_size="1 mm" --set solver.end_time="2 us"
"$python" - "$out" <<'PY'
import csv, os, sys
out = sys.argv[1]
limits = list(csv.DictReader(open(os.path.join(out, "limit.csv"))))
trials = list(csv.DictReader(open(os.path.join(out, "trials.csv"))))
assert len(limits) == 1, limits
row = limits[0]
held, failed, critical = float(row["held_m"]), float(row["failed_m"]), float(row["critical_diameter_m"])
print(f"limit: holds at {held*1e3:.2f} mm, fails at {failed*1e3:.2f} mm, critical {critical*1e3:.2f} mm, "
      f"{row['runs']} runs; equation {float(row['christiansen_m'])*1e3:.2f} mm")
assert 2e-3 - 1e-12 <= held < failed <= 8e-3 + 1e-12, row
assert failed - held <= 4e-3 + 1e-12, row
assert abs(critical - 0.5 * (held + failed)) < 1e-12, row
assert int(row["runs"]) == len(trials), (row, len(trials))
assert float(row["christiansen_m"]) > 0, row
by_diameter = {round(float(t["diameter_m"]), 9): t for t in trials}
assert by_diameter[round(held, 9)]["failed"] == "0" and by_diameter[round(failed, 9)]["failed"] == "1", trials
print("kessler limit: ok")
PY
