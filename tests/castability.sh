#!/bin/bash
# Castability checks (issue 22 item 2), "softopt check-design":
#  1. Wall thickness on the thick sphere octant (A = 1, B = 2 mm): B - A at
#     every node of its spherical surfaces, their rims on the symmetry planes
#     included (the planes are mirrors, not surfaces of the part), within
#     the flat triangles' chord error;
#     the verdict against Minimum wall thickness both ways.
#  2. A body whose surface passes through itself (bad_input's overlapping
#     boxes): the self-intersection row counts the pairs and refuses it.
#  3. check-design on a finished run checks its design.msh; the sphere's
#     final analysis has no deformed self-contact.
#  4. Walls that touch (inputs/slot.geo): check-design measures the slot,
#     0.4 mm, as the minimum gap (a warning below Minimum gap = 1 mm) and
#     the wall before it, 0.6 mm; the analysis finds the pressure where the
#     deformed surface first passes through itself.
#  5. Corners are not walls (inputs/leaning_side.geo, a frustum whose side
#     leans in 13 degrees from the clamped base, with walls of 2 mm at the
#     base and the cap): near the base's rim the rays leave through the
#     neighbouring face 13 degrees from grazing, a length that goes to 0 at
#     the rim (0.57 mm at the first samples, 0.25 mm up). They are marked
#     as corners (-2 in wall_thickness.vtu) and the minimum is the cap's
#     2 mm.
# Usage: castability.sh SOFTOPT_EXECUTABLE SOURCE_DIR
softopt=$1
source=$2
source "${BASH_SOURCE%/*}/script_test.sh"
source "$source/tests/sphere_case.sh"
sphere() { # OUTPUT_DIRECTORY MINIMUM_WALL_THICKNESS ITERATIONS
  sphere_case "$source/meshes/sphere_octant.geo" "$1" "" 302 "$3" 0
  printf 'subsection Castability\n  set Minimum wall thickness = %s\nend\n' "$2"
}

# The samples of wall_thickness.vtu in the folder argv[1]: points, thickness.
wall_samples() {
  cat <<'PY'
import re, sys
text = open(sys.argv[1] + "/wall_thickness.vtu").read()
arrays = re.findall(r'<DataArray[^>]*>\n(.*?)</DataArray>', text, re.S)
points = [tuple(map(float, l.split())) for l in arrays[0].strip().split("\n")]
thickness = [float(v) for v in arrays[-1].split()]
PY
}

sphere thin 0.9 1 > thin.prm
"$softopt" check-design thin.prm > thin.log 2>&1 || { echo "FAIL check-design"; cat thin.log; exit 1; }
{ wall_samples; cat <<'PY'
import csv, math, sys
d = sys.argv[1]
rows = {r["check"]: r for r in csv.DictReader(open(d + "/castability.csv"))}
wall = rows["minimum wall thickness"]
# Every node of the spheres, their rims on the symmetry planes included
# (there the normal is projected onto the plane); -1: no opposite wall.
on_spheres = [t for p, t in zip(points, thickness)
              if min(abs(math.dist(p, (0, 0, 0)) - r) for r in (1, 2)) < 1e-6]
rims = sum(1 for p in points if min(abs(math.dist(p, (0, 0, 0)) - r) for r in (1, 2)) < 1e-6 and min(p) < 1e-9)
worst = max(abs(t - 1) for t in on_spheres)
ok = len(on_spheres) > 100 and rims > 20 and worst < 0.01 and min(on_spheres) > 0
print(("ok  " if ok else "FAIL") + " thickness at the %d nodes of the spheres (%d on the rims): largest error %.1e mm (< 0.01, B - A = 1 mm)" % (len(on_spheres), rims, worst))
minimum = float(wall["value"])
ok2 = abs(minimum - 1) < 0.01 and wall["verdict"] == "ok"
print(("ok  " if ok2 else "FAIL") + " minimum wall thickness %.4f mm (within 0.01 of 1), verdict %s against 0.9 mm" % (minimum, wall["verdict"]))
crossing = rows["self-intersections"]
ok3 = crossing["value"] == "0" and crossing["verdict"] == "ok"
print(("ok  " if ok3 else "FAIL") + " self-intersections %s, %s" % (crossing["value"], crossing["verdict"]))
sys.exit(0 if ok and ok2 and ok3 else 1)
PY
} | /usr/bin/python3 - thin || failures=$((failures + 1))

sphere thick 1.5 1 > thick.prm
"$softopt" check-design thick.prm > thick.log 2>&1 || { echo "FAIL check-design"; cat thick.log; exit 1; }
grep -q "^minimum wall thickness,.*,warning$" thick/castability.csv &&
  echo "ok   below Minimum wall thickness = 1.5 mm: warning" ||
  { fail "no warning below 1.5 mm"; cat thick/castability.csv; }

cp "$source/tests/bad_input/overlapping_boxes.geo" .
sed -e 's/^set Output directory.*/set Output directory = boxes/' \
  "$source/tests/bad_input/self_intersecting.prm" > boxes.prm
"$softopt" check-design boxes.prm > boxes.log 2>&1 || { echo "FAIL check-design boxes"; cat boxes.log; exit 1; }
row=$(grep "^self-intersections," boxes/castability.csv)
pairs=$(echo "$row" | cut -d, -f2)
if [[ "$row" == *",refused" ]] && [ "$pairs" -gt 0 ]; then
  echo "ok   overlapping boxes: $pairs intersecting triangle pairs, refused"
else
  fail "overlapping boxes: $row"
fi

# A finished run: check-design reads its final design.
sphere run 0.9 2 > run.prm
"$softopt" optimize run.prm > run.log 2>&1 || { echo "FAIL optimize"; cat run.log; exit 1; }
grep -q "minimum wall thickness" run.log && echo "ok   optimize ends with the castability checks" ||
  fail "optimize printed no castability checks"
