#!/usr/bin/env python3
"""tools/plots/residual_velocity.py on three synthetic runs whose answer is known: a projectile of
2 kg (1 kg per half model) flying at 45 degrees in the y-z plane at 600, 1000 and 1500 m/s; the
first two runs hold, the third perforates and its projectile ends at 900 m/s along its flight. The
script must report v_r = 0, 0 and 900 m/s, bracket v_bl in (1000, 1500] and give a = 2 / (2 + 0.5).

    check_residual_velocity.py SCRIPT WORK_DIR
"""
import csv
import json
import math
import os
import subprocess
import sys

import h5py
import numpy as np

script, work = sys.argv[1], sys.argv[2]
os.makedirs(work, exist_ok=True)
direction = np.array([0.0, math.sqrt(0.5), -math.sqrt(0.5)])
runs = []
for speed, end_speed, verdict in ((600.0, 40.0, "detached_spall"), (1000.0, 300.0, "bulge"),
                                  (1500.0, 900.0, "perforation")):
    run = os.path.join(work, f"run-{speed:.0f}")
    os.makedirs(os.path.join(run, "fields"), exist_ok=True)
    summary = {"problem": {"bodies": [{"name": "plate"}, {"name": "rod"}]},
               "analysis": {"ballistic_limit": {"impact_speed_m_per_s": speed, "simulated": verdict},
                            "breakup_model": {"projectile_mass_kg": 2.0}}}
    with open(os.path.join(run, "summary.json"), "w", encoding="utf-8") as f:
        json.dump(summary, f)
    for step, (time, v) in enumerate(((0.0, speed), (1e-5, 0.5 * (speed + end_speed)), (2e-5, end_speed))):
        # The plate's points at rest, the rod's two points of unequal mass with unequal speeds whose
        # mass-weighted mean is v along the flight (and a sideways part that cancels).
        body = np.array([0, 0, 1, 1], dtype=np.int32)
        density = np.full(4, 1000.0)
        volume = np.array([1e-3, 1e-3, 0.75e-3, 0.25e-3])
        side = np.array([1.0, 0.0, 0.0])
        velocity = np.zeros((4, 3))
        velocity[2] = (v - 100.0) * direction + 10.0 * side
        velocity[3] = (v + 300.0) * direction - 30.0 * side
        with h5py.File(os.path.join(run, "fields", f"fields_{step:08d}.h5"), "w") as h5:
            h5.attrs["time"] = time
            h5.attrs["step"] = step
            h5["points/body"] = body
            h5["points/density"] = density
            h5["points/volume"] = volume
            h5["points/velocity"] = velocity
            h5["points/position"] = np.zeros((4, 3))
    runs.append(run)

out = os.path.join(work, "sweep")
printed = subprocess.run([sys.executable, script, *runs, "--projectile", "rod", "--plug-mass", "0.5", "--out", out],
                         check=True, capture_output=True, text=True).stdout
print(printed)
failures = []
with open(os.path.join(out, "residual_velocity.csv"), newline="", encoding="utf-8") as f:
    rows = list(csv.DictReader(f))
expected = {600.0: 0.0, 1000.0: 0.0, 1500.0: 900.0}
for row in rows:
    speed, residual = float(row["impact_speed_m_per_s"]), float(row["residual_m_per_s"])
    if abs(residual - expected[speed]) > 1e-6 * 1500.0:
        failures.append(f"v = {speed:.0f} m/s: residual {residual} m/s, expected {expected[speed]}")
if "a = m_p / (m_p + m_plug) = 0.800" not in printed:
    failures.append("a is not 2 / (2 + 0.5) = 0.800")
if "simulated v_bl in (1000, 1500] m/s" not in printed:
    failures.append("v_bl is not bracketed in (1000, 1500]")
if not os.path.exists(os.path.join(out, "plots", "residual_velocity.png")):
    failures.append("plots/residual_velocity.png was not drawn")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
