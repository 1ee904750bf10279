#!/usr/bin/env bash
# Runs an example deck for its first microseconds and checks what it wrote: summary.json has the
# problem size and a completed status, and the XDMF files match the HDF5 datasets. An optional
# fifth argument, "debris" or "no-debris", is what the impact analysis must say.
set -euo pipefail
kessler=$1 python=$2 deck=$3 out=$4 debris=${5:-}
rm -rf "$out"
"$kessler" run "$deck" --out "$out" --set solver.end_time="2 us" --set output.every="1 us"
"$python" - "$out" "$debris" <<'PY'
import json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
if sys.argv[2]:
    # Nothing breaks in an elastic impact: the analysis reports no debris, hole, cloud or verdict.
    a = s["analysis"]
    assert a["debris"] == (sys.argv[2] == "debris"), a["debris"]
    if not a["debris"]:
        assert a["debris_clouds"] == [] and a["holes"] == [] and "ballistic_limit" not in a, a
    print("analysis ok: debris", a["debris"])
assert s["status"] == "completed", s["status"]
assert s["problem"]["points"] > 0 and s["steps"] > 0, s
assert abs(s["simulated_time_s"] - 2e-6) < 1e-12, s["simulated_time_s"]
assert s["outputs"] == 3, s["outputs"]
print("summary.json ok:", s["problem"]["points"], "points,", s["steps"], "steps")
PY
"$python" "$(dirname "$0")/../io/check_xdmf.py" "$out/points.xdmf" "$out/nodes.xdmf"
