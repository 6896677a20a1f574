#!/bin/bash
# Mold parts (issue 22 item 3), "softopt mold", checked from the STL files
# themselves, not from the program's own sums:
#  1. The paper's initial actuator (4 mm mesh), split along z and along a
#     tilted plane (normal 0, 1, 1): every part is a closed, consistently
#     oriented 2-manifold with vertices matched by their bytes (each edge
#     once in each direction, one piece, Euler characteristic 2); body +
#     cores + halves fill the mold's box, whose extents are read off the
#     halves in the mold's frame and must be the actuator's (60 mm along
#     the axis, radius 11.5 mm) plus the wall: volumes add up to 1e-6
#     relative, with each core's stem outside the box (a 48-gon prism)
#     taken off.
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
source "${BASH_SOURCE%/*}/script_test.sh"

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

# parts FOLDER LENGTH RADIUS UNDERCUT_MM2: the checks of every part of a
# mold around a cylinder-like body (LENGTH along the axis, RADIUS), with
# Wall thickness 5, Stem diameter 4 and Stem length 10 as in case_prm.
parts() {
  /usr/bin/python3 - "$@" <<'PY'
import collections, csv, glob, math, os, sys
import numpy as np
folder, length, radius, expected = sys.argv[1], *map(float, sys.argv[2:])
wall, stem_diameter, stem_length = 5, 4, 10

def read_stl(path):
    with open(path, "rb") as f:
        f.seek(80)
        n = int(np.frombuffer(f.read(4), "<u4")[0])
        record = np.dtype([("normal", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])
        return np.frombuffer(f.read(n * record.itemsize), record)["v"]

def closed_sphere(triangles):
    # Vertices by their bytes, as a program reading the file matches them:
    # each directed edge once and its reverse once (closed, oriented,
    # manifold edges), one connected piece, and V - E + F = 2 (no pinched
    # vertex, no handle).
    index, edges = {}, collections.Counter()
    faces = [[index.setdefault(p.tobytes(), len(index)) for p in t] for t in triangles]
    for f in faces:
        for a, b in zip(f, f[1:] + f[:1]):
            edges[(a, b)] += 1
    oriented = all(c == 1 and edges.get((b, a)) == 1 for (a, b), c in edges.items())
    parent = list(range(len(index)))
    def root(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i
    for a, b in edges:
        parent[root(a)] = root(b)
    pieces = len({root(i) for i in range(len(index))})
    euler = len(index) - len(edges) // 2 + len(faces)
    return oriented and pieces == 1 and euler == 2

def volume(triangles):
    t = triangles.astype(float)
    return np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2])).sum() / 6

parts = {os.path.basename(f)[:-4]: read_stl(f) for f in sorted(glob.glob(folder + "/*.stl"))}
ok = set(parts) == {"cast", "core_1", "half_a", "half_b"}
print(("ok  " if ok else "FAIL") + " %s: %s" % (folder, ", ".join(parts)))
for name, triangles in parts.items():
    good = closed_sphere(triangles) and volume(triangles) > 0
    ok &= good
    print(("ok  " if good else "FAIL") + " %-6s %6d triangles, a closed oriented manifold sphere, volume %.2f mm^3"
          % (name, len(triangles), volume(triangles)))

# The box in the mold's frame (frame.csv: axis, split normal).
frame = {r["direction"]: np.array([float(r[c]) for c in "xyz"]) for r in csv.DictReader(open(folder + "/frame.csv"))}
axis, normal = frame["axis"], frame["split_normal"]
directions = np.array([axis, np.cross(normal, axis), normal])
points = np.concatenate([parts["half_a"], parts["half_b"]]).reshape(-1, 3).astype(float) @ directions.T
extents = points.max(0) - points.min(0)
width = 2 * (radius + wall)
good = abs(extents[0] - (length + 2 * wall)) < 1e-3 and all(width * math.cos(math.pi / 8) < w < width + 1e-3 for w in extents[1:])
ok &= good
print(("ok  " if good else "FAIL") + " box %.4f x %.4f x %.4f mm: the body (%g mm, radius %g) and a %g mm wall" % (*extents, length, radius, wall))

box = np.prod(extents)
stem_area = 48 / 2 * (stem_diameter / 2) ** 2 * math.sin(2 * math.pi / 48)  # the stem's 48-gon
cores = [volume(t) - stem_area * stem_length for n, t in parts.items() if n.startswith("core")]
total = sum(volume(parts[n]) for n in ("cast", "half_a", "half_b")) + sum(cores)
good = abs(total - box) / box < 1e-6
ok &= good
print(("ok  " if good else "FAIL") + " body + core in the box + halves %.3f mm^3, box %.3f mm^3: relative difference %.1e (< 1e-6)"
      % (total, box, abs(total - box) / box))

rows = {r["part"]: r for r in csv.DictReader(open(folder + "/parts.csv"))}
good = all(rows.get(n, {}).get("closed") == "1" and rows[n]["manifold"] == "1" for n in parts)
ok &= good
print(("ok  " if good else "FAIL") + " parts.csv: every part closed and manifold")

undercuts = {r["check"]: r for r in csv.DictReader(open(folder + "/undercuts.csv"))}
good = set(undercuts) == {"undercut half_a", "undercut half_b"}
ok &= good
for check, r in sorted(undercuts.items()):
    area = float(r["value"])
    good = (abs(area - expected) < 0.05 * expected and r["verdict"] == "warning") if expected > 0 else (area == 0 and r["verdict"] == "ok")
    ok &= good
    print(("ok  " if good else "FAIL") + " %s: %.1f mm^2, %s (expected %.1f mm^2%s)"
          % (check, area, r["verdict"], expected, ", within 5 %" if expected > 0 else ""))
sys.exit(0 if ok else 1)
PY
}

# The open top cavity's plug: the cup's wall and floor on the far side.
plug=$(/usr/bin/python3 -c "import math; print(math.pi * 10 * 10 + math.pi * 10**2 / 2)")

case_prm "$source/meshes/actuator.geo" 4 actuator > actuator.prm
"$softopt" actuator.prm > actuator.log 2>&1 || { echo "FAIL mold actuator"; cat actuator.log; exit 1; }
parts actuator/mold 60 11.5 "$plug" || failures=$((failures + 1))

# A split plane along no coordinate axis: the same checks, the same plug.
case_prm "$source/meshes/actuator.geo" 4 tilted "subsection Mold
  set Split plane normal = 0, 1, 1
end" > tilted.prm
"$softopt" tilted.prm > tilted.log 2>&1 || { echo "FAIL mold tilted"; cat tilted.log; exit 1; }
parts tilted/mold 60 11.5 "$plug" || failures=$((failures + 1))

case_prm "$source/tests/inputs/closed_cylinder.geo" 2 cylinder > cylinder.prm
"$softopt" cylinder.prm > cylinder.log 2>&1 || { echo "FAIL mold cylinder"; cat cylinder.log; exit 1; }
parts cylinder/mold 20 8 0 || failures=$((failures + 1))

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
