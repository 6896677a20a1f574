#!/bin/bash
# A run owns its folder, and a restart continues the same problem (issue 23).
# On the coarse sphere octant (a few seconds per run):
#   1. a fresh run into a folder holding an earlier run is refused, and the
#      earlier history.csv is untouched;
#   2. --restart with a changed Pressure is refused, naming the entry;
#   3. --restart that would not run further is refused (also with another
#      subsection Verification, which may change);
#   4. --restart with more iterations (and the pressure written another way)
#      goes on: rows 0..2, one of each;
#   5. a second run into a folder while a first one writes there stops at
#      once, naming the first run's process;
#   6. --start-over removes the earlier run and starts at iteration 0;
#   7. after a restart, design.pvd lists the snapshots from before it too,
#      and snapshots/ holds one surface per iteration, the last design.stl;
#   8. a restart from a truncated checkpoint says so;
#   9. a restart whose checkpoint names a new mesh that was deleted names
#      that mesh;
#  10. a rerun killed (-9) in its final analysis leaves no stop reason of
#      the finished run beside its partial load_path.csv, and a restart
#      then finishes it;
#  11. a full disk (load_path.csv linked to /dev/full) and an output folder
#      that cannot be made are reported with the file and the system's
#      reason.
# Usage: run_folder.sh SOFTOPT_EXECUTABLE SOURCE_DIR
softopt=$1
source=$2
source "${BASH_SOURCE%/*}/script_test.sh"
trap 'kill $background $rerun 2>/dev/null; rm -rf "$work"' EXIT
cp "$source/meshes/sphere_octant.geo" sphere.geo

source "$source/tests/sphere_case.sh"
case_file() { # $1: pressure, $2: maximum iterations
  sphere_case sphere.geo run "" "$1" "$2" 1
}

expect() { # $1: probe, $2: exit code, $3: "ok" or the text the message must hold
  if [ "$3" = ok ]; then
    if [ "$2" -ne 0 ]; then
      fail "$1: exit code $2 (expected 0)"; cat log
    else
      echo "ok   $1"
    fi
  elif [ "$2" -eq 0 ]; then
    fail "$1: exit code 0 (expected a refusal)"
  elif ! grep -qF -- "$3" log; then
    fail "$1: the message does not contain \"$3\":"; cat log
  else
    echo "ok   $1: refused (exit code $2)"
  fi
}

rows() { tail -n +2 run/history.csv | cut -d, -f1 | tr '\n' ' '; }

case_file 100 2 > case.prm
"$softopt" optimize case.prm > log 2>&1
expect "first run" $? ok
before=$(md5sum < run/history.csv)

# 1. A fresh run into the folder of the first.
"$softopt" optimize case.prm > log 2>&1
expect "fresh run into an earlier run's folder" $? "holds an earlier run"
if [ "$(md5sum < run/history.csv)" != "$before" ]; then
  fail "fresh run: history.csv was changed"
fi

# 2. A restart with another pressure.
case_file 120 3 > changed.prm
"$softopt" optimize changed.prm --restart > log 2>&1
expect "restart with a changed Pressure" $? 'Loading/Pressure: "100" then, "120" now'

# 3. A restart that would not run further.
"$softopt" optimize case.prm --restart > log 2>&1
expect "restart without more iterations" $? "would not run further"
#    Subsection Verification may change (it acts after the loop): the same
#    refusal, not one of changed entries.
(case_file 100 2; printf 'subsection Verification\n  set Mesh sizes = 0.4\nend\n') > verify.prm
"$softopt" optimize verify.prm --restart > log 2>&1
expect "restart with another Verification, without more iterations" $? "would not run further"

# 4. A restart with one iteration more (Pressure written 100.0: the same
#    number, so the same problem).
case_file 100.0 3 > longer.prm
"$softopt" optimize longer.prm --restart > log 2>&1
expect "restart with more iterations" $? ok
if [ "$(rows)" != "0 1 2 " ]; then
  fail "restart: history.csv has rows $(rows)(expected 0 1 2)"
fi
#    An entry the run's program did not have yet (here Final mesh update,
#    its line removed as an older program wrote parameters.prm) acted with
#    its default: at the default it passes (to the same refusal as 3), set
#    otherwise it is a changed entry.
sed -i '/set Final mesh update/d' run/parameters.prm
case_file 100 3 > same.prm
"$softopt" optimize same.prm --restart > log 2>&1
expect "restart of an older run, a new entry at its default" $? "would not run further"
(case_file 100 4; printf 'subsection Optimization\n  set Mesh update interval = 0\n  set Final mesh update = 3\nend\n') > final.prm
"$softopt" optimize final.prm --restart > log 2>&1
expect "restart of an older run, a new entry set" $? 'Optimization/Final mesh update: (absent: its default "0") then, "3" now'

# 5. Two runs into one folder at once.
case_file 100 30 > long.prm
"$softopt" optimize long.prm --start-over > background.log 2>&1 &
background=$!
for _ in $(seq 50); do
  grep -q "^iteration" background.log 2>/dev/null && break
  sleep 0.2
done
"$softopt" optimize long.prm --restart > log 2>&1
expect "second run while the first writes" $? "Another softopt run (process $background"
kill $background 2>/dev/null
wait $background 2>/dev/null

