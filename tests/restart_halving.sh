#!/bin/bash
# A restart at an iteration whose design was halved reproduces the
# uninterrupted run (issue 23): tests/step_halving.prm (iteration 1 is
# refused three times and halved) with a checkpoint at every iteration; the
# final analysis's stop reason removed, as a kill during it leaves it, and
# the run restarted: it resumes at iteration 1, halves three times again,
# and writes the same history rows (every printed digit but the wall time).
# Usage: restart_halving.sh SOFTOPT_EXECUTABLE SOURCE_DIR
softopt=$1
source=$2
source "${BASH_SOURCE%/*}/script_test.sh"
sed "s#../meshes#$source/meshes#; s/Checkpoint interval  = 0/Checkpoint interval  = 1/" \
  "$source/tests/step_halving.prm" > case.prm
"$softopt" case.prm > first.log 2>&1 || { echo "FAIL first run"; cat first.log; exit 1; }
cut -d, -f1,2,3,5- results/history.csv > uninterrupted.csv
rm results/final_analysis/stop_reason.txt
"$softopt" optimize case.prm --restart > restart.log 2>&1 ||
  { echo "FAIL restart"; cat restart.log; exit 1; }
cut -d, -f1,2,3,5- results/history.csv > restarted.csv
halved=$(grep -c "step halved" restart.log)
if ! grep -q "Restarting at iteration 1" restart.log || [ "$halved" -ne 3 ]; then
  fail "the restart did not resume at iteration 1 and halve 3 times ($halved)"
else
  echo "ok   the restart resumed at iteration 1 and halved $halved times (3 expected)"
fi
if ! cmp -s uninterrupted.csv restarted.csv; then
  fail "history.csv differs:"; diff uninterrupted.csv restarted.csv
else
  echo "ok   history.csv is that of the uninterrupted run ($(($(wc -l < restarted.csv) - 1)) rows)"
fi
exit $failures
