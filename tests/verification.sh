#!/bin/bash
# Verification on finer meshes and the final design as a mesh (issue 19
# item 3, issue 22 item 1), on the thick sphere octant (A = 1, B = 2 mm,
# nu = 0.4999, p = 0.3 mu): the objective is the mean u_x over the outer
# surface, w_B / 2 by symmetry, with w_B from the incompressible closed form.
#  1. One iteration (the final design is the sphere itself) verified at 0.2
#     and 0.12 mm: the errors fall toward the closed form; what is left is
#     nu = 0.4999's compressibility (about 1e-4).
#  2. Three iterations (a moved design): design.msh analyzed with
#     design.prm repeats the final analysis to round-off, and
#     "softopt verify" repeats verification.csv, with its first row from the
#     final analysis or, without one, from design.msh, also with
#     out-of-core factors.
# Usage: verification.sh SOFTOPT_EXECUTABLE SOURCE_DIR
softopt=$1
source=$2
source "${BASH_SOURCE%/*}/script_test.sh"
source "$source/tests/sphere_case.sh"
case_file() { # OUTPUT_DIRECTORY ITERATIONS MESH_SIZES
  thick_sphere_case "$source" "$1" "$2" 0.5 ""
  printf 'subsection Verification\n  set Mesh sizes = %s\nend\n' "$3"
}

case_file sphere 1 "0.2, 0.12" > sphere.prm
"$softopt" optimize sphere.prm > sphere.log 2>&1 || { echo "FAIL optimize sphere"; cat sphere.log; exit 1; }
/usr/bin/python3 - sphere/verification.csv "$(thick_sphere_exact)" <<'PY' || failures=$((failures + 1))
import csv, sys
exact = float(sys.argv[-1])  # thick_sphere_exact
rows = list(csv.DictReader(open(sys.argv[1])))
errors = [abs(float(r["g_1"]) / exact - 1) for r in rows]
cells = [int(r["cells"]) for r in rows]
print("     closed form mean u_x %.10f mm" % exact)
for r, e in zip(rows, errors):
    print("     %s mm: %6d cells, g_1 %.10f, error %.1e" % (r["mesh_size_mm"], int(r["cells"]), float(r["g_1"]), e))
ok = len(rows) == 3 and cells[0] < cells[1] < cells[2]
print(("ok  " if ok else "FAIL") + " three rows, optimization mesh first, cells increasing")
ok2 = max(errors[1:]) < 0.2 * errors[0] and max(errors[1:]) < 2e-4
print(("ok  " if ok2 else "FAIL") + " finer-mesh errors %.1e, %.1e (< 0.2 x %.1e and < 2e-4)" % (errors[1], errors[2], errors[0]))
sys.exit(0 if ok and ok2 else 1)
PY
grep -q "g_1: .* (0.2 mm, +" sphere.log || fail "no change against the optimization mesh printed"

case_file moved 3 "0.2" > moved.prm
"$softopt" optimize moved.prm > moved.log 2>&1 || { echo "FAIL optimize moved"; cat moved.log; exit 1; }
"$softopt" analyze moved/design.prm > analyze.log 2>&1 || { echo "FAIL analyze design.prm"; cat analyze.log; exit 1; }
cp moved/verification.csv first_verification.csv
"$softopt" verify moved.prm > verify.log 2>&1 || { echo "FAIL verify"; cat verify.log; exit 1; }
/usr/bin/python3 - moved <<'PY' || failures=$((failures + 1))
import csv, sys
d = sys.argv[1]
last = lambda f: list(csv.DictReader(open(f)))[-1]
final = last(d + "/final_analysis/load_path.csv")
again = last(d + "/design_analysis/load_path.csv")
moved = float(list(csv.DictReader(open(d + "/history.csv")))[-1]["max_design_change_mm"])
ok = True
for c in ("cavity_volume_mm3", "g_1"):
    e = abs(float(again[c]) / float(final[c]) - 1)
    good = e < 1e-9
    ok &= good
    print(("ok  " if good else "FAIL") + " design.msh: %s %s against the final analysis's %s, difference %.0e (< 1e-9)" % (c, again[c], final[c], e))
good = moved > 1e-3
print(("ok  " if good else "FAIL") + " the final design moved (max |dd| %.3g mm > 1e-3)" % moved)
sys.exit(0 if ok and good else 1)
PY
if cmp -s first_verification.csv moved/verification.csv && grep -q "from the run's final analysis" verify.log; then
  echo "ok   softopt verify repeats verification.csv ($(($(wc -l < first_verification.csv) - 1)) rows), the first from the final analysis"
else
  fail "softopt verify gives another verification.csv, or analyzed design.msh again:"; diff first_verification.csv moved/verification.csv
fi
# Without a finished final analysis, verify analyzes design.msh itself.
mv moved/final_analysis/load_path_summary.csv summary.csv
"$softopt" verify moved.prm > verify2.log 2>&1 || { echo "FAIL verify without a final analysis"; cat verify2.log; exit 1; }
mv summary.csv moved/final_analysis/load_path_summary.csv
if cmp -s first_verification.csv moved/verification.csv && ! grep -q "from the run's final analysis" verify2.log; then
  echo "ok   without final_analysis/load_path_summary.csv, verify analyzes design.msh and repeats verification.csv"
else
  fail "verify without a final analysis:"; diff first_verification.csv moved/verification.csv
