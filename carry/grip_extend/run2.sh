#!/bin/bash
cd "$(dirname "$0")"
export LD_LIBRARY_PATH=/work/runs/s48/bin OMP_NUM_THREADS=1 MUMPS_OOC_TMPDIR=$PWD/mumps_tmp
( while sleep 30; do used=$(free -m | awk '/Mem:/{print $3}'); echo "$(date +%T) $used" >> mem.log; if [ "$used" -gt 21500 ]; then pkill -f "/work/runs/s48/bin/softopt"; fi; done ) &
watch=$!
mpirun --allow-run-as-root -np 2 /work/runs/s48/bin/softopt optimize grip_extend.prm "$@"
rc=$?
kill $watch
exit $rc