# 6. Start over.
"$softopt" optimize case.prm --start-over > log 2>&1
expect "start over" $? ok
if [ "$(rows)" != "0 1 " ]; then
  fail "start over: history.csv has rows $(rows)(expected 0 1)"
fi
# 7. The design snapshots' index after a restart (at iteration 1, the
#    last checkpoint).
case_file 100 2 | sed 's/VTU output = none/VTU output = targets/;
  s/Maximum iterations = 2/Maximum iterations = 2\n  set Output interval = 1/' > vtu.prm
"$softopt" optimize vtu.prm --start-over > log 2>&1
expect "run with snapshots" $? ok
sed 's/Maximum iterations = 2/Maximum iterations = 3/' vtu.prm > vtu3.prm
"$softopt" optimize vtu3.prm --restart > log 2>&1
expect "restart with snapshots" $? ok
listed=$(grep -o 'file="design_[0-9]*.pvtu"' run/design.pvd | tr '\n' ' ')
if [ "$listed" != 'file="design_0000.pvtu" file="design_0001.pvtu" file="design_0002.pvtu" ' ]; then
  fail "design.pvd after the restart lists $listed(expected iterations 0, 1, 2)"
else
  echo "ok   design.pvd after the restart lists iterations 0, 1 and 2"
fi
#    The surface snapshots: one per iteration (those of the runs before the
#    --start-over removed), the last the final design.stl.
listed=$(cd run/snapshots && ls | tr '\n' ' ')
if [ "$listed" != "design_0000.stl design_0001.stl design_0002.stl " ]; then
  fail "snapshots/ holds $listed(expected design_0000.stl to design_0002.stl)"
elif ! cmp -s run/snapshots/design_0002.stl run/design.stl; then
  fail "snapshots/design_0002.stl differs from design.stl (the same design)"
else
  echo "ok   snapshots/ holds design_0000.stl to design_0002.stl, the last equal to design.stl"
fi
rendered=$(/usr/bin/python3 "$source/scripts/render_snapshots" run snapshots.png --panels 2 2>&1)
if [ "$rendered" != "Wrote snapshots.png (2 snapshots)" ] || [ ! -s snapshots.png ]; then
  fail "render_snapshots --panels 2: $rendered"
else
  echo "ok   render_snapshots --panels 2 draws the first and the last"
fi
# 8. A truncated checkpoint.
case_file 100 2 > case.prm
"$softopt" optimize case.prm --start-over > log 2>&1
expect "run for the truncated checkpoint" $? ok
truncate -s 2000 run/checkpoint/rank-0.bin
rm run/final_analysis/stop_reason.txt
"$softopt" optimize case.prm --restart > log 2>&1
expect "restart from a truncated checkpoint" $? "rank-0.bin is truncated"

# 9. The new mesh a checkpoint continues on, deleted.
case_file 100 3 | sed 's/Checkpoint interval = 1/Checkpoint interval = 1\n  set Mesh update interval = 1\n  set Remesh below quality = 1/' > remesh.prm
"$softopt" optimize remesh.prm --start-over > log 2>&1
expect "run with new meshes" $? ok
rm run/mesh-1.msh run/final_analysis/stop_reason.txt
"$softopt" optimize remesh.prm --restart > log 2>&1
expect "restart without its new mesh" $? "continues on the mesh <run/mesh-1.msh>"
# 10. Killed in the final analysis of a rerun.
case_file 100 2 > case.prm
"$softopt" optimize case.prm --start-over > log 2>&1
expect "run before the killed rerun" $? ok
case_file 100 3 | sed 's/Final analysis steps = 1/Final analysis steps = 5000/' > slow.prm
"$softopt" optimize slow.prm --restart > log 2>&1 &
rerun=$!
# Into its final analysis (the log says so), then a few of its 5000 rows.
reached=no
for _ in $(seq 600); do
  if grep -q "Forward analysis of the final design" log &&
     [ "$(wc -l < run/final_analysis/load_path.csv 2>/dev/null || echo 0)" -gt 5 ]; then
    reached=yes; break
  fi
  sleep 0.1
done
kill -9 $rerun; wait $rerun 2>/dev/null
if [ $reached = no ]; then
  fail "killed final analysis: the rerun did not reach its final analysis in 60 s"
elif [ -e run/final_analysis/stop_reason.txt ]; then
  fail "killed final analysis: the finished run's stop_reason.txt is still there"
else
  echo "ok   killed final analysis: no stale stop_reason.txt ($(($(wc -l < run/final_analysis/load_path.csv) - 1)) rows in load_path.csv)"
fi
case_file 100 3 > case3.prm
"$softopt" optimize case3.prm --restart > log 2>&1
expect "restart after the killed final analysis" $? ok
if [ "$(cat run/final_analysis/stop_reason.txt 2>/dev/null)" != "reached the last target load factor" ]; then
  fail "the restart did not finish the final analysis"
fi
# 11. A full disk, and a folder where a file is.
sphere_case sphere.geo full "" 100 1 0 > full.prm
mkdir -p full && ln -sf /dev/full full/load_path.csv
"$softopt" analyze full.prm > log 2>&1
expect "full disk" $? "Cannot write <full/load_path.csv>: No space left on device"
touch a_file
sphere_case sphere.geo a_file/out "" 100 1 0 > nodir.prm
"$softopt" analyze nodir.prm > log 2>&1
expect "output folder under a file" $? "Cannot create the output directory <a_file/out>"
exit $failures
