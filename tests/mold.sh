#!/bin/bash
# Mold parts (issue 22 item 3), "softopt mold", checked from the STL files
# themselves, not from the program's own sums:
#  1. The paper's initial actuator (4 mm mesh): every part is a closed,
#     consistently oriented 2-manifold (each edge once in each direction);
#     body + cores + halves fill the mold's box, whose extents are read off
#     the halves and must be the actuator's (60 mm along the axis, radius
#     11.5 mm) plus the wall: volumes add up to 1e-6 relative, with each
#     core's stem outside the box (a 48-gon prism) taken off.
#  2. Undercuts: the open top cavity's plug (radius 10, depth 10 mm) sits in
#     both halves across the split plane; a half pulled along the split
#     normal cannot release the half of the plug's wall and floor that faces
#     away from it: pi r h + pi r^2 / 2 = 471 mm^2 each (within 5 %, the
#     4 mm mesh's polygon). A closed cylinder (inputs/closed_cylinder.geo)
#     releases: 0 mm^2 for both halves.
#  3. Refusals, each with a message, a non-zero exit and no mold files (an
#     earlier mold/ left as it was): a self-intersecting design, walls
#     thinner than Castability / Minimum wall thickness, a half-model with
#     symmetry planes, keys wider than half the wall.
# Usage: mold.sh SOFTOPT_EXECUTABLE SOURCE_DIR
softopt=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

case_prm() { # MESH_FILE MESH_SIZE OUTPUT_DIRECTORY [EXTRA LINES]
  cat <<PRM
set Output directory = $3
set Command = mold
set Print timings = false
subsection Geometry
  set Mesh file = $1
  set Mesh size = $2
  set Dirichlet boundaries = 1: xyz
  set Pressure boundary ids = 2
  set Design boundary ids = 3
end
subsection Mold
  set Wall thickness = 5
  set Stem diameter = 4
  set Stem length = 10
end
$4
PRM
}

case_prm "$source/meshes/actuator.geo" 4 actuator > actuator.prm
"$softopt" actuator.prm > actuator.log 2>&1 || { echo "FAIL mold actuator"; cat actuator.log; exit 1; }
/usr/bin/python3 - actuator/mold 5 4 10 <<'PY' || failures=$((failures + 1))
import collections, csv, glob, math, os, sys
import numpy as np
folder, wall, stem_diameter, stem_length = sys.argv[1], *map(float, sys.argv[2:])

