#!/usr/bin/env bash
# Regression: examples/sphere-plate.yaml (10 mm Al sphere, 2 mm Al plate, 6.18 km/s) at 0.7 mm
# (the 40 mm plate with free edges, to 4 us: a few seconds), its measurements checked against
# physics rather than pinned numbers (docs/validation.md):
#   - the plate is perforated: a hole is found on the shot line, and the rear-wall (here the
#     only plate) classification says perforation;
#   - the hole is at least as wide as the projectile (d = 10 mm) and at most 4 d: at t/d = 0.2 and
#     6 km/s aluminium holes measure D/d ~ 1.5-3 (Piekutowski 1996; Hill 2004), and a thin plate
#     cannot stop the sphere from punching its own diameter through;
#   - the debris cloud's leading edge behind the plate has moved at no more than 1.1 times the
#     impact speed (the cloud front of Al on Al at 6 km/s travels at ~0.9-0.95 v) and at least
#     0.5 times it (the sphere is only 20% decelerated by a plate of a fifth of its diameter);
#   - the cloud's bulk front speed (the axial speed 5% of its mass exceeds) lies between 0.5 and
#     1.0 times the impact speed: no faster than the free surface of a symmetric Al-on-Al impact
#     after release (2 u_p = v), no slower than the bound on the leading edge above;
#   - with free plate edges, momentum along the shot is conserved to 1% (contact and erosion
#     neither make nor lose momentum).
set -euo pipefail
kessler=$1 python=$2 deck=$3 out=$4
rm -rf "$out"
"$kessler" run "$deck" --out "$out" --quiet \
  --set bodies.0.mesh_size="0.7 mm" --set bodies.1.mesh_size="0.7 mm" \
  --set bodies.1.fixed=none --set solver.end_time="4 us" --set output.every="2 us" --set analysis.plots=false
"$python" - "$out/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
assert s["status"] == "completed", s["status"]
a = s["analysis"]
assert "error" not in a, a
d, v, t = 10e-3, 6180.0, s["simulated_time_s"]
gap = 0.2e-3      # the sphere starts 0.2 mm above the plate
failures = []
hole = a["holes"][0]
print(f"hole: found {hole['found']}, diameter {hole['diameter_m']*1e3:.2f} mm "
      f"(axes {hole['major_axis_m']*1e3:.2f} x {hole['minor_axis_m']*1e3:.2f} mm); bounds [{d*1e3:.0f}, {4*d*1e3:.0f}] mm")
if not hole["found"]:
    failures.append("no hole in the plate")
elif not (d <= hole["diameter_m"] <= 4 * d):
    failures.append(f"hole diameter {hole['diameter_m']*1e3:.2f} mm outside [{d*1e3:.0f}, {4*d*1e3:.0f}] mm")
wall = a["rear_wall"]["classification"]
print("plate classification:", wall)
if wall != "perforation":
    failures.append(f"the plate is classified '{wall}', not perforation")
cloud = [c for c in a["debris_clouds"] if c["body"] == "all"][0]
edge = cloud["leading_edge_m"]
flight = t - gap / v  # time since first contact
lo, hi = 0.5 * v * flight - 2e-3, 1.1 * v * flight  # the rear face is 2 mm below the front face
print(f"cloud leading edge {edge*1e3:.2f} mm behind the rear face at t = {t*1e6:.2f} us; bounds [{lo*1e3:.2f}, {hi*1e3:.2f}] mm")
if not (lo <= edge <= hi):
    failures.append(f"cloud leading edge {edge*1e3:.2f} mm outside [{lo*1e3:.2f}, {hi*1e3:.2f}] mm")
front = cloud["bulk_axial_speed_m_per_s"]
print(f"cloud bulk front speed {front:.0f} m/s = {front / v:.3f} v; bounds [0.5, 1.0] v")
if not (0.5 * v <= front <= v):
    failures.append(f"cloud bulk front speed {front:.0f} m/s outside [{0.5 * v:.0f}, {v:.0f}] m/s")
p0 = s["energy"]["initial"]["momentum_kg_m_s"][2]
p1 = s["energy"]["final"]["momentum_kg_m_s"][2]
print(f"momentum z: {p0:.6g} -> {p1:.6g} kg m/s")
if abs(p1 - p0) > 0.01 * abs(p0):
    failures.append(f"momentum along the shot changed by {100*abs(p1-p0)/abs(p0):.2f}% (> 1%)")
print("fragments:", a["fragments"]["count"])
if failures:
    print("FAIL: " + "; ".join(failures))
    sys.exit(1)
print("sphere-plate regression: ok")
PY