fi
# Nor when the summary names another functional, or a value is not a
# number (a target not reached); its time kept, so only its content differs.
summary=moved/final_analysis/load_path_summary.csv
cp -p "$summary" summary.csv
for edit in 's/^g_1,/f_1,/' 's/^\(g_1,[^,]*,[^,]*,\)[^,]*/\1nan/'; do
  sed "$edit" summary.csv > "$summary"; touch -r summary.csv "$summary"
  cmp -s summary.csv "$summary" && fail "the edit $edit did not change the summary"
  "$softopt" verify moved.prm > verify_edited.log 2>&1 || { echo "FAIL verify with an edited summary"; cat verify_edited.log; exit 1; }
  if cmp -s first_verification.csv moved/verification.csv && ! grep -q "from the run's final analysis" verify_edited.log; then
    echo "ok   with the summary edited ($edit), verify analyzes design.msh"
  else
    fail "verify with the summary edited ($edit):"; diff first_verification.csv moved/verification.csv
  fi
done
cp -p summary.csv "$summary"
# verify takes each functional's value at its target, not its lowest or
# highest along the path (the sphere's single target is also its highest):
# with those two columns changed, the first row stays; with the value at
# the target changed, the first row follows it.
for columns in "minimum maximum" value_at_target; do
  /usr/bin/python3 - summary.csv "$summary" $columns <<'PY' || failures=$((failures + 1))
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
missing = set(sys.argv[3:]) - set(rows[0])
if missing:
    sys.exit("FAIL the summary has no column %s" % ", ".join(sorted(missing)))
for r in rows:
    r.update({c: "1.25" for c in sys.argv[3:]})
w = csv.DictWriter(open(sys.argv[2], "w", newline=""), fieldnames=rows[0].keys(), lineterminator="\n")
w.writeheader(); w.writerows(rows)
PY
  touch -r summary.csv "$summary"
  cmp -s summary.csv "$summary" && fail "setting $columns to 1.25 did not change the summary"
  "$softopt" verify moved.prm > verify_column.log 2>&1 || { echo "FAIL verify with $columns edited"; cat verify_column.log; exit 1; }
  first=$(sed -n 2p moved/verification.csv | cut -d, -f4)
  expected=$(sed -n 2p first_verification.csv | cut -d, -f4)
  [ "$columns" = value_at_target ] && expected=1.25
  if grep -q "from the run's final analysis" verify_column.log && [ "$first" = "$expected" ]; then
    echo "ok   with $columns of the summary set to 1.25, verify's first g_1 is $first (expected $expected)"
  else
    fail "verify with $columns of the summary set to 1.25: first g_1 $first, expected $expected"
  fi
done
cp -p summary.csv "$summary"
# Nor when the path failed after the last target (optimize exits 1 then;
# verify must not read the failure as a success): its stop reason edited,
# the time kept.
stop=moved/final_analysis/stop_reason.txt
cp -p "$stop" stop_reason.txt
echo "the load step could not be solved above load factor 1" > "$stop"; touch -r stop_reason.txt "$stop"
"$softopt" verify moved.prm > verify_failed.log 2>&1 || { echo "FAIL verify after a failed final analysis"; cat verify_failed.log; exit 1; }
cp -p stop_reason.txt "$stop"
if cmp -s first_verification.csv moved/verification.csv && ! grep -q "from the run's final analysis" verify_failed.log; then
  echo "ok   with the final analysis's stop reason a failure, verify analyzes design.msh"
else
  fail "verify with a failed final analysis:"; diff first_verification.csv moved/verification.csv
fi
# Nor after parameters.prm was edited: the final analysis may be another
# problem's.
sleep 1; touch moved/parameters.prm
"$softopt" verify moved.prm > verify3.log 2>&1 || { echo "FAIL verify after parameters.prm"; cat verify3.log; exit 1; }
if cmp -s first_verification.csv moved/verification.csv && ! grep -q "from the run's final analysis" verify3.log; then
  echo "ok   with parameters.prm newer than the final analysis, verify analyzes design.msh"
else
  fail "verify after parameters.prm was edited:"; diff first_verification.csv moved/verification.csv
fi
# A linear-solver entry may differ from the run's: out-of-core factors (for
# fine verification meshes) give the same values, set for every
# factorization (Linear solver) or for the verification meshes only
# (Verification).
cp moved/verification.csv in_core_verification.csv
for subsection in "Linear solver" "Verification"; do
  { case_file moved 3 "0.2"; printf 'subsection %s\n  set Out-of-core factors = true\nend\n' "$subsection"; } > ooc.prm
  if ! "$softopt" verify ooc.prm > ooc.log 2>&1 || ! grep -q "unknowns out of core" ooc.log; then
    fail "verify with out-of-core factors ($subsection)"; cat ooc.log
  else
    /usr/bin/python3 - in_core_verification.csv moved/verification.csv "$subsection" <<'PY' || failures=$((failures + 1))
import csv, sys
a, b = (list(csv.DictReader(open(f))) for f in sys.argv[1:3])
d = max(abs(float(y[k]) - float(x[k])) / max(abs(float(x[k])), 1e-300)
        for x, y in zip(a, b) for k in x if k not in ("cells", "dofs") and float(x[k]) != 0)
ok = len(a) == len(b) and d < 1e-8
print(("ok  " if ok else "FAIL") + " verify with out-of-core factors (%s): %d rows, largest relative difference %.0e (< 1e-8)" % (sys.argv[3], len(b) - 1, d))
sys.exit(0 if ok else 1)
PY
  fi
done
case_file moved 3 "" > empty.prm
if "$softopt" verify empty.prm > empty.log 2>&1 || ! grep -q '"Mesh sizes" is empty' empty.log; then
  fail "verify without mesh sizes"; cat empty.log
else
  echo "ok   verify without mesh sizes is refused: $(grep -o '"Mesh sizes" is empty[^.]*' empty.log | head -1)"
fi
exit $failures