def read_stl(path):
    with open(path, "rb") as f:
        f.seek(80)
        n = int(np.frombuffer(f.read(4), "<u4")[0])
        record = np.dtype([("normal", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])
        return np.frombuffer(f.read(n * record.itemsize), record)["v"].astype(float)

def closed_manifold(triangles):
    # Each directed edge once, and its reverse once: closed, manifold and
    # consistently oriented.
    index, edges = {}, collections.Counter()
    for t in triangles:
        ids = [index.setdefault(tuple(p), len(index)) for p in t]
        for a, b in zip(ids, ids[1:] + ids[:1]):
            edges[(a, b)] += 1
    return all(c == 1 and edges.get((b, a)) == 1 for (a, b), c in edges.items())

def volume(triangles):
    return np.einsum("ij,ij->i", triangles[:, 0], np.cross(triangles[:, 1], triangles[:, 2])).sum() / 6

parts = {os.path.basename(f)[:-4]: read_stl(f) for f in sorted(glob.glob(folder + "/*.stl"))}
ok = set(parts) == {"cast", "core_1", "half_a", "half_b"}
print(("ok  " if ok else "FAIL") + " parts: " + ", ".join(parts))
for name, triangles in parts.items():
    good = closed_manifold(triangles) and volume(triangles) > 0
    ok &= good
    print(("ok  " if good else "FAIL") + " %-6s %6d triangles, closed oriented manifold, volume %.2f mm^3"
          % (name, len(triangles), volume(triangles)))

halves = np.concatenate([parts["half_a"], parts["half_b"]]).reshape(-1, 3)
lo, hi = halves.min(0), halves.max(0)
length, width = hi - lo, 2 * (11.5 + wall)
good = abs(length[0] - (60 + 2 * wall)) < 1e-4 and all(width * math.cos(math.pi / 8) < w <= width + 1e-4 for w in length[1:])
ok &= good
print(("ok  " if good else "FAIL") + " box %.4f x %.4f x %.4f mm: the actuator (60 mm, radius 11.5) and a %g mm wall" % (*length, wall))

box = np.prod(length)
stem_area = 48 / 2 * (stem_diameter / 2) ** 2 * math.sin(2 * math.pi / 48)  # the stem's 48-gon
cores = [volume(t) - stem_area * stem_length for n, t in parts.items() if n.startswith("core")]
total = sum(volume(parts[n]) for n in ("cast", "half_a", "half_b")) + sum(cores)
good = abs(total - box) / box < 1e-6
ok &= good
print(("ok  " if good else "FAIL") + " body + core in the box + halves %.3f mm^3, box %.3f mm^3: relative difference %.1e (< 1e-6)"
      % (total, box, abs(total - box) / box))

rows = list(csv.DictReader(open(folder + "/parts.csv")))
good = all(r["closed"] == "1" and r["manifold"] == "1" for r in rows if r["file"])
ok &= good
print(("ok  " if good else "FAIL") + " parts.csv: every part closed and manifold")

plug = math.pi * 10 * 10 + math.pi * 10 ** 2 / 2
for r in csv.DictReader(open(folder + "/undercuts.csv")):
    area = float(r["value"])
    good = abs(area - plug) / plug < 0.05 and r["verdict"] == "warning"
    ok &= good
    print(("ok  " if good else "FAIL") + " %s: %.1f mm^2, %s (the top cavity's plug: %.1f mm^2, within 5 %%)"
          % (r["check"], area, r["verdict"], plug))
sys.exit(0 if ok else 1)
PY

case_prm "$source/tests/inputs/closed_cylinder.geo" 2 cylinder > cylinder.prm
"$softopt" cylinder.prm > cylinder.log 2>&1 || { echo "FAIL mold cylinder"; cat cylinder.log; exit 1; }
for half in half_a half_b; do
  grep -q "^undercut $half,0,mm2,,,,ok$" cylinder/mold/undercuts.csv &&
    echo "ok   closed cylinder: undercut of $half 0 mm^2, ok" ||
    { fail "closed cylinder $half"; cat cylinder/mold/undercuts.csv; }
done

# Refusals. refused NAME EXPECTED_TEXT PRM_FILE: a non-zero exit, the text
# in the message, and no mold files written or changed.
refused() {
  local output
  output=$(sed -n 's/^set Output directory = //p' "$3")
  local before
  before=$(cat "$output"/mold/* 2>/dev/null | md5sum)
  if "$softopt" "$3" > "$1.log" 2>&1; then
    fail "$1: exit code 0"
  elif ! grep -qF -- "$2" "$1.log"; then
    fail "$1: the message does not say \"$2\""; cat "$1.log"
  elif [ "$(cat "$output"/mold/* 2>/dev/null | md5sum)" != "$before" ] || [ -e "$output/mold.tmp" ]; then
    fail "$1: mold files written or changed"
  else
    echo "ok   $1 refused: $(grep -F -- "$2" "$1.log" | head -n 1 | sed 's/^ *//')"
  fi
}

cp "$source/tests/bad_input/overlapping_boxes.geo" .
case_prm overlapping_boxes.geo 3 boxes > boxes.prm
refused "self-intersecting design" "its surface intersects itself" boxes.prm
[ -e boxes/mold ] && fail "a mold folder for the self-intersecting design"

case_prm "$source/meshes/actuator.geo" 4 actuator \
  "subsection Castability
  set Minimum wall thickness = 2
end" > thin.prm
refused "thin walls" "mm thin at (" thin.prm

source "$source/tests/sphere_case.sh"
{ sphere_case "$source/meshes/sphere_octant.geo" octant "" 0.3 1 0; echo "set Command = mold"; } > octant.prm
refused "symmetry planes" "is a symmetry plane, and a mold needs the whole actuator" octant.prm

case_prm "$source/meshes/actuator.geo" 4 actuator \
  "subsection Mold
  set Key radius = 3
end" > keys.prm
refused "keys wider than the wall" "Key radius" keys.prm
exit $failures
