#!/bin/bash
# "Output / Deformed STL" (issue 20, the renders of the inflated part): the
# sphere octant of tests/compliance_ratio_path.prm inflated to 0.7 of its
# pressure maximum writes deformed_<p>kPa.stl at each target. At each, the
# cavity's mean radius on the STL (its vertices inside r = 1.5 mm, off the
# symmetry planes; every one lies on the P2 surface) must equal that of load_path.csv's
# cavity volume, (6 V / pi)^(1/3) for the octant, within the 0.5 mm mesh's
# chord error (bound 0.1 %), and every edge must be shared by exactly two
# triangles (watertight). The final analysis of "optimize" writes them at
# the same four targets, not at its equal load steps.
# Usage: deformed_stl.sh SOFTOPT_EXECUTABLE SOURCE_DIR
softopt=$1
source=$2
source "${BASH_SOURCE%/*}/script_test.sh"
sed -e "s#../meshes/#$source/meshes/#" \
    -e 's/set VTU output = none/set VTU output = none\n  set Deformed STL = true/' \
    "$source/tests/compliance_ratio_path.prm" > case.prm
"$softopt" analyze case.prm > run.log 2>&1 || { echo "FAIL analyze"; cat run.log; exit 1; }
/usr/bin/python3 - "$source/scripts" <<'PY'
import csv, glob, math, sys
sys.path.insert(0, sys.argv[1])
import numpy as np
from stl_view import read_triangles

rows = {round(float(r["pressure_kPa"]), 3): float(r["cavity_volume_mm3"])
        for r in csv.DictReader(open("results/load_path.csv"))}
files = sorted(glob.glob("results/deformed_*kPa.stl"))
failures = 0
print(f"{len(files)} deformed STL files (4 targets)")
failures += len(files) != 4
for name in files:
    p = float(name.split("deformed_")[1][:-len("kPa.stl")])
    triangles = read_triangles(name)
    points = triangles.reshape(-1, 3)
    radii = np.linalg.norm(points, axis=1)
    # Off the symmetry planes (a zero coordinate), inside r = 1.5 mm.
    inner = np.unique(points[(radii < 1.5) & (points.min(axis=1) > 1e-9)], axis=0)
    radius = np.linalg.norm(inner, axis=1).mean()
    V = next(v for q, v in rows.items() if abs(q - p) < 1e-3 * max(1, p))
    exact = (6 * V / math.pi) ** (1 / 3)
    error = abs(radius - exact) / exact
    edges = {}
    for t in triangles.round(12).tolist():
        for a, b in ((0, 1), (1, 2), (2, 0)):
            key = tuple(sorted((tuple(t[a]), tuple(t[b]))))
            edges[key] = edges.get(key, 0) + 1
    open_edges = sum(1 for n in edges.values() if n != 2)
    ok = error < 1e-3 and open_edges == 0
    failures += not ok
    print(f"{p:g} kPa: cavity radius {radius:.5f} mm against (6V/pi)^(1/3) "
          f"{exact:.5f} mm, error {error:.1e} (< 1e-3); edges not in two "
          f"triangles: {open_edges} (= 0) {'ok' if ok else 'FAIL'}")
sys.exit(1 if failures else 0)
PY
failures=$?
# The final analysis of "optimize" writes them at the same four targets,
# not at its equal steps.
sed -e 's/set Command = analyze/set Command = optimize/' \
    -e 's/^set Output directory = results/set Output directory = run/' case.prm > run.prm
printf 'subsection Optimization\n  set Maximum iterations = 1\n  set Final analysis steps = 5\nend\n' >> run.prm
"$softopt" optimize run.prm > optimize.log 2>&1 || { echo "FAIL optimize"; cat optimize.log; exit 1; }
n=$(ls run/final_analysis/deformed_*kPa.stl | wc -l)
steps=$(($(wc -l < run/final_analysis/load_path.csv) - 1))
[ "$n" = 4 ] && echo "final analysis: $n deformed STL files at $steps load steps (4 targets) ok" ||
  { echo "final analysis: $n deformed STL files at $steps load steps (4 targets) FAIL"; failures=1; }
exit $failures
