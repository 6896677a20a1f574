#!/bin/bash
# A mesh that refines as the design settles (issue 19 item 4), on the thick
# sphere octant of verification.sh (objective: the mean u_x of the outer
# surface; 0.5 mm, then 0.2 mm from iteration 2 on):
#  1. At iteration 2 the design is meshed anew at 0.2 mm, the states carry
#     over (Newton starts from them: "(warm)") and the check from rest finds
#     the same branch.
#  2. The objective on the new mesh differs from that of the same design on
#     the fixed 0.5 mm mesh by no more than twice the 0.5 mm mesh's own error
#     against the closed form (at iteration 0, the sphere itself).
#  3. A restart from the checkpoint of iteration 2, written before the new
#     mesh, makes it again and repeats the uninterrupted run's rows.
#  4. The schedule's size at iteration 0 replaces Geometry / Mesh size.
# Usage: mesh_schedule.sh SOFTOPT_EXECUTABLE SOURCE_DIR
softopt=$1
source=$2
source "${BASH_SOURCE%/*}/script_test.sh"
source "$source/tests/sphere_case.sh"
case_file() { # OUTPUT_DIRECTORY ITERATIONS SCHEDULE [MESH_SIZE]
  thick_sphere_case "$source" "$1" "$2" "${4:-0.5}" \
    "  set Mesh size schedule = $3
  set Checkpoint interval = 2"
}
run() { # NAME ARGUMENTS...
  local name=$1
  shift
  "$softopt" "$@" > "$name.log" 2>&1 || { echo "FAIL softopt $*"; cat "$name.log"; exit 1; }
}

# The schedule's size at iteration 0 replaces Mesh size (0.6 here).
case_file scheduled 5 "0.5 @ 0, 0.2 @ 2" 0.6 > scheduled.prm
case_file fixed 3 "" > fixed.prm
run scheduled optimize scheduled.prm
run fixed optimize fixed.prm

line=$(grep "iteration 2: the schedule's mesh size 0.2 mm" scheduled.log)
if [[ "$line" == *"the states carry over"* ]]; then
  echo "ok   iteration 2: the schedule's mesh size 0.2 mm, the states carry over"
else
  fail "no new mesh with the states carried over at iteration 2: $line"; cat scheduled.log
fi
row=$(grep "^iteration    2 " scheduled.log)
[[ "$row" == *"(warm)"* ]] && echo "ok   Newton on the new mesh starts from the carried states" ||
  fail "Newton on the new mesh did not start from the carried states: $row"
[[ "$row" == *"from rest: same branch"* ]] && echo "ok   the check from rest on the new mesh finds the same branch" ||
  fail "the check from rest on the new mesh: $row"

/usr/bin/python3 - scheduled/history.csv fixed/history.csv "$(thick_sphere_exact)" <<'PY' || failures=$((failures + 1))
import csv, sys
exact = float(sys.argv[-1])  # thick_sphere_exact
scheduled = list(csv.DictReader(open(sys.argv[1])))
fixed = list(csv.DictReader(open(sys.argv[2])))
cells = [int(r["cells"]) for r in scheduled]
ok = cells[0] == cells[1] and cells[2] > 2 * cells[1] and len(set(cells[2:])) == 1
print(("ok  " if ok else "FAIL") + " cells per iteration %s: the finer mesh from iteration 2 on" % cells)
mesh_error = abs(float(scheduled[0]["g_1"]) / exact - 1)
change = abs(float(scheduled[2]["g_1"]) / float(fixed[2]["g_1"]) - 1)
ok2 = change < 2 * mesh_error
print(("ok  " if ok2 else "FAIL") +
      " iteration 2's design: g_1 %.10f at 0.2 mm, %.10f at 0.5 mm, difference %.1e (< 2 x %.1e, the 0.5 mm mesh's error at iteration 0)"
      % (float(scheduled[2]["g_1"]), float(fixed[2]["g_1"]), change, mesh_error))
same = all(scheduled[k]["g_1"] == fixed[k]["g_1"] for k in (0, 1))
print(("ok  " if same else "FAIL") + " iterations 0 and 1 equal to the fixed 0.5 mm mesh's (the schedule's 0.5 @ 0 replaced Mesh size = 0.6)")
sys.exit(0 if ok and ok2 and same else 1)
PY

# A run that stops after iteration 2, then goes on from its checkpoint of
# iteration 2, written before that iteration's new mesh: the restart makes
# the new mesh again.
case_file scheduled_restart 3 "0.5 @ 0, 0.2 @ 2" 0.6 > restart.prm
run first optimize restart.prm
case_file scheduled_restart 5 "0.5 @ 0, 0.2 @ 2" 0.6 > restart.prm
run second optimize restart.prm --restart
grep -q "Restarting at iteration 2" second.log || fail "the restart did not start at iteration 2: $(head -3 second.log)"
grep -q "iteration 2: the schedule's mesh size 0.2 mm" second.log && echo "ok   the restart makes iteration 2's new mesh again" ||
  fail "the restart did not make iteration 2's new mesh"
/usr/bin/python3 - scheduled/history.csv scheduled_restart/history.csv <<'PY' || failures=$((failures + 1))
import csv, sys
a = list(csv.DictReader(open(sys.argv[1])))
b = list(csv.DictReader(open(sys.argv[2])))
worst = max(abs(float(b[k]["g_1"]) / float(a[k]["g_1"]) - 1) for k in range(5))
ok = len(b) == 5 and worst < 1e-9 and b[4]["cells"] == a[4]["cells"]
print(("ok  " if ok else "FAIL") + " the restart repeats rows 2 to 4: largest difference %.1e (< 1e-9), %s cells" % (worst, b[4]["cells"]))
sys.exit(0 if ok else 1)
PY

# Bad input: a schedule that is not "size @ iteration".
case_file bad 3 "0.3 at 2" > bad.prm
if "$softopt" optimize bad.prm > bad.log 2>&1 || ! grep -q 'is not "size @ iteration"' bad.log; then
  fail "a malformed schedule"; cat bad.log
else
  echo "ok   a malformed schedule is refused: $(grep -o '"0.3 at 2" is not[^(]*' bad.log | head -1)"
fi
exit $failures
