#!/usr/bin/env bash
# Regression: examples/breakup-sphere-cube.yaml (a 1 m sphere and a 1 m cube at 0.2 g/cm^3 meeting
# at 15.2 km/s, SPH with the finite-element reconstruction) at 10 cm elements to 60 us (a few
# seconds), checked against answers that do not depend on the simulation's accuracy:
#   - the collision is analysed without plates, at the relative speed: the NASA breakup model's
#     reference mass is the two bodies' 304.72 kg (the lattice carries each shape's exact volume),
#     its specific energy m_sphere (15.2 km/s)^2 / (2 m_cube) = 60,486 J/g, catastrophic (> 40 J/g);
#   - mass: each body's fragments and broken material add up to its mass, to round-off;
#   - momentum: (104.72 - 200) kg x 7.6 km/s = -724,128 kg m/s along x (the quarter model's times
#     four) is conserved to 1e-9 of the bodies' momenta (no wall, no fixed face: pair forces, equal
#     and opposite, and their mirror images across the symmetry planes, which push along y and z);
#   - every point has a row in fragment_points.csv, whose fragment ranks agree with fragments.csv;
#   - the pictures are drawn when matplotlib is there (fragments.png with each body's curve,
#     back_projection.png).
set -euo pipefail
kessler=$1 python=$2 deck=$3 out=$4
rm -rf "$out"
"$kessler" run "$deck" --out "$out" --quiet \
  --set bodies.0.mesh_size="10 cm" --set bodies.1.mesh_size="10 cm" \
  --set solver.end_time="60 us" --set output.every="30 us"
"$python" - "$out" <<'PY'
import csv, json, os, sys
run = sys.argv[1]
s = json.load(open(os.path.join(run, "summary.json")))
assert s["status"] == "completed", s["status"]
a = s["analysis"]
assert "error" not in a, a
failures = []
model = a["breakup_model"]
m_sphere, m_cube, v = 104.72, 200.0, 15200.0
emr = 0.5 * m_sphere * v**2 / m_cube / 1000.0
print(f"NASA model: M = {model['reference_mass_kg']:.3f} kg (304.72), {model['specific_energy_J_per_g']:.1f} J/g "
      f"({emr:.1f}), catastrophic {model['catastrophic']}")
if abs(model["reference_mass_kg"] - (m_sphere + m_cube)) > 1e-3 * (m_sphere + m_cube):
    failures.append(f"reference mass {model['reference_mass_kg']} kg, not {m_sphere + m_cube} kg")
if abs(model["specific_energy_J_per_g"] - emr) > 1e-3 * emr:
    failures.append(f"specific energy {model['specific_energy_J_per_g']} J/g, not {emr:.1f}")
if not model["catastrophic"]:
    failures.append("not catastrophic")

rows = list(csv.DictReader(open(os.path.join(run, "fragments.csv"))))
f = a["fragments"]
for body, mass in (("sphere", m_sphere), ("cube", m_cube)):
    in_fragments = sum(float(r["mass_kg"]) * int(r["copies"]) for r in rows if r["body"] == body)
    broken = f["eroded_mass_kg"][body]
    total = f["body_mass_kg"][body]
    count = sum(int(r["copies"]) for r in rows if r["body"] == body)
    print(f"{body}: {count} fragments, {in_fragments:.4f} kg in fragments + {broken:.4f} kg broken = "
          f"{in_fragments + broken:.4f} kg of {total:.4f} kg ({mass})")
    if abs(in_fragments + broken - total) > 1e-9 * total:
        failures.append(f"{body}: fragments and broken material do not add up to the body's mass")
    if abs(total - mass) > 1e-3 * mass:
        failures.append(f"{body}: mass {total} kg, not {mass} kg")

# The momentum of the simulated part: a quarter of the whole (the symmetry planes y = 0, z = 0).
simulated = {b["name"]: b["mass_kg"] for b in s["problem"]["bodies"]}
images = f["body_mass_kg"]["cube"] / simulated["cube"]
p0 = s["energy"]["initial"]["momentum_kg_m_s"][0] * images
p1 = s["energy"]["final"]["momentum_kg_m_s"][0] * images
scale = (m_sphere + m_cube) * 7600.0
print(f"momentum x of the whole: {p0:.6f} -> {p1:.6f} kg m/s (expected {(m_sphere - m_cube) * 7600.0:.0f}; "
      f"{images:.0f} images)")
if abs(p0 - (m_sphere - m_cube) * 7600.0) > 1e-3 * scale:
    failures.append(f"initial momentum {p0} kg m/s")
if abs(p1 - p0) > 1e-9 * scale:
    failures.append(f"momentum changed by {p1 - p0:.3g} kg m/s")

points = list(csv.DictReader(open(os.path.join(run, "fragment_points.csv"))))
ranks = {int(p["fragment"]) for p in points}
if len(points) != s["problem"]["points"]:
    failures.append(f"fragment_points.csv has {len(points)} rows for {s['problem']['points']} points")
if ranks - set(range(len(rows) + 1)) or len(ranks - {0}) != len(rows):
    failures.append("fragment_points.csv's ranks do not match fragments.csv")

try:
    import matplotlib  # noqa: F401
    for picture in ("fragments.png", "back_projection.png"):
        if not os.path.exists(os.path.join(run, "plots", picture)):
            failures.append(f"plots/{picture} was not drawn (see plots/plots.log)")
except ImportError:
    print("no matplotlib: pictures not checked")
if failures:
    print("FAIL: " + "; ".join(failures))
    sys.exit(1)
print("breakup regression: ok")
PY