rm run/castability.csv
"$softopt" check-design run.prm > check_run.log 2>&1 || { echo "FAIL check-design run"; cat check_run.log; exit 1; }
grep -q "The final design of <run> (design.msh" check_run.log && [ -f run/castability.csv ] &&
  echo "ok   check-design on a finished run checks design.msh" ||
  { fail "check-design on a finished run"; cat check_run.log; }
grep -q "^deformed self-contact,,kPa,,,,ok$" run/castability.csv &&
  echo "ok   deformed self-contact: none along the sphere's final analysis" ||
  { fail "no deformed self-contact row"; cat run/castability.csv; }

# Walls that touch: a block with a cavity and, beyond a wall 0.6 mm thick,
# a slot 0.4 mm wide (inputs/slot.geo). The first step whose deformed
# surface passes through itself (load_path.csv, self_contact) against the
# gap between two tracked nodes facing each other across the slot, an
# independent measure: it must close at that step or the next.
cat > slot.prm <<PRM
set Output directory = slot
set Print timings = false
subsection Output
  set VTU output = none
  set Tracked points = wall: 5, 5.6, 5; far: 5, 6, 5
end
subsection Geometry
  set Mesh file = $source/tests/inputs/slot.geo
  set Mesh size = 1.5
  set Dirichlet boundaries = 1: xyz
  set Pressure boundary ids = 2
  set Design boundary ids = 3
end
subsection Material
  set Young's modulus = 1.2
  set Poisson's ratio = 0.49
end
subsection Loading
  set Pressure = 15
  set Initial load increment = 0.05
  set Maximum load increment = 0.05
end
PRM
"$softopt" check-design slot.prm > slot_check.log 2>&1 || { echo "FAIL check-design slot"; cat slot_check.log; exit 1; }
/usr/bin/python3 - slot <<'PY' || failures=$((failures + 1))
import csv, sys
rows = {r["check"]: r for r in csv.DictReader(open(sys.argv[1] + "/castability.csv"))}
gap, wall = rows["minimum gap"], rows["minimum wall thickness"]
ok = abs(float(gap["value"]) - 0.4) < 1e-6 and gap["verdict"] == "warning"
print(("ok  " if ok else "FAIL") + " minimum gap %.6f mm (the slot: 0.4, error < 1e-6), %s below 1 mm" % (float(gap["value"]), gap["verdict"]))
ok2 = abs(float(wall["value"]) - 0.6) < 1e-6
print(("ok  " if ok2 else "FAIL") + " minimum wall thickness %.6f mm (the wall before the slot: 0.6, error < 1e-6)" % float(wall["value"]))
sys.exit(0 if ok and ok2 else 1)
PY
"$softopt" analyze slot.prm > slot.log 2>&1 || { echo "FAIL analyze slot"; cat slot.log; exit 1; }
grep -q "warning: at .* kPa the deformed surface passes through itself" slot.log &&
  echo "ok   the analysis warns where the walls touch" || fail "no contact warning"
/usr/bin/python3 - slot <<'PY' || failures=$((failures + 1))
import csv, sys
d = sys.argv[1]
path = list(csv.DictReader(open(d + "/load_path.csv")))
tracked = list(csv.DictReader(open(d + "/tracked_points.csv")))
contact = next(int(r["step"]) for r in path if r["self_contact"] == "1")
gap = [0.4 + float(r["wall_Y_mm"]) - 5.6 - (float(r["wall_uy_mm"]) - float(r["far_uy_mm"])) for r in tracked]
closed = next(k for k, g in enumerate(gap) if g <= 0)
ok = closed - 1 <= contact <= closed
print(("ok  " if ok else "FAIL") + " walls touch at step %d (%s kPa); the tracked gap %.3f mm there closes at step %d (%s kPa): within one step" %
      (contact, path[contact]["pressure_kPa"], gap[contact], closed, path[closed]["pressure_kPa"]))
sys.exit(0 if ok else 1)
PY
# Corners are not walls.
sed -e 's/^set Output directory.*/set Output directory = leaning/' \
    -e "s|set Mesh file = .*|set Mesh file = $source/tests/inputs/leaning_side.geo|" \
    -e 's/set Mesh size = .*/set Mesh size = 1/' slot.prm > leaning.prm
printf 'subsection Castability\n  set Sampling size = 0.25\nend\n' >> leaning.prm
"$softopt" check-design leaning.prm > leaning.log 2>&1 || { echo "FAIL check-design leaning"; cat leaning.log; exit 1; }
{ wall_samples; cat <<'PY'
import csv, sys
d = sys.argv[1]
rows = {r["check"]: r for r in csv.DictReader(open(d + "/castability.csv"))}
wall = rows["minimum wall thickness"]
# Corners at the samples of the leaning side just above the base.
low = [t for p, t in zip(points, thickness) if 0.1 < p[0] < 0.5 and (p[1]**2 + p[2]**2)**0.5 > 7.8]
ok = len(low) > 20 and all(t == -2 for t in low)
print(("ok  " if ok else "FAIL") + " the %d samples of the leaning side 0.1-0.5 mm above the base: %d corners (all)" % (len(low), sum(1 for t in low if t == -2)))
minimum = float(wall["value"])
ok2 = abs(minimum - 2) < 1e-6 and wall["verdict"] == "ok"
print(("ok  " if ok2 else "FAIL") + " minimum wall thickness %.6f mm (the cap and the base: 2, error < 1e-6), %s" % (minimum, wall["verdict"]))
sys.exit(0 if ok and ok2 else 1)
PY
} | /usr/bin/python3 - leaning || failures=$((failures + 1))
exit $failures
