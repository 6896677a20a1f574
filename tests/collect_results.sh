#!/bin/bash
# scripts/collect_results: a finished run's small records copied unchanged
# and every panel rendered (history, load path, tracked points, snapshots,
# design, deformed part), on a two-iteration run of the thick sphere octant;
# a run still going (history.csv only) gets its history and a note per
# missing file; a folder that is no run's output is refused with a message.
# Usage: collect_results.sh SOFTOPT_EXECUTABLE SOURCE_DIR
softopt=$1
source=$2
source "${BASH_SOURCE%/*}/script_test.sh"
source "$source/tests/sphere_case.sh"
check() { # CONDITION_EXIT_CODE MESSAGE
  if [ "$1" -eq 0 ]; then echo "ok   $2"; else fail "$2"; fi
}

{ thick_sphere_case "$source" run 2 0.5 "  set Output interval = 1"
  printf 'subsection Output\n  set VTU output = targets\n  set Deformed STL = true\n'
  printf '  set Tracked points = a: 1.2, 1.2, 1\nend\n'
  printf 'subsection Verification\n  set Mesh sizes = 0.4\nend\n'; } > run.prm
"$softopt" optimize run.prm > run.log 2>&1 || { echo "FAIL optimize"; cat run.log; exit 1; }

/usr/bin/python3 "$source/scripts/collect_results" run results > collect.log 2>&1
check $? "collect_results exits with 0"
for f in history.csv verification.csv castability.csv paths.log stop_reason.txt \
         final_analysis/load_path.csv final_analysis/tracked_points.csv; do
  cmp -s "run/$f" "results/$f"
  check $? "$f copied unchanged"
done
for f in history.png pressure_volume.png tracked_points.png snapshots.png \
         design.png deformed_302kPa.png; do
  [ -s "results/$f" ]
  check $? "$f rendered"
done
[ -z "$(find results -name '*.vtu' -o -name '*.stl')" ]
check $? "no VTU or STL among the records"

/usr/bin/python3 "$source/scripts/collect_results" run.prm elsewhere > refused.log 2>&1
status=$?
[ $status -ne 0 ] && grep -q "run.prm has no history.csv" refused.log && [ ! -e elsewhere ]
check $? "a folder that is no output directory is refused, nothing written (exit $status: $(cat refused.log))"

# A run still going: history.csv only. Its history is drawn, the rest
# skipped with a note each.
mkdir partial && cp run/history.csv partial/
/usr/bin/python3 "$source/scripts/collect_results" partial partial_results > partial.log 2>&1
check $? "a run with history.csv only: exit 0"
[ -s partial_results/history.png ] && [ ! -e partial_results/design.png ]
check $? "its history.png rendered, no design.png"
for note in "no design.stl" "no snapshots" "no final_analysis" "no verification.csv"; do
  grep -q "$note" partial.log
  check $? "its note: $note"
done

[ $failures -eq 0 ] || { cat collect.log partial.log; exit 1; }
